#include "editor_app.h"

#include <GL/gl.h>
#include <imgui.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <chrono>
#include <ctime>

#include "edit/session_file.h"
#include "gp/model_file.h"
#include "gp/sha256.h"
#include "io/bvh_writer.h"
#include "io/clip_loader.h"
#include "io/parse_error.h"
#include "model_panel.h"
#include "path_panel.h"
#include "shortcuts.h"
#include "skeleton/synthetic_clip.h"

namespace mgp::ui {

namespace {
const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

void applyStyle() {
    ImGui::StyleColorsDark();
    ImGuiStyle& st = ImGui::GetStyle();
    st.WindowRounding = 0.0f;
    st.FrameRounding = 3.0f;
    st.GrabRounding = 3.0f;
    st.WindowBorderSize = 1.0f;
    st.FramePadding = ImVec2(6, 3);
    st.ItemSpacing = ImVec2(7, 5);
    ImVec4* c = st.Colors;
    c[ImGuiCol_WindowBg] = ImVec4(0.16f, 0.165f, 0.18f, 1.0f);
    c[ImGuiCol_TitleBg] = ImVec4(0.12f, 0.125f, 0.14f, 1.0f);
    c[ImGuiCol_TitleBgActive] = ImVec4(0.14f, 0.15f, 0.17f, 1.0f);
    c[ImGuiCol_MenuBarBg] = ImVec4(0.12f, 0.125f, 0.14f, 1.0f);
    c[ImGuiCol_FrameBg] = ImVec4(0.24f, 0.25f, 0.28f, 1.0f);
    c[ImGuiCol_Button] = ImVec4(0.27f, 0.29f, 0.33f, 1.0f);
    c[ImGuiCol_ButtonHovered] = ImVec4(0.35f, 0.40f, 0.48f, 1.0f);
    c[ImGuiCol_ButtonActive] = ImVec4(0.28f, 0.50f, 0.80f, 1.0f);
    c[ImGuiCol_Header] = ImVec4(0.28f, 0.32f, 0.38f, 1.0f);
    c[ImGuiCol_PlotHistogram] = ImVec4(0.28f, 0.58f, 0.92f, 1.0f);
    c[ImGuiCol_Border] = ImVec4(0.08f, 0.08f, 0.09f, 1.0f);
}

std::string baseName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

std::string absolute(const std::string& path) {
    std::error_code ec;
    const auto p = std::filesystem::absolute(path, ec);
    return ec ? path : p.lexically_normal().string();
}

// Adds `extension` when the user typed a name without one.
std::string withExtension(const std::string& path, const std::string& extension) {
    return std::filesystem::path(path).has_extension() ? path : path + extension;
}

double secondsNow() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

const char* compareModeName(CompareMode m) {
    return m == CompareMode::kPlainIk ? "plain" : m == CompareMode::kSecondModel ? "model" : "none";
}
}  // namespace

EditorApp::EditorApp(EditorOptions options) : options_(std::move(options)) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // a fixed layout; nothing written beside the working directory
    io.LogFilename = nullptr;
    io.BackendPlatformName = "motiongp";
    for (int k = 0; k < ImGuiKey_COUNT; ++k) io.KeyMap[k] = -1;
    io.KeyMap[ImGuiKey_Tab] = key::kTab;
    io.KeyMap[ImGuiKey_LeftArrow] = key::kLeft;
    io.KeyMap[ImGuiKey_RightArrow] = key::kRight;
    io.KeyMap[ImGuiKey_UpArrow] = key::kUp;
    io.KeyMap[ImGuiKey_DownArrow] = key::kDown;
    io.KeyMap[ImGuiKey_PageUp] = key::kPageUp;
    io.KeyMap[ImGuiKey_PageDown] = key::kPageDown;
    io.KeyMap[ImGuiKey_Home] = key::kHome;
    io.KeyMap[ImGuiKey_End] = key::kEnd;
    io.KeyMap[ImGuiKey_Delete] = key::kDelete;
    io.KeyMap[ImGuiKey_Backspace] = key::kBackspace;
    io.KeyMap[ImGuiKey_Space] = key::kSpace;
    io.KeyMap[ImGuiKey_Enter] = key::kEnter;
    io.KeyMap[ImGuiKey_Escape] = key::kEscape;
    io.KeyMap[ImGuiKey_A] = 'A';
    io.KeyMap[ImGuiKey_C] = 'C';
    io.KeyMap[ImGuiKey_V] = 'V';
    io.KeyMap[ImGuiKey_X] = 'X';
    io.KeyMap[ImGuiKey_Y] = 'Y';
    io.KeyMap[ImGuiKey_Z] = 'Z';
    std::error_code ec;
    // Latin-1 plus what messages and panels print: Greek (α β γ η σ), dashes and ellipsis,
    // arrows, and maths (≥ ≤ √ ²); DejaVu Sans has them all.
    static const ImWchar kGlyphs[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x2027, 0x2070, 0x209F,
                                      0x2190, 0x21FF, 0x2200, 0x22FF, 0};
    scale_ = std::isfinite(options_.uiScale) ? std::clamp(options_.uiScale, 0.5f, 4.0f) : 1.0f;
    if (!options_.builtinFont && std::filesystem::exists(kFontPath, ec))
        io.Fonts->AddFontFromFileTTF(kFontPath, std::round(15.0f * scale_), nullptr, kGlyphs);
    else
        io.FontGlobalScale = scale_;  // the built-in bitmap font only comes in one size
    applyStyle();
    ImGui::GetStyle().ScaleAllSizes(scale_);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    viewport_ = std::make_unique<ViewportPanel>();
    autosave_ = AutosaveTimer(options_.autosaveSeconds);
    if (options_.recentFiles) {
        recent_ = std::make_unique<RecentFiles>();
        recent_->load();
    }
    if (options_.offerAutosaveRestore) restoreOffer_ = findOrphanedAutosaves();
    if (!options_.layoutFile.empty()) prefs_ = loadLayoutPrefs(options_.layoutFile);
}

EditorApp::~EditorApp() {
    // Quitting normally (whatever the user chose about unsaved changes) leaves no autosave to
    // offer; a crash or a kill leaves it for the next start.
    if (!autosaveFile_.empty()) discardAutosave(autosaveFile_);
    viewport_.reset();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
}

std::string EditorApp::reportingErrors(const std::function<void()>& work) {
    try {
        work();
        return "";
    } catch (const std::exception& e) {
        state_.setStatus(e.what(), true);
        return e.what();
    }
}

