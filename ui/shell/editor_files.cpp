// EditorApp's file operations: open a clip, model or session, save a model or session, export
// BVH and PNG, and the recent-files list they feed. Every one reports errors on the status line
// and returns them; a model trained on another clip than the open one asks before replacing it.
#include "ui/shell/editor_app.h"

#include <filesystem>

#include "gp/model_file.h"
#include "io/clip_export.h"
#include "io/clip_loader.h"
#include "io/data_paths.h"
#include "io/fbx_export.h"
#include "io/text_reader.h"
#include "session/session_mapping.h"
#include "skeleton/clip_match.h"
#include "skeleton/synthetic_clip.h"
#include "ui/shell/editor_session.h"

namespace mgp::ui {

namespace {

// Adds `extension` when the user typed a name without one.
std::string withExtension(const std::string& path, const std::string& extension) {
    return std::filesystem::path(path).has_extension() ? path : path + extension;
}
}  // namespace

std::string EditorApp::openClip(const std::string& path) {
    return reportingErrors([&] {
        Clip clip = loadClip(path);
        state_.training.cancel();
        state_.doc.setClip(std::move(clip), false);  // the model goes with the old clip
        state_.clipLabel = fileNameOf(path);
        state_.modelLabel.clear();
        state_.cameraNeedsFraming = true;
        state_.playing = false;
        std::error_code ec;
        const std::string shown = std::filesystem::weakly_canonical(path, ec).string();
        state_.setStatus("opened " + (ec ? path : shown));
        sessionPath_.clear();
        markSaved(true);
        remember(path, RecentKind::kClip);
    });
}

void EditorApp::openSyntheticClip(const std::string& why) {
    state_.doc.setClip(makeSyntheticWalk(), true);
    state_.clipLabel = "synthetic demo clip";
    state_.modelLabel.clear();
    state_.cameraNeedsFraming = true;
    state_.setStatus(why.empty() ? "synthetic demo clip" : why);
    sessionPath_.clear();
    markSaved(true);
}

std::string EditorApp::openModel(const std::string& path, bool askedAboutUnsaved) {
    gp::ModelVersionPtr v;
    const std::string err = reportingErrors([&] { v = gp::ModelVersion::make(gp::loadModel(path)); });
    if (!err.empty()) return err;
    // A model brings the clips it was trained on. When the open clip is one of them, that clip
    // becomes the model's primary clip (gp::withPrimaryClip; editing, the latent map's frames and
    // adaptive updates follow it). When it is none of them, ask before replacing it with the
    // model's first clip (the open clip and its edits would go).
    std::string difference;
    const int openIndex = state_.doc.hasClip() ? gp::findCapture(*v->model, state_.doc.clip(), &difference) : 0;
    if (openIndex > 0) {
        try {
            v = gp::ModelVersion::make(gp::withPrimaryClip(*v->model, openIndex));
        } catch (const std::exception& e) {
            return e.what();
        }
    }
    if (openIndex < 0) {
        const std::string modelClip = v->model->sourceFile.empty() ? v->model->clip.name : v->model->sourceFile;
        const std::string trainedOn =
            v->model->clipCount() > 1 ? std::to_string(v->model->clipCount()) + " clips (" + v->model->clipNames() + ")"
                                      : modelClip + " (" + std::to_string(v->model->clip.frameCount()) + " frames)";
        prompts_.askModelClip({fileNameOf(path) + " was trained on " + trainedOn + ".",
                               "The open clip is " + state_.clipLabel + " (" + std::to_string(state_.doc.frameCount()) +
                                   " frames): " + difference + ".",
                               "Opening the model replaces the open clip with " + modelClip + "."},
                              [this, v, path, askedAboutUnsaved] {
                                  prompts_.guard(
                                      !askedAboutUnsaved && dirty(), [this, v, path] { installModel(v, path); },
                                      "opening the model's clip");
                              });
        state_.setStatus("the model was trained on " + modelClip + ", not on the open clip: asking first");
        return "";
    }
    // Installing a model restarts the document on its clip: the edits and the old model go.
    prompts_.guard(
        !askedAboutUnsaved && dirty(), [this, v, path] { installModel(v, path); }, "opening a model");
    return "";
}

void EditorApp::installModel(gp::ModelVersionPtr v, const std::string& path) {
    state_.doc.setModel(v, true);
    state_.clipLabel = v->model->sourceFile.empty() ? v->model->clip.name : v->model->sourceFile;
    state_.modelLabel = fileNameOf(path);
    state_.cameraNeedsFraming = true;
    state_.setStatus("opened model " + path);
    sessionPath_.clear();
    markSaved(true);
    remember(path, RecentKind::kModel);
}

std::string EditorApp::openModelClip(const std::string& name, int frame) {
    const gp::ModelVersionPtr v = state_.doc.model();
    if (!v) return "no model: open or train one first";
    const int index = v->model->findClip(name);
    if (index < 0) return "the model has no clip '" + name + "'; its clips: " + v->model->clipNames();
    const int frames = v->model->clipAt(index).frameCount();
    if (frame < 0 || frame >= frames)
        return "expected a frame in 1.." + std::to_string(frames) + " of " + name + ", found " +
               std::to_string(frame + 1);
    const std::string where = name + " frame " + std::to_string(frame + 1);
    if (index == 0) {
        state_.doc.setFrame(frame);
        state_.setStatus("jumped to " + where);
        return "";
    }
    // The open clip and its edits go (the model stays): ask about unsaved changes first. The clip
    // is looked up again when the answer comes, by name, in the model of that moment.
    guardUnsaved(
        [this, name, frame, where] {
            const gp::ModelVersionPtr now = state_.doc.model();
            const int i = now ? now->model->findClip(name) : -1;
            if (i < 0) {
                state_.setStatus("the model no longer has clip " + name, true);
                return;
            }
            const gp::ModelVersionPtr relabelled =
                i == 0 ? now : gp::ModelVersion::make(gp::withPrimaryClip(*now->model, i));
            const std::string before = state_.clipLabel;
            const bool modelSaved = !modelUnsaved();  // relabelled, it is the same model: saved or not
            state_.training.cancel();                 // a training of the old clip must not land on this one
            state_.compareTraining.cancel();
            state_.doc.setModel(relabelled, true);
            state_.doc.setFrame(frame);
            state_.clipLabel = relabelled->model->sourceFile.empty() ? name : relabelled->model->sourceFile;
            state_.playing = false;
            state_.cameraNeedsFraming = true;
            sessionPath_.clear();  // the session file holds the other clip
            markSaved(modelSaved);
            state_.setStatus("switched from " + before + " to " + where + " (same model)");
        },
        "switching to clip " + name);
    if (dirty()) state_.setStatus("switching to " + where + ": asking about unsaved changes first");
    return "";
}

std::string EditorApp::saveModel(const std::string& path) {
    const gp::ModelVersionPtr v = state_.doc.model();
    if (!v) {
        state_.setStatus("no model to save", true);
        return "no model to save";
    }
    return reportingErrors([&] {
        gp::saveModel(path, *v->model);
        savedModel_ = v->model;
        state_.modelLabel = fileNameOf(path);
        state_.setStatus("saved model " + path);
        remember(path, RecentKind::kModel);
    });
}

bool EditorApp::modelUnsaved() const {
    const gp::ModelVersionPtr v = state_.doc.model();
    return v && v->model != savedModel_.lock();
}

bool EditorApp::compareModelUnsaved() const {
    const gp::ModelVersionPtr v = state_.doc.compareModel();
    return v && v->model != savedCompareModel_.lock();
}

void EditorApp::noteSavedCompareModel() {
    if (const gp::ModelVersionPtr v = state_.doc.compareModel())
        savedCompareModel_ = v->model;
    else
        savedCompareModel_.reset();
}

void EditorApp::markSaved(bool modelSaved) {
    savedRevision_ = state_.doc.revision();
    if (modelSaved) {
        if (const gp::ModelVersionPtr v = state_.doc.model())
            savedModel_ = v->model;
        else
            savedModel_.reset();
    }
    state_.selectedKey = state_.hoveredKey = -1;
}

void EditorApp::remember(const std::string& path, RecentKind kind) {
    if (!recent_) return;
    recent_->add(path, kind);
    try {
        recent_->save();
    } catch (const std::exception&) {
        // The list is a convenience: a read-only config folder must not turn an open into an error.
    }
}

std::string EditorApp::saveSession(const std::string& pathIn) {
    const std::string path = withExtension(pathIn, ".mgsession");
    return reportingErrors([&] {
        const gp::ModelVersionPtr written = state_.doc.model();  // an update may land while writing
        mgp::saveSession(path, editorSession(state_));
        sessionPath_ = absolutePath(path);
        markSaved(false);
        noteSavedCompareModel();
        if (written)
            savedModel_ = written->model;
        else
            savedModel_.reset();
        forgetAutosave();  // the saved file is newer: never offer the older autosave after a crash
        remember(path, RecentKind::kSession);
        state_.setStatus("saved session " + path);
    });
}

void EditorApp::saveSessionOrAsk() {
    if (sessionPath_.empty())
        openDialog(FileKind::kSaveSession);
    else
        saveSession(sessionPath_);
}

std::string EditorApp::openSession(const std::string& path, bool addToRecent) {
    bool replaced = false;  // whether the document was already changed when something failed
    try {
        // Everything that can still fail is checked before the document changes.
        CheckedSession checked = checkSession(mgp::loadSession(path), path);
        replaced = true;
        state_.training.cancel();
        state_.compareTraining.cancel();
        applySession(state_.doc, checked, path);  // leaves the editor's half in checked.data
        applyEditorSession(state_, checked.data);
        const SessionData& d = checked.data;
        sessionPath_ = absolutePath(path);
        markSaved(true);
        noteSavedCompareModel();
        forgetAutosave();
        if (addToRecent) remember(path, RecentKind::kSession);
        std::string status = "opened session " + path;
        for (const std::string& w : d.warnings) status += "  (" + w + ")";
        state_.setStatus(status, !d.warnings.empty());
        return "";
    } catch (const std::exception& e) {
        if (replaced) {
            // Half-loaded: never let Ctrl+S write it over the previous session's file.
            sessionPath_.clear();
            savedRevision_ = -1;
        }
        state_.setStatus(e.what(), true);
        return e.what();
    }
}

std::string EditorApp::exportMotion(const std::string& pathIn, const std::string& defaultExtension) {
    const std::string path = withExtension(pathIn, defaultExtension);
    if (!state_.doc.hasClip()) return "no clip to export";
    return reportingErrors([&] {
        Clip edited = state_.doc.clip();
        for (const auto& [frame, record] : state_.doc.edits()) edited.frames[frame] = record.pose;
        if (fileExtension(path) == "fbx") {
            // Through Blender, seconds: on the export worker; pollExport reports its stages and end.
            if (const std::string problem = fbxExportUnavailable(path); !problem.empty())
                throw std::runtime_error(problem);
            if (const std::string busy = state_.exporting.start(std::move(edited), path); !busy.empty())
                throw std::runtime_error(busy);
            exportSeen_ = true;
            state_.setStatus("exporting " + fileNameOf(path) + " through Blender...");
            return;
        }
        exportClip(edited, path);
        state_.setStatus("exported " + std::to_string(edited.frameCount()) + " frames (" +
                         std::to_string(state_.doc.edits().size()) + " edited) to " + path);
    });
}

std::string EditorApp::exportPng(const std::string& pathIn) {
    const std::string path = withExtension(pathIn, ".png");
    if (!state_.doc.hasClip()) return "no clip to draw";
    return reportingErrors([&] {
        render::writePng(viewport_->renderImage(state_), path);
        state_.setStatus("exported the viewport to " + path);
    });
}

void EditorApp::openRecent(const std::string& path) {
    guardUnsaved([this, path] { openAny(path); }, "opening another file");
}

std::string EditorApp::openAny(const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".mgsession") return openSession(path);
    if (ext == ".json" || ext == ".model") return openModel(path, true);  // every caller asked already
    return openClip(path);
}

}  // namespace mgp::ui