std::string EditorApp::openClip(const std::string& path) {
    return reportingErrors([&] {
        Clip clip = loadClip(path);
        state_.training.cancel();
        state_.doc.setClip(std::move(clip), false);
        state_.clipLabel = baseName(path);
        state_.modelLabel.clear();
        state_.cameraNeedsFraming = true;
        state_.playing = false;
        std::error_code ec;
        const std::string shown = std::filesystem::weakly_canonical(path, ec).string();
        state_.setStatus("opened " + (ec ? path : shown) +
                         (state_.doc.trainable() ? "" : "  (BVH: view-only, training needs ASF/AMC)"));
        sessionPath_.clear();
        markSaved();
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
    markSaved();
}

std::string EditorApp::openModel(const std::string& path) {
    return reportingErrors([&] {
        gp::ModelVersionPtr v = gp::ModelVersion::make(gp::loadModel(path));
        state_.doc.setModel(v, true);
        state_.clipLabel = v->model->sourceFile.empty() ? v->model->clip.name : v->model->sourceFile;
        state_.modelLabel = baseName(path);
        state_.cameraNeedsFraming = true;
        state_.setStatus("opened model " + path);
        sessionPath_.clear();
        markSaved();
        remember(path, RecentKind::kModel);
    });
}

std::string EditorApp::saveModel(const std::string& path) {
    const gp::ModelVersionPtr v = state_.doc.model();
    if (!v) {
        state_.setStatus("no model to save", true);
        return "no model to save";
    }
    return reportingErrors([&] {
        gp::saveModel(path, *v->model);
        state_.modelLabel = baseName(path);
        state_.setStatus("saved model " + path);
        remember(path, RecentKind::kModel);
    });
}

std::string EditorApp::startTraining() {
    if (!state_.doc.hasClip()) return "no clip";
    const std::string err =
        state_.training.start(state_.doc.clip(), state_.trainOptions, baseName(state_.doc.clip().sourcePath));
    if (err.empty()) {
        state_.setStatusWhile("training (the editor stays usable; Cancel in the Model panel)",
                              [job = &state_.training] { return job->running(); });
        trainingSeen_ = true;
    } else {
        state_.setStatus(err, true);
    }
    return err;
}

// Also called whenever a clip, model or session replaced the document: forget per-document UI.
void EditorApp::markSaved() {
    savedRevision_ = state_.doc.revision();
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

namespace {
SessionData sessionOf(const EditorState& s) {
    const EditorDocument& doc = s.doc;
    SessionData d;
    const Clip& c = doc.clip();
    d.syntheticClip = doc.synthetic();
    if (!d.syntheticClip) {
        d.clipPath = c.sourcePath.empty() ? "" : absolute(c.sourcePath);
        d.skeletonPath = c.skeletonPath.empty() ? "" : absolute(c.skeletonPath);
        std::error_code ec;
        if (!c.sourcePath.empty() && std::filesystem::is_regular_file(c.sourcePath, ec))
            d.clipSha256 = gp::sha256OfFile(c.sourcePath);  // warns on open if the clip changed since
    }
    if (const gp::ModelVersionPtr v = doc.model()) {
        d.model = *v->model;
        d.modelVersion = v->number;
    }
    if (const gp::ModelVersionPtr v = doc.compareModel()) d.compareModel = *v->model;
    d.edits = doc.edits();
    d.frame = doc.frame();
    for (int i = 0; i < kEffectorCount; ++i) d.pins[i] = doc.pinned(static_cast<Effector>(i));
    d.selectedEffector = s.selected ? static_cast<int>(*s.selected) : -1;
    d.compareMode = compareModeName(doc.compareMode());
    d.adaptiveEnabled = doc.adaptiveEnabled();
    d.camera.yawDeg = s.camera.yawDeg;
    d.camera.pitchDeg = s.camera.pitchDeg;
    d.camera.distanceCm = s.camera.distanceCm;
    d.camera.fovYDeg = s.camera.fovYDeg;
    d.camera.targetCm = {s.camera.targetCm.x, s.camera.targetCm.y, s.camera.targetCm.z};
    d.camera.followCharacter = s.followCharacter;
    if (const auto& p = doc.pathEdit()) {
        d.path.present = true;
        d.path.effector = p->effector;
        d.path.keyFrames = p->keyFrames;
        d.path.keyOffsetsCm = p->keyOffsetsCm;
        d.path.mode = p->mode;
    }
    d.ui = {{"show_captured_path", s.showCapturedPath}, {"show_before_ghost", s.showBeforeGhost},
            {"clip_label", s.clipLabel}, {"model_label", s.modelLabel}};
    return d;
}
}  // namespace

std::string EditorApp::saveSession(const std::string& pathIn) {
    const std::string path = withExtension(pathIn, ".mgsession");
    return reportingErrors([&] {
        mgp::saveSession(path, sessionOf(state_));
        sessionPath_ = absolute(path);
        markSaved();
        forgetAutosave();  // the saved file is newer: never offer the older autosave after a crash
        remember(path, RecentKind::kSession);
        state_.setStatus("saved session " + path);
    });
}

std::string EditorApp::autosaveNow() {
    if (!state_.doc.hasClip()) return "nothing to autosave";
    try {
        if (autosaveFile_.empty()) autosaveFile_ = autosavePath();
        mgp::saveSession(autosaveFile_, sessionOf(state_));
        autosave_.markSaved(secondsNow());
        autosavedRevision_ = state_.doc.revision();
        return "";
    } catch (const std::exception& e) {
        // Never interrupt the user for a failed autosave; say it in the status line.
        state_.setStatus(std::string("autosave failed: ") + e.what(), true);
        return e.what();
    }
}

void EditorApp::forgetAutosave() {
    if (!autosaveFile_.empty()) discardAutosave(autosaveFile_);
    autosave_.markSaved(secondsNow());
    autosavedRevision_ = state_.doc.revision();
}

void EditorApp::autosaveIfDue() {
    // Only what changed since the last autosave (and is not saved in the session) is worth writing.
    const bool changed = dirty() && state_.doc.revision() != autosavedRevision_;
    if (autosave_.due(secondsNow(), changed)) autosaveNow();
}

std::string EditorApp::openSession(const std::string& path, bool addToRecent) {
    bool replaced = false;  // whether the document was already changed when something failed
    try {
        SessionData d = mgp::loadSession(path);
        EditorDocument& doc = state_.doc;
        // Everything that can still fail is checked before the document changes.
        std::optional<Clip> clip = loadSessionClip(d, path);  // none: the model carries it (both validated)
        const Clip& target = clip ? *clip : d.model->clip;
        if (d.path.present) {
            std::string problem = validatePathKeys(d.path.keyFrames, target.frameCount());
            if (problem.empty() && !target.skeleton.hasEffector(d.path.effector))
                problem = std::string("expected an effector of the clip's skeleton, found ") + effectorName(d.path.effector);
            if (problem.empty() && d.path.keyOffsetsCm.size() != d.path.keyFrames.size())
                problem = "expected one offset per key";
            if (!problem.empty()) throw ParseError(path + ": path: " + problem);
        }
        gp::ModelVersionPtr model = d.model ? gp::ModelVersion::make(std::move(*d.model), d.modelVersion) : nullptr;
        gp::ModelVersionPtr compare = d.compareModel ? gp::ModelVersion::make(std::move(*d.compareModel)) : nullptr;
        auto text = [&](const char* key, const std::string& fallback) {
            const auto it = d.ui.find(key);
            return it != d.ui.end() && it->is_string() ? it->get<std::string>() : fallback;
        };
        auto flag = [&](const char* key, bool fallback) {
            const auto it = d.ui.find(key);
            return it != d.ui.end() && it->is_boolean() ? it->get<bool>() : fallback;
        };
        replaced = true;
        state_.training.cancel();
        state_.compareTraining.cancel();
        if (model) doc.setModel(model, true);
        else doc.setClip(std::move(*clip), d.syntheticClip);
        if (compare) doc.setCompareModel(compare);
        doc.setAdaptiveEnabled(d.adaptiveEnabled);
        doc.restoreEdits(std::move(d.edits));
        doc.setFrame(d.frame);
        for (int i = 0; i < kEffectorCount; ++i) doc.setPinned(static_cast<Effector>(i), d.pins[i]);
        doc.setCompareMode(d.compareMode == "plain" ? CompareMode::kPlainIk
                           : d.compareMode == "model" ? CompareMode::kSecondModel
                                                      : CompareMode::kNone);
        if (d.path.present) {
            PathEdit p{d.path.effector, d.path.keyFrames, d.path.keyOffsetsCm, d.path.mode};
            if (const std::string problem = doc.setPathEdit(std::move(p)); !problem.empty())
                throw ParseError(path + ": path edit: " + problem);
        }
        state_.selected.reset();
        if (d.selectedEffector >= 0 && d.selectedEffector < kEffectorCount)
            state_.selected = static_cast<Effector>(d.selectedEffector);
        state_.camera.yawDeg = float(d.camera.yawDeg);
        state_.camera.pitchDeg = float(d.camera.pitchDeg);
        state_.camera.distanceCm = float(d.camera.distanceCm);
        state_.camera.fovYDeg = float(d.camera.fovYDeg);
        state_.camera.targetCm = glm::vec3(d.camera.targetCm.x(), d.camera.targetCm.y(), d.camera.targetCm.z());
        state_.followCharacter = d.camera.followCharacter;
        state_.cameraNeedsFraming = false;
        state_.cameraRestored = true;
        state_.playing = false;
        state_.showCapturedPath = flag("show_captured_path", true);
        state_.showBeforeGhost = flag("show_before_ghost", false);
        state_.clipLabel = text("clip_label", doc.clip().name);
        state_.modelLabel = doc.hasModel() ? text("model_label", "from session") : "";
        sessionPath_ = absolute(path);
        markSaved();
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

std::string EditorApp::restoreAutosave(const std::string& path) {
    std::string file = path;
    if (file.empty()) {
        const std::vector<AutosaveCandidate> found = findOrphanedAutosaves();
        if (found.empty()) return "no autosave to restore";
        file = found.front().path;
    }
    const std::string err = openSession(file, false);
    if (!err.empty()) return err;
    // The restored work is unsaved: it has no session file of its own yet. It becomes this
    // editor's autosave before the old file goes, so a second crash loses nothing either.
    sessionPath_.clear();
    savedRevision_ = -1;
    if (!autosaveNow().empty()) return "could not keep the restored autosave: " + state_.messages.latestText();
    discardAutosave(file);
    restoreOffer_.clear();
    state_.setStatus("restored the autosave from " + file + " (File > Save session to keep it)");
    return "";
}

std::string EditorApp::exportBvh(const std::string& pathIn) {
    const std::string path = withExtension(pathIn, ".bvh");
    if (!state_.doc.hasClip()) return "no clip to export";
    return reportingErrors([&] {
        Clip edited = state_.doc.clip();
        for (const auto& [frame, record] : state_.doc.edits()) edited.frames[frame] = record.pose;
        writeBvh(edited, path);
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

void EditorApp::pollJobs() {
    std::string regenerateError;
    const std::string regenerated = state_.doc.pollRegenerate(&regenerateError);
    if (!regenerated.empty()) state_.setStatus(regenerated);
    else if (!regenerateError.empty()) state_.setStatus(regenerateError, true);
    if (gp::ModelVersionPtr v = state_.training.take()) {
        const Clip& c = v->model->clip;
        const bool same = state_.doc.hasClip() && c.name == state_.doc.clip().name &&
                          c.frameCount() == state_.doc.frameCount();
        state_.doc.setModel(v, !same);
        state_.modelLabel = std::string("trained ") + gp::kernelKindName(v->model->kind) + " (unsaved)";
        state_.setStatus(state_.training.message());
        trainingSeen_ = false;
    }
    if (trainingSeen_ && !state_.training.running()) {
        // Stopped without a model (cancelled or failed): say how it ended.
        trainingSeen_ = false;
        const std::string why = state_.training.message();
        state_.setStatus(why.empty() ? "training stopped" : "training stopped: " + why);
    }
    if (gp::ModelVersionPtr v = state_.compareTraining.take()) {
        state_.doc.setCompareModel(v);
        state_.setStatus("compare model: " + state_.compareTraining.message());
    }
    if (state_.requestTrain) {
        state_.requestTrain = false;
        startTraining();
    }
    if (state_.requestTrainCompare) {
        state_.requestTrainCompare = false;
        gp::TrainOptions o = state_.trainOptions;
        o.kind = o.kind == gp::KernelKind::kFas ? gp::KernelKind::kSgplvm : gp::KernelKind::kFas;
        const std::string err = state_.compareTraining.start(state_.doc.clip(), o);
        if (!err.empty()) state_.setStatus(err, true);
    }
}

void EditorApp::waitIdle() {
    state_.training.join();
    state_.compareTraining.join();
    pollJobs();
    state_.doc.waitIdle();
    pollJobs();  // a finished regeneration posts its keys to the adaptive worker
    state_.doc.waitIdle();
    latent_.prefetch(state_);  // the next frame uploads it
    latent_.waitIdle();
}

bool EditorApp::animating() const {
    const EditorDocument& d = state_.doc;
    return replay_.pending() || state_.playing || d.dragging() || d.latentDragging() || d.regenerating() || state_.training.running() ||
           state_.compareTraining.running() || d.adaptivePending() > 0 || latent_.busy() ||
           (d.hasModel() && !latent_.upToDate(state_));
}

std::string EditorApp::title() const {
    std::string t = std::string(dirty() ? "* " : "") + "MotionGP - ";
    if (!sessionPath_.empty()) t += baseName(sessionPath_) + " - ";
    if (!state_.doc.hasClip()) t += "no clip";
    else if (state_.doc.synthetic()) t += "synthetic demo clip (no mocap data found)";
    else t += state_.clipLabel + (state_.doc.clip().format == ClipFormat::kBvh ? " (BVH, view-only)" : "");
    if (!state_.modelLabel.empty()) t += " - model: " + state_.modelLabel;
    return t;
}

bool EditorApp::handleScreenPosition(Effector e, float& x, float& y) const {
    return viewport_->handleScreenPosition(state_, e, x, y);
}

bool EditorApp::keyScreenPosition(int key, float& x, float& y) const {
    return viewport_->keyScreenPosition(state_, key, x, y);
}

std::string EditorApp::runAction(const std::vector<std::string>& a) {
    if (a.empty()) return "empty action";
    const std::string& n = a[0];
    const std::string arg = a.size() > 1 ? a[1] : "";
    if (n == "open") return openClip(arg);
    if (n == "open-model") return openModel(arg);
    if (n == "save-model") return saveModel(arg);
    if (n == "train") {
        if (a.size() > 1) state_.trainOptions.kind = arg == "sgplvm" ? gp::KernelKind::kSgplvm : gp::KernelKind::kFas;
        if (a.size() > 2) state_.trainOptions.activeSize = std::atoi(a[2].c_str());
        if (a.size() > 3) state_.trainOptions.outerIterations = std::atoi(a[3].c_str());
        return startTraining();
    }
    if (n == "train-compare") {
        state_.requestTrainCompare = true;
        pollJobs();
        return "";
    }
    if (n == "cancel-train") {
        state_.training.cancel();
        return "";
    }
    if (n == "wait") {
        waitIdle();
        return "";
    }
    if (n == "play" || n == "pause") {
        state_.playing = n == "play";
        return "";
    }
    if (n == "frame") {
        state_.doc.setFrame(std::atoi(arg.c_str()) - 1);
        return "";
    }
    if (n == "pin") {
        Effector e;
        if (!parseEffector(arg, e)) return "unknown effector '" + arg + "'";
        state_.doc.togglePin(e);
        return "";
    }
    if (n == "compare") {
        state_.doc.setCompareMode(arg == "plain" ? CompareMode::kPlainIk
                                  : arg == "model" ? CompareMode::kSecondModel
                                                   : CompareMode::kNone);
        return "";
    }
    if (n == "frame-camera") {
        state_.requestFrameCamera = true;
        return "";
    }
    if (n == "undo") return state_.doc.undo();
    if (n == "copy-pose") {
        copyPose();
        return "";
    }
    if (n == "paste-pose") return pastePose();
    if (n == "redo") return state_.doc.redo();
    if (n == "path") {
        Effector e;
        if (!parseEffector(arg, e)) return "unknown effector '" + arg + "'";
        return state_.doc.beginPathEdit(e);
    }
    if (n == "path-keys") {
        std::vector<int> keys;
        for (std::size_t i = 1; i < a.size(); ++i) keys.push_back(std::atoi(a[i].c_str()) - 1);
        return state_.doc.setPathKeyFrames(std::move(keys));
    }
    if (n == "path-offset") {
        if (a.size() != 5) return "expected path-offset KEY DX DY DZ";
        return state_.doc.setPathKeyOffset(std::atoi(a[1].c_str()) - 1, Eigen::Vector3d(std::atof(a[2].c_str()),
                                                                                        std::atof(a[3].c_str()),
                                                                                        std::atof(a[4].c_str())));
    }
    if (n == "path-mode") {
        state_.doc.setPathMode(arg == "displacement" ? PathMode::kDisplacement : PathMode::kDirect);
        return "";
    }
    if (n == "regenerate") return state_.doc.startRegenerate(a.size() > 1 ? std::atoi(arg.c_str()) : 500);
    if (n == "save-session") return saveSession(arg);
    if (n == "open-session") return openSession(arg);
    if (n == "export-bvh") return exportBvh(arg);
    if (n == "export-png") return exportPng(arg);
    if (n == "autosave") return autosaveNow();
    if (n == "restore-autosave") return restoreAutosave(arg);
    if (n == "quit") {
        state_.requestQuit = true;
        return "";
    }
    if (n == "discard-and-quit") {
        quitConfirmed_ = true;
        return "";
    }
    return "unknown action '" + n + "'";
}

void EditorApp::shortcuts() {
    ImGuiIO& io = ImGui::GetIO();
    // A modal, a menu or a text field owns the keyboard: no shortcut reaches the document then.
    state_.keysBlocked = io.WantTextInput || dialog_.isOpen() || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);
    if (state_.keysBlocked) return;
    EditorDocument& doc = state_.doc;
    auto report = [this](const std::string& err) {
        if (!err.empty()) state_.setStatus(err, true);
    };
    if (chordPressed('Z', kCtrl, true)) report(doc.undo());
    if (chordPressed('Z', kCtrl | kShift, true) || chordPressed('Y', kCtrl, true)) report(doc.redo());
    if (chordPressed('O', kCtrl)) state_.requestOpenClip = true;
    if (chordPressed('M', kCtrl)) state_.requestOpenModel = true;
    if (chordPressed('S', kCtrl)) {
        if (sessionPath_.empty()) request_ = DialogPurpose::kSaveSession;
        else saveSession(sessionPath_);
    }
    if (chordPressed('S', kCtrl | kShift)) request_ = DialogPurpose::kSaveSession;
    if (chordPressed('E', kCtrl)) request_ = DialogPurpose::kExportBvh;
    if (chordPressed('E', kCtrl | kShift)) request_ = DialogPurpose::kExportPng;
    if (chordPressed('T', kCtrl) && doc.trainable() && !state_.training.running()) state_.requestTrain = true;
    if (chordPressed('R', kCtrl) && doc.pathEdit() && !doc.regenerating()) report(doc.startRegenerate());
    if (chordPressed('Q', kCtrl)) state_.requestQuit = true;
    if (chordPressed('C', kCtrl)) copyPose();
    if (chordPressed('V', kCtrl)) report(pastePose());
    if (chordPressed(key::kSpace)) state_.playing = !state_.playing;
    if (chordPressed(key::kRight, kNoMods, true)) doc.setFrame(doc.frame() + 1);
    if (chordPressed(key::kRight, kShift, true)) doc.setFrame(doc.frame() + 10);
    if (chordPressed(key::kLeft, kNoMods, true)) doc.setFrame(doc.frame() - 1);
    if (chordPressed(key::kLeft, kShift, true)) doc.setFrame(doc.frame() - 10);
    if (chordPressed(key::kHome)) doc.setFrame(0);
    if (chordPressed(key::kEnd)) doc.setFrame(doc.frameCount() - 1);
    if (chordPressed(key::kF1)) showHelp_ = !showHelp_;
}

void EditorApp::copyPose() {
    if (!state_.doc.hasClip()) return;
    poseClipboard_ = state_.doc.currentPose();
    state_.setStatus("copied the pose of frame " + std::to_string(state_.doc.frame() + 1));
}

std::string EditorApp::pastePose() {
    if (!poseClipboard_) return "nothing to paste: copy a pose first (Edit > Copy pose, Ctrl+C)";
    const std::string err = state_.doc.pastePose(*poseClipboard_);
    if (err.empty()) state_.setStatus("pasted the pose onto frame " + std::to_string(state_.doc.frame() + 1));
    return err;
}

void EditorApp::menus() {
    EditorDocument& doc = state_.doc;
    if (!ImGui::BeginMainMenuBar()) return;
    // Esc closes an open menu (and the menus above it).
    const bool escape = ImGui::IsKeyPressed(key::kEscape, false);
    auto beginMenu = [escape](const char* label, bool enabled = true) {
        if (!ImGui::BeginMenu(label, enabled)) return false;
        if (escape) ImGui::CloseCurrentPopup();
        return true;
    };
    if (beginMenu("File")) {
        if (ImGui::MenuItem("Open...", "Ctrl+O")) state_.requestOpenClip = true;
        if (beginMenu("Open recent", recent_ && !recent_->entries().empty())) {
            const std::vector<RecentFile> entries = recent_->entries();  // a copy: opening reorders the list
            for (const RecentFile& r : entries) {
                const std::string label = baseName(r.path) + "  (" + recentKindName(r.kind) + ")";
                if (ImGui::MenuItem(label.c_str()))
                    guardUnsaved([this, path = r.path] { openAny(path); }, "opening another file");
                if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.path.c_str());
            }
            ImGui::EndMenu();
        }
        if (ImGui::MenuItem("Save session", "Ctrl+S", false, doc.hasClip())) {
            if (sessionPath_.empty()) request_ = DialogPurpose::kSaveSession;
            else saveSession(sessionPath_);
        }
        if (ImGui::MenuItem("Save session as...", "Ctrl+Shift+S", false, doc.hasClip())) request_ = DialogPurpose::kSaveSession;
        ImGui::Separator();
        if (ImGui::MenuItem("Open model...", "Ctrl+M")) state_.requestOpenModel = true;
        if (ImGui::MenuItem("Save model...", nullptr, false, doc.hasModel())) state_.requestSaveModel = true;
        ImGui::Separator();
        if (ImGui::MenuItem("Export motion as BVH...", "Ctrl+E", false, doc.hasClip())) request_ = DialogPurpose::kExportBvh;
        if (ImGui::MenuItem("Export viewport as PNG...", "Ctrl+Shift+E", false, doc.hasClip()))
            request_ = DialogPurpose::kExportPng;
        ImGui::Separator();
        if (ImGui::MenuItem("Synthetic demo clip"))
            guardUnsaved([this] { openSyntheticClip(""); }, "opening the demo clip");
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q")) state_.requestQuit = true;
        ImGui::EndMenu();
    }
    if (beginMenu("Edit")) {
        const std::string undo = doc.canUndo() ? "Undo " + doc.undoLabel() : "Undo";
        const std::string redo = doc.canRedo() ? "Redo " + doc.redoLabel() : "Redo";
        auto report = [this](const std::string& err) {
            if (!err.empty()) state_.setStatus(err, true);
        };
        const bool idle = !doc.regenerating();
        if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, doc.canUndo() && idle)) report(doc.undo());
        if (ImGui::MenuItem(redo.c_str(), "Ctrl+Shift+Z", false, doc.canRedo() && idle)) report(doc.redo());
        ImGui::Separator();
        if (ImGui::MenuItem("Revert frame to capture", nullptr, false, doc.isEdited(doc.frame()))) doc.clearEdit(doc.frame());
        if (ImGui::MenuItem("Copy pose", "Ctrl+C", false, doc.hasClip())) copyPose();
        if (ImGui::MenuItem("Paste pose", "Ctrl+V", false, poseClipboard_.has_value() && !doc.regenerating()))
            report(pastePose());
        if (beginMenu("Pins")) {
            for (int i = 0; i < kEffectorCount; ++i) {
                const auto e = static_cast<Effector>(i);
                if (ImGui::MenuItem(effectorName(e), i == 0 ? "P on handle" : nullptr, doc.pinned(e), doc.hasEffector(e)))
                    doc.togglePin(e);
            }
            ImGui::EndMenu();
        }
        ImGui::Separator();
        const Effector pathEffector = state_.selected.value_or(Effector::kRFoot);
        const std::string begin = std::string("Edit path of ") + effectorName(pathEffector);
        if (ImGui::MenuItem(begin.c_str(), nullptr, false, doc.hasEffector(pathEffector))) report(doc.beginPathEdit(pathEffector));
        if (ImGui::MenuItem("Regenerate path span", "Ctrl+R", false, doc.pathEdit() && doc.hasModel() && !doc.regenerating()))
            report(doc.startRegenerate());
        if (ImGui::MenuItem("Cancel regeneration", nullptr, false, doc.regenerating())) doc.cancelRegenerate();
        if (ImGui::MenuItem("Stop editing the path", nullptr, false, doc.pathEdit().has_value())) doc.endPathEdit();
        ImGui::EndMenu();
    }
    if (beginMenu("Model")) {
        if (ImGui::MenuItem("Train", "Ctrl+T", false, doc.trainable() && !state_.training.running()))
            state_.requestTrain = true;
        if (ImGui::MenuItem("Cancel training", nullptr, false, state_.training.running())) state_.training.cancel();
        bool adaptive = doc.adaptiveEnabled();
        if (ImGui::MenuItem("Adaptive active set", nullptr, &adaptive)) doc.setAdaptiveEnabled(adaptive);
        ImGui::EndMenu();
    }
    if (beginMenu("View")) {
        if (ImGui::MenuItem("Frame character", "F")) state_.requestFrameCamera = true;
        ImGui::MenuItem("Messages", nullptr, &showMessages_);
        if (ImGui::MenuItem("Reset layout", nullptr, false, prefs_.rightWidth > 0.0f || prefs_.timelineHeight > 0.0f)) {
            prefs_ = LayoutPrefs{};
            if (!options_.layoutFile.empty()) saveLayoutPrefs(options_.layoutFile, prefs_);
        }
        ImGui::MenuItem("Follow character", nullptr, &state_.followCharacter);
        ImGui::MenuItem("Pose range tint", nullptr, &state_.showRangeTint, doc.hasModel());
        if (beginMenu("Compare ghost")) {
            if (ImGui::MenuItem("Off", nullptr, doc.compareMode() == CompareMode::kNone)) doc.setCompareMode(CompareMode::kNone);
            if (ImGui::MenuItem("Plain IK", nullptr, doc.compareMode() == CompareMode::kPlainIk))
                doc.setCompareMode(CompareMode::kPlainIk);
            if (ImGui::MenuItem("Second model", nullptr, doc.compareMode() == CompareMode::kSecondModel))
                doc.setCompareMode(CompareMode::kSecondModel);
            ImGui::EndMenu();
        }
        ImGui::EndMenu();
    }
    if (beginMenu("Playback")) {
        if (ImGui::MenuItem(state_.playing ? "Pause" : "Play", "Space")) state_.playing = !state_.playing;
        if (ImGui::MenuItem("Next frame", "Right")) doc.setFrame(doc.frame() + 1);
        if (ImGui::MenuItem("Previous frame", "Left")) doc.setFrame(doc.frame() - 1);
        if (ImGui::MenuItem("Forward 10 frames", "Shift+Right")) doc.setFrame(doc.frame() + 10);
        if (ImGui::MenuItem("First frame", "Home")) doc.setFrame(0);
        if (ImGui::MenuItem("Last frame", "End")) doc.setFrame(doc.frameCount() - 1);
        ImGui::EndMenu();
    }
    if (beginMenu("Help")) {
        if (ImGui::MenuItem("Controls", "F1")) showHelp_ = true;
        ImGui::EndMenu();
    }
    // Right side of the menu bar: background work.
    std::string bg;
    if (state_.training.running()) {
        const TrainingProgress p = state_.training.progress();
        bg = "training " + std::to_string(p.iteration) + "/" + std::to_string(p.total);
    } else if (doc.adaptivePending() > 0) {
        bg = "adaptive update...";
    } else if (latent_.busy()) {
        bg = "latent map...";
    }
    if (!bg.empty()) {
        ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(bg.c_str()).x - 16);
        ImGui::TextColored(ImVec4(0.45f, 0.8f, 1.0f, 1), "%s", bg.c_str());
    }
    ImGui::EndMainMenuBar();
}

void EditorApp::layout(int w, int h) {
    const float menuH = ImGui::GetFrameHeight();
    // Sizes in pixels at scale 1; a HiDPI monitor's content scale multiplies them (and the fonts).
    const float k = scale_;
    const float timelineH = 104.0f * k;
    // The right column: 380 px wide with fixed panel heights from 1280×800 up; in a smaller window
    // narrower (30 % of the width, at least 290 px) with the heights shared out so every panel
    // keeps its main controls in view down to 1024×600.
    const float avail = float(h) - menuH;
    float rightW = 380.0f * k, modelH = 262.0f * k, latentH = 356.0f * k;
    if (float(w) < 1280.0f * k || avail < modelH + latentH + 160.0f * k) {
        rightW = std::clamp(float(w) * 0.30f, std::min(290.0f * k, float(w) * 0.45f), 380.0f * k);
        modelH = std::clamp(avail * 0.30f, 130.0f * k, 262.0f * k);
        const float readoutH = std::max(avail * 0.29f, 170.0f * k);
        latentH = std::clamp(avail - modelH - readoutH, 120.0f * k, std::min(356.0f * k, rightW));
    }
    // The splitters' positions, as the user left them (scale-1 pixels), within sane bounds.
    if (prefs_.rightWidth > 0.0f) rightW = std::clamp(prefs_.rightWidth * k, std::min(240.0f * k, float(w) * 0.3f), float(w) * 0.6f);
    float timelineFinal = timelineH;
    if (prefs_.timelineHeight > 0.0f)
        timelineFinal = std::clamp(prefs_.timelineHeight * k, std::min(70.0f * k, float(h) * 0.2f), float(h) * 0.5f);
    layoutPanels(w, h, menuH, rightW, timelineFinal, modelH, latentH);
}

void EditorApp::layoutPanels(int w, int h, float menuH, float rightW, float timelineH, float modelH, float latentH) {
    const float leftW = float(w) - rightW;
    const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus;
    auto place = [](float x, float y, float ww, float hh) {
        ImGui::SetNextWindowPos(ImVec2(x, y));
        ImGui::SetNextWindowSize(ImVec2(std::max(ww, 50.0f), std::max(hh, 40.0f)));
    };

    place(0, menuH, leftW, float(h) - menuH - timelineH);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::Begin("Viewport", nullptr, fixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoBackground |
                                          ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar();
    viewport_->draw(state_);
    ImGui::End();

    place(0, float(h) - timelineH, leftW, timelineH);
    ImGui::Begin("Timeline", nullptr, fixed | ImGuiWindowFlags_NoScrollbar);
    {
        // Track above, status line below.
        const float statusH = ImGui::GetTextLineHeightWithSpacing();
        ImGui::BeginChild("tl", ImVec2(0, -statusH), false, ImGuiWindowFlags_NoScrollbar);
        timeline_.draw(state_);
        ImGui::EndChild();
        if (const StatusMessage* m = state_.messages.current()) {
            if (m->error) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1), "%s", m->text.c_str());
            else ImGui::TextDisabled("%s", m->text.c_str());
        }
    }
    ImGui::End();

    place(leftW, menuH, rightW, modelH);
    ImGui::Begin("Model", nullptr, fixed);
    drawModelPanel(state_);
    ImGui::End();

    place(leftW, menuH + modelH, rightW, latentH);
    ImGui::Begin("Latent map", nullptr, fixed | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    latent_.draw(state_);
    ImGui::End();

    place(leftW, menuH + modelH + latentH, rightW, float(h) - menuH - modelH - latentH);
    ImGui::Begin("Readout and path", nullptr, fixed | ImGuiWindowFlags_NoTitleBar);
    if (ImGui::BeginTabBar("##bottomright")) {
        // The Path tab comes forward while a path is edited.
        const bool pathActive = state_.doc.pathEdit().has_value();
        if (ImGui::BeginTabItem("IK readout")) {
            drawIkReadout(state_);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Path", nullptr, pathActive && !pathTabShown_ ? ImGuiTabItemFlags_SetSelected : 0)) {
            drawPathPanel(state_);
            ImGui::EndTabItem();
        }
        pathTabShown_ = pathActive;
        ImGui::EndTabBar();
    }
    ImGui::End();

    // Splitters, on top of the panels' edges: the right column's width and the timeline's height.
    bool released = false;
    const float dx = splitter("##split-right", leftW - 3.0f, menuH, 6.0f, float(h) - menuH, true, released);
    if (dx != 0.0f) prefs_.rightWidth = std::max(1.0f, (rightW - dx) / scale_);
    bool releasedTimeline = false;
    const float dy = splitter("##split-timeline", 0.0f, float(h) - timelineH - 3.0f, leftW - 3.0f, 6.0f, false, releasedTimeline);
    if (dy != 0.0f) prefs_.timelineHeight = std::max(1.0f, (timelineH - dy) / scale_);
    if ((released || releasedTimeline) && !options_.layoutFile.empty()) {
        const std::string err = saveLayoutPrefs(options_.layoutFile, prefs_);
        if (!err.empty()) state_.setStatus("could not remember the layout: " + err, true);
    }

    if (showHelp_) {
        ImGui::SetNextWindowPos(ImVec2(leftW * 0.5f, float(h) * 0.4f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
        ImGui::Begin("Controls", &showHelp_, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
        ImGui::Text("Viewport");
        ImGui::BulletText("Hover a hand/foot/head handle, left-drag: pose with learned IK (camera-facing plane)");
        ImGui::BulletText("Shift while dragging a handle or a path key: move on the horizontal plane");
        ImGui::BulletText("X, Y or Z while dragging a handle: along that world axis (again: free); the offset shows in cm");
        ImGui::BulletText("Right-click or P on a handle: pin / unpin (keeps a foot planted)");
        ImGui::BulletText("Left-drag empty space: orbit   Middle-drag or Shift+left: pan   Wheel: zoom   F: frame");
        ImGui::BulletText("Esc during a drag: cancel");
        ImGui::Text("Path editing (Edit menu or the Path tab)");
        ImGui::BulletText("Drag a key point in the viewport, or type its offset in the Path tab");
        ImGui::BulletText("Ctrl+R: regenerate the span between the first and last key");
        ImGui::BulletText("Drag the edges between the viewport, the right column and the timeline to resize them");
        ImGui::Text("Timeline");
        ImGui::BulletText("Space: play/pause   Left/Right: step (Shift: 10)   Home/End: first/last");
        ImGui::Text("Latent map");
        ImGui::BulletText("Hover: nearest training frame   Click a point: go to its frame");
        ImGui::BulletText("Drag the red point: pose from the model mean f(x)");
        ImGui::Text("Files and history");
        ImGui::BulletText("Ctrl+C / Ctrl+V: copy this frame's pose / paste it onto another frame (root kept)");
        ImGui::BulletText("Ctrl+Z: undo   Ctrl+Shift+Z or Ctrl+Y: redo (a drag or a regeneration is one step;");
        ImGui::Text("      undo also restores the model version the step changed)");
        ImGui::BulletText("Ctrl+O: open a session, clip or model   Ctrl+M: open model");
        ImGui::BulletText("Ctrl+S: save session   Ctrl+Shift+S: save session as");
        ImGui::BulletText("Ctrl+E: export BVH   Ctrl+Shift+E: export viewport PNG");
        ImGui::BulletText("Ctrl+T: train   Ctrl+Q: quit   F1: this window");
        ImGui::TextDisabled("Unsaved work is autosaved every %.0f s and offered back after a crash.", options_.autosaveSeconds);
        ImGui::End();
    }
}

float EditorApp::splitter(const char* id, float x, float y, float w, float h, bool vertical, bool& released) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    ImGui::Begin(id, nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    ImGui::PopStyleVar(3);
    ImGui::InvisibleButton("##strip", ImVec2(w, h));
    const bool active = ImGui::IsItemActive();
    released = ImGui::IsItemDeactivated();
    float delta = 0.0f;
    if (active || ImGui::IsItemHovered()) {
        ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
        ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h), IM_COL32(90, 140, 220, active ? 200 : 120));
        if (active) delta = vertical ? ImGui::GetIO().MouseDelta.x : ImGui::GetIO().MouseDelta.y;
    }
    ImGui::End();
    return delta;
}

// View > Messages: the status line's history, newest first.
void EditorApp::messagesWindow() {
    if (!showMessages_) return;
    ImGui::SetNextWindowSize(ImVec2(520, 260), ImGuiCond_Appearing);
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::Begin("Messages", &showMessages_, ImGuiWindowFlags_NoSavedSettings)) {
        const auto& h = state_.messages.history();
        if (h.empty()) ImGui::TextDisabled("(no messages yet)");
        for (auto it = h.rbegin(); it != h.rend(); ++it) {
            ImGui::TextDisabled("%6.0f s ago", state_.uiSeconds - it->postedAt);
            ImGui::SameLine();
            if (it->error) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1), "%s", it->text.c_str());
            else ImGui::TextUnformatted(it->text.c_str());
        }
    }
    ImGui::End();
}

void EditorApp::dialogs() {
    // Opening something else replaces the document: ask about unsaved changes first.
    if (std::exchange(state_.requestOpenClip, false))
        guardUnsaved([this] { openDialog(DialogPurpose::kClip); }, "opening another file");
    if (std::exchange(state_.requestOpenModel, false))
        guardUnsaved([this] { openDialog(DialogPurpose::kModel); }, "opening a model");
    if (std::exchange(state_.requestSaveModel, false)) openDialog(DialogPurpose::kSaveModel);
    if (const DialogPurpose p = std::exchange(request_, DialogPurpose::kNone); p != DialogPurpose::kNone) openDialog(p);
    if (auto path = dialog_.draw()) {
        switch (purpose_) {
            case DialogPurpose::kClip: openAny(*path); break;
            case DialogPurpose::kModel: openModel(*path); break;
            case DialogPurpose::kSaveModel: saveModel(*path); break;
            case DialogPurpose::kSaveSession:
                if (saveSession(*path).empty() && afterSave_) std::exchange(afterSave_, nullptr)();
                break;
            case DialogPurpose::kExportBvh: exportBvh(*path); break;
            case DialogPurpose::kExportPng: exportPng(*path); break;
            default: break;
        }
        purpose_ = DialogPurpose::kNone;
    }
    if (!dialog_.isOpen()) afterSave_ = nullptr;  // the save dialog was cancelled: so is the action
}

void EditorApp::openDialog(DialogPurpose purpose) {
    const std::string mocap = options_.mocapDir.empty() ? "" : options_.mocapDir + "/asf_amc";
    // Save dialogs start with a name made from the session or the clip, ready to confirm.
    const EditorDocument& doc = state_.doc;
    const std::string clipStem = doc.hasClip() && !doc.clip().sourcePath.empty()
                                     ? std::filesystem::path(doc.clip().sourcePath).stem().string()
                                     : doc.hasClip() && !doc.clip().name.empty() ? doc.clip().name : "motion";
    const std::string sessionName =
        sessionPath_.empty() ? clipStem + ".mgsession" : std::filesystem::path(sessionPath_).filename().string();
    const std::string frameTag = "_f" + std::to_string(doc.frame() + 1);
    switch (purpose) {
        case DialogPurpose::kClip:
            dialog_.open("Open session, clip (ASF/AMC, BVH) or model", FileDialog::Mode::kOpen,
                         {".mgsession", ".amc", ".bvh", ".json", ".model"}, mocap);
            break;
        case DialogPurpose::kModel: dialog_.open("Open model", FileDialog::Mode::kOpen, {".json", ".model"}, ""); break;
        case DialogPurpose::kSaveModel:
            dialog_.open("Save model", FileDialog::Mode::kSave, {".json", ".model"}, "", clipStem + ".model");
            break;
        case DialogPurpose::kSaveSession:
            dialog_.open("Save session", FileDialog::Mode::kSave, {".mgsession"}, "", sessionName);
            break;
        case DialogPurpose::kExportBvh:
            dialog_.open("Export motion as BVH", FileDialog::Mode::kSave, {".bvh"}, "", clipStem + "_edited.bvh");
            break;
        case DialogPurpose::kExportPng:
            dialog_.open("Export viewport as PNG", FileDialog::Mode::kSave, {".png"}, "", clipStem + frameTag + ".png");
            break;
        case DialogPurpose::kNone: return;
    }
    purpose_ = purpose;
}

bool EditorApp::popupOpen() const {
    return dialog_.isOpen() || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
}

void EditorApp::guardUnsaved(std::function<void()> action, std::string what) {
    if (!dirty()) {
        action();
        return;
    }
    pending_ = std::move(action);
    pendingWhat_ = std::move(what);
}

std::string EditorApp::openAny(const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".mgsession") return openSession(path);
    if (ext == ".json" || ext == ".model") return openModel(path);
    return openClip(path);
}

// Modal questions: unsaved changes before quitting or replacing the document, and restoring an
// autosave after a crash. One modal at a time: a question waits while another popup is open.
void EditorApp::prompts() {
    if (std::exchange(state_.requestQuit, false)) guardUnsaved([this] { quitConfirmed_ = true; }, "quitting");
    const bool otherPopup = dialog_.isOpen() || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);
    if (pending_ && !otherPopup) ImGui::OpenPopup("Unsaved changes");
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    askingUnsaved_ = ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    if (askingUnsaved_) {
        ImGui::Text("This session has changes that are not saved%s.",
                    sessionPath_.empty() ? "" : (" to " + baseName(sessionPath_)).c_str());
        ImGui::Text("Save them before %s?", pendingWhat_.c_str());
        if (ImGui::Button("Save", ImVec2(110, 0))) {
            std::function<void()> action = std::exchange(pending_, nullptr);
            if (sessionPath_.empty()) {
                request_ = DialogPurpose::kSaveSession;  // the action runs once the file is saved
                afterSave_ = std::move(action);
            } else if (saveSession(sessionPath_).empty()) {
                action();
            }
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Don't save", ImVec2(110, 0))) {
            std::exchange(pending_, nullptr)();
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(110, 0)) || ImGui::IsKeyPressed(key::kEscape, false)) {
            pending_ = nullptr;
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
    if (!restoreOffer_.empty() && !dialog_.isOpen() && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId))
        ImGui::OpenPopup("Restore autosave");
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Restore autosave", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (restoreOffer_.empty()) {  // answered elsewhere (a script, File menu)
            ImGui::CloseCurrentPopup();
            ImGui::EndPopup();
            return;
        }
        const AutosaveCandidate c = restoreOffer_.front();
        ImGui::Text("MotionGP did not quit normally last time.");
        ImGui::Text("An autosave of its work was left at\n%s", c.path.c_str());
        const std::time_t when = static_cast<std::time_t>(c.mtimeSeconds);
        char stamp[64];
        std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M:%S", std::localtime(&when));
        ImGui::TextDisabled("written %s by editor process %d", stamp, c.pid);
        if (ImGui::Button("Restore", ImVec2(110, 0))) {
            const std::string path = c.path;
            ImGui::CloseCurrentPopup();
            restoreAutosave(path);
            restoreOffer_.clear();
        }
        ImGui::SameLine();
        if (ImGui::Button("Discard", ImVec2(110, 0))) {
            discardAutosave(c.path);
            restoreOffer_.erase(restoreOffer_.begin());
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Not now", ImVec2(110, 0))) {
            restoreOffer_.clear();  // kept on disk: offered again next start
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
}

void EditorApp::frame(InputState& in, double dt, int width, int height) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(width), float(height));
    io.DisplayFramebufferScale = ImVec2(1, 1);
    io.DeltaTime = dt > 0.0 ? float(dt) : 1.0f / 60.0f;
    io.MousePos = in.mouseX >= 0 && in.mouseY >= 0 ? ImVec2(in.mouseX, in.mouseY) : ImVec2(-FLT_MAX, -FLT_MAX);
    replay_.next(in);
    for (int b = 0; b < 3; ++b) io.MouseDown[b] = replay_.buttons()[b];
    io.MouseWheel = in.wheel;
    in.wheel = 0.0f;
    for (int k = 0; k < key::kCount && k < int(IM_ARRAYSIZE(io.KeysDown)); ++k) io.KeysDown[k] = replay_.keys()[k];
    io.KeyShift = replay_.shift();
    io.KeyCtrl = replay_.ctrl();
    io.KeyAlt = replay_.alt();
    for (char32_t c : in.chars) io.AddInputCharacter(static_cast<unsigned>(c));
    in.chars.clear();

    state_.uiSeconds += io.DeltaTime;
    pollJobs();
    autosaveIfDue();
    TimelinePanel::advance(state_, io.DeltaTime);

    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    shortcuts();
    menus();
    state_.messages.update(state_.uiSeconds, state_.doc.revision());
    layout(width, height);
    dialogs();
    prompts();
    messagesWindow();
    ImGui::Render();

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

render::Image EditorApp::capture(int width, int height) const {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return render::readFramebuffer(width, height);
}

// ---- script player ---------------------------------------------------------------------------

ScriptPlayer::ScriptPlayer(GuiScript script) : script_(std::move(script)) {}

void ScriptPlayer::apply(int frame, InputState& in, EditorApp& app, std::vector<std::string>& screenshots) {
    const auto& ev = script_.events();
    auto button = [](const std::string& b) { return b == "left" ? 0 : b == "right" ? 1 : 2; };
    while (next_ < ev.size() && ev[next_].frame <= frame) {
        const ScriptEvent& e = ev[next_++];
        const auto& a = e.args;
        if (e.verb == "move") {
            in.mouseX = float(std::atof(a[0].c_str()));
            in.mouseY = float(std::atof(a[1].c_str()));
        } else if (e.verb == "moveby") {
            in.mouseX += float(std::atof(a[0].c_str()));
            in.mouseY += float(std::atof(a[1].c_str()));
        } else if (e.verb == "hover") {
            Effector eff;
            float x, y;
            const bool onScreen = a[0].rfind("key:", 0) == 0
                                      ? app.keyScreenPosition(std::atoi(a[0].c_str() + 4) - 1, x, y)
                                      : parseEffector(a[0], eff) && app.handleScreenPosition(eff, x, y);
            if (onScreen) {
                in.mouseX = x;
                in.mouseY = y;
            } else {
                errors_.push_back("line " + std::to_string(e.line) + ": handle '" + a[0] + "' is not on screen");
            }
        } else if (e.verb == "down" || e.verb == "up") {
            in.setButton(button(a[0]), e.verb == "down");
        } else if (e.verb == "wheel") {
            in.wheel += float(std::atof(a[0].c_str()));
        } else if (e.verb == "key" || e.verb == "keydown" || e.verb == "keyup") {
            const int k = keyFromName(a[0]);
            if (k < 0) continue;
            in.setKey(k, e.verb != "keyup");
            if (e.verb == "key") in.setKey(k, false);  // a tap: the replay spreads it over two frames
        } else if (e.verb == "action") {
            if (a[0] == "screenshot") {
                screenshots.push_back(a.size() > 1 ? a[1] : "screenshot.png");
            } else {
                const std::string err = app.runAction(a);
                if (!err.empty()) errors_.push_back("line " + std::to_string(e.line) + ": " + err);
            }
        }
    }
}

}  // namespace mgp::ui
