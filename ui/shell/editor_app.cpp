#include "ui/shell/editor_app.h"

#include <GL/gl.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "edit/mirror_edit.h"
#include "render/gl_context.h"
#include "skeleton/clip_match.h"
#include "ui/actions/action_args.h"
#include "ui/actions/editor_actions.h"
#include "ui/actions/shortcuts.h"
#include "ui/shell/editor_session.h"
#include "ui/shell/frame_signature.h"
#include "ui/shell/imgui_setup.h"
#include "ui/windows/help_window.h"
#include "ui/windows/menu_bar.h"
#include "ui/windows/messages_window.h"

namespace mgp::ui {

namespace {

double secondsNow() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

float clampedScale(float s) { return std::isfinite(s) ? std::clamp(s, 0.5f, 4.0f) : 1.0f; }
}  // namespace

EditorApp::EditorApp(EditorOptions options)
    : options_(std::move(options)),
      scale_(clampedScale(options_.uiScale)),
      layout_(scale_, options_.layoutFile),
      autosave_(options_.autosaveSeconds) {
    createImGuiContext(scale_, options_.builtinFont);
    const std::string libraryProblem = imguiOpenGlLibraryProblem();
    if (!libraryProblem.empty() || !ImGui_ImplOpenGL3_Init("#version 330 core")) {
        // No destructor runs for a constructor that throws: the context goes here.
        ImGui::DestroyContext();
        throw render::RenderError(!libraryProblem.empty()
                                      ? libraryProblem
                                      : "expected an OpenGL 3.3 context for the editor's Dear ImGui "
                                        "renderer, found an older one (or none current)");
    }
    viewport_ = std::make_unique<ViewportPanel>();
    if (options_.recentFiles) {
        recent_ = std::make_unique<RecentFiles>();
        recent_->load();
    }
    if (options_.offerAutosaveRestore) prompts_.offerAutosaves(findOrphanedAutosaves());
}

EditorApp::~EditorApp() {
    // Quitting normally (whatever the user chose about unsaved changes) leaves no autosave to
    // offer; a crash or a kill leaves it for the next start.
    autosave_.discard();
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

std::string EditorApp::startTraining() {
    if (!state_.doc.hasClip()) return "no clip";
    // The new model replaces this one when it is ready: a model no file holds is asked about first
    // (Save keeps it in the session file), as when a file replaces it.
    return runAfterAsking(
        modelUnsaved(),
        [this] {
            return reportTrainingStart(state_.training.start(state_.doc.clip(), state_.trainOptions,
                                                             fileNameOf(state_.doc.clip().sourcePath)));
        },
        "training a new model");
}

std::string EditorApp::startTraining(std::vector<gp::TrainingClip> clips, const gp::FrameSelection& selection) {
    if (!state_.doc.hasClip()) return "no clip";
    return runAfterAsking(
        modelUnsaved(),
        [this, clips = std::move(clips), selection]() mutable {
            return reportTrainingStart(state_.training.start(std::move(clips), selection, state_.trainOptions));
        },
        "training a new model");
}

std::string EditorApp::reportTrainingStart(const std::string& err) {
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
std::string EditorApp::autosaveNow() {
    if (!state_.doc.hasClip()) return "nothing to autosave";
    try {
        autosave_.write(editorSession(state_), secondsNow(), state_.doc.revision());
        return "";
    } catch (const std::exception& e) {
        // Never interrupt the user for a failed autosave; say it in the status line.
        state_.setStatus(std::string("autosave failed: ") + e.what(), true);
        return e.what();
    }
}

void EditorApp::forgetAutosave() { autosave_.forget(secondsNow(), state_.doc.revision()); }

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
    savedModel_.reset();  // only the autosave holds its model
    savedCompareModel_.reset();
    if (!autosaveNow().empty()) return "could not keep the restored autosave: " + state_.messages.latestText();
    discardAutosave(file);
    prompts_.dropAutosaveOffer();
    state_.setStatus("restored the autosave from " + file + " (File > Save session to keep it)");
    return "";
}

void EditorApp::pollJobs() {
    std::string regenerateError;
    const std::string regenerated = state_.doc.pollRegenerate(&regenerateError);
    if (!regenerateError.empty())
        state_.setStatus(regenerateError, true);
    else if (!regenerated.empty())
        state_.setStatus(regenerated);
    std::string fillError;
    const std::string filled = state_.doc.pollFill(&fillError);
    if (!fillError.empty())
        state_.setStatus(fillError, true);
    else if (!filled.empty())
        state_.setStatus(filled);
    pollTraining();
    pollExport();
    if (gp::ModelVersionPtr v = state_.compareTraining.take()) {
        state_.doc.setCompareModel(v);
        state_.setStatus("compare model: " + state_.compareTraining.message());
    }
}

void EditorApp::pollTraining() {
    EditorDocument& doc = state_.doc;
    // Models change between gestures only: a drag, a latent drag or a regeneration keeps the
    // version it started on, and the training's results wait (the worker keeps them until taken).
    if (doc.dragging() || doc.latentDragging() || doc.regenerating()) return;
    const auto sameClip = [&](const gp::ModelVersionPtr& v) {
        return doc.hasClip() && sameCapture(doc.clip(), v->model->clip);
    };
    if (gp::ModelVersionPtr v = state_.training.takeRefinement()) {
        const bool first = !doc.refining();
        doc.installRefinement(v, !sameClip(v));
        state_.modelLabel = std::string("refining ") + gp::kernelKindName(v->model->kind) + " (unsaved)";
        // Said once; the later replacements show in the Model panel, not over the user's own messages.
        if (first)
            state_.setStatus("a model from training iteration " + std::to_string(v->model->iterations) +
                             " is ready to drag against; training goes on and replaces it between gestures");
    }
    if (gp::ModelVersionPtr v = state_.training.take()) {
        const int taught = doc.refining() ? doc.finishRefinement(v, !sameClip(v)) : (doc.setModel(v, !sameClip(v)), 0);
        state_.modelLabel = std::string("trained ") + gp::kernelKindName(v->model->kind) + " (unsaved)";
        std::string status = state_.training.message();
        if (taught > 0) status += "; " + std::to_string(taught) + " pose(s) accepted meanwhile are being taught to it";
        state_.setStatus(status);
        trainingSeen_ = false;
    }
    if (trainingSeen_ && !state_.training.running()) {
        // Stopped without a final model (cancelled or failed): say how it ended. A model it
        // published meanwhile stays, and the poses that waited for the final one are taught to it.
        trainingSeen_ = false;
        const std::string why = state_.training.message();
        std::string status = why.empty() ? "training stopped" : "training stopped: " + why;
        if (doc.refining()) {
            const gp::ModelVersionPtr kept = doc.model();
            doc.finishRefinement(kept, false);
            status += "; keeping the model from iteration " + std::to_string(kept->model->iterations);
        }
        state_.setStatus(status);
    }
}

std::string EditorApp::startCompareTraining() {
    // Its model replaces the compare model when ready: one no session file holds is asked about first.
    return runAfterAsking(
        compareModelUnsaved(),
        [this] {
            gp::TrainOptions o = state_.trainOptions;
            o.kind = o.kind == gp::KernelKind::kFas ? gp::KernelKind::kSgplvm : gp::KernelKind::kFas;
            const std::string err = state_.compareTraining.start(state_.doc.clip(), o);
            if (!err.empty()) state_.setStatus(err, true);
            return err;
        },
        "training a new compare model");
}

void EditorApp::pollExport() {
    if (!exportSeen_) return;
    if (std::optional<ExportOutcome> done = state_.exporting.take()) {
        exportSeen_ = false;
        state_.setStatus("exported " + std::to_string(done->frames) + " frames to " + done->path);
    } else if (state_.exporting.running()) {
        const std::string stage = state_.exporting.stage();
        if (!stage.empty() && stage != exportStage_) state_.setStatus("exporting: " + stage);
        exportStage_ = stage;
    } else {
        exportSeen_ = false;  // stopped without a file: say why
        state_.setStatus(state_.exporting.message(), true);
    }
}

void EditorApp::waitIdle() {
    state_.exporting.join();
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
    return replay_.pending() || state_.playing || d.dragging() || d.latentDragging() || d.regenerating() ||
           state_.training.running() || state_.compareTraining.running() || d.models().pending() > 0 ||
           latent_.busy() || (d.hasModel() && !latent_.upToDate(state_));
}

std::string EditorApp::title() const {
    std::string t = std::string(dirty() ? "* " : "") + "MotionGP - ";
    if (!sessionPath_.empty()) t += fileNameOf(sessionPath_) + " - ";
    if (!state_.doc.hasClip())
        t += "no clip";
    else if (state_.doc.synthetic())
        t += "synthetic demo clip (no mocap data found)";
    else
        t += state_.clipLabel + (state_.doc.clip().format == ClipFormat::kBvh ? " (BVH)" : "");
    if (!state_.modelLabel.empty()) t += " - model: " + state_.modelLabel;
    return t;
}

bool EditorApp::handleScreenPosition(Effector e, float& x, float& y) const {
    return viewport_->handleScreenPosition(state_, e, x, y);
}

bool EditorApp::latentDotScreenPosition(const std::string& clip, int frame, float& x, float& y) const {
    const gp::ModelVersionPtr v = state_.doc.model();
    if (!v) return false;
    const gp::GpModel& m = *v->model;
    const int c = m.findClip(clip);
    for (int i = 0; c >= 0 && i < m.N() && i < int(m.trainingFrames.size()); ++i)
        if (m.rowClip(i) == c && m.trainingFrames[static_cast<std::size_t>(i)] == frame)
            return latent_.dotPosition(state_, i, x, y);
    return false;
}

bool EditorApp::keyScreenPosition(int key, float& x, float& y) const {
    return viewport_->keyScreenPosition(state_, key, x, y);
}

std::string EditorApp::runAction(const std::vector<std::string>& args) {
    return ActionTable::editor().run(*this, args);
}

void EditorApp::shortcuts() {
    ImGuiIO& io = ImGui::GetIO();
    // A modal, a menu or a text field owns the keyboard: no shortcut reaches the document then.
    state_.keysBlocked = io.WantTextInput || dialog_.isOpen() || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);
    if (!state_.keysBlocked) ActionTable::editor().runShortcuts(*this);
}

void EditorApp::runRequests() {
    const std::vector<std::vector<std::string>> requests = std::exchange(state_.requests, {});
    for (const std::vector<std::string>& args : requests) {
        const long before = state_.messages.postCount();
        const std::string err = runAction(args);
        if (!err.empty() && state_.messages.postCount() == before) state_.setStatus(err, true);
    }
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

std::string EditorApp::mirrorPose() {
    const std::string err = mirrorCurrentPose(state_.doc);
    if (err.empty())
        state_.setStatus("mirrored the pose of frame " + std::to_string(state_.doc.frame() + 1) + " left/right");
    return err;
}

std::string EditorApp::rotateJoint(const std::vector<std::string>& a) {
    if (a.empty()) {
        jointWindow_.show();
        return "";
    }
    return jointWindow_.rotate(state_, a);
}

std::string EditorApp::trainOnClips(const std::vector<std::string>& a) {
    if (!state_.doc.hasClip()) return "no clip open";
    trainClips_.show(*this);
    if (a.empty()) return "";
    // CLIPS: the clips to train with the open clip (which is always included), by name or path.
    std::string list = a[0];
    for (std::size_t at = 0; at <= list.size();) {
        const std::size_t comma = std::min(list.find(',', at), list.size());
        const std::string name = list.substr(at, comma - at);
        if (!name.empty())
            if (std::string err = trainClips_.check(name, true); !err.empty()) return err;
        at = comma + 1;
    }
    gp::FrameSelection& sel = trainClips_.selection();
    if (a.size() > 1 && a[1] != "all") {
        const std::size_t colon = a[1].find(':');
        if (colon == std::string::npos) return "expected a frame range A:B or all, found '" + a[1] + "'";
        if (std::string err = parseIntArg(a[1].substr(0, colon), "the first frame A", sel.first); !err.empty())
            return err;
        if (std::string err = parseIntArg(a[1].substr(colon + 1), "the last frame B", sel.last); !err.empty())
            return err;
        if (sel.first < 1 || sel.last < sel.first) return "expected frames A:B with 1 <= A <= B, found '" + a[1] + "'";
    }
    if (a.size() > 2)
        if (std::string err = parseIntArg(a[2], "the step K", sel.step); !err.empty()) return err;
    if (sel.step < 1) return "expected a step K >= 1, found " + std::to_string(sel.step);
    gp::TrainOptions o = state_.trainOptions;
    if (a.size() > 3)
        if (std::string err = parseIntArg(a[3], "the active set size M", o.activeSize); !err.empty()) return err;
    if (a.size() > 4)
        if (std::string err = parseIntArg(a[4], "the iteration count T", o.outerIterations); !err.empty()) return err;
    if (a.size() > 5)
        return "expected train-clips CLIPS [A:B|all] [K] [M] [T], found " + std::to_string(a.size()) + " arguments";
    state_.trainOptions = o;
    return trainClips_.train(*this);
}

void EditorApp::dialogs() {
    if (auto path = dialog_.draw()) {
        lastDialogFolder_ = std::filesystem::path(*path).parent_path().string();
        switch (purpose_) {
            case FileKind::kOpenAny: openAny(*path); break;
            case FileKind::kModel: openModel(*path, true); break;  // asked before the dialog opened
            case FileKind::kSaveModel: saveModel(*path); break;
            case FileKind::kSaveSession:
                if (saveSession(*path).empty())
                    if (auto then = prompts_.takeAfterSave()) then();
                break;
            case FileKind::kExportBvh: exportMotion(*path, ".bvh"); break;
            case FileKind::kExportGltf: exportMotion(*path, ".glb"); break;
            case FileKind::kExportFbx: exportMotion(*path, ".fbx"); break;
            case FileKind::kExportPng: exportPng(*path); break;
            case FileKind::kNone: break;
        }
        purpose_ = FileKind::kNone;
    }
    if (!dialog_.isOpen()) prompts_.dropAfterSave();  // the save dialog was cancelled: so is the action
}

void EditorApp::askForFile(FileKind kind, const std::string& what) {
    if (what.empty())
        openDialog(kind);
    else
        guardUnsaved([this, kind] { openDialog(kind); }, what);
}

void EditorApp::openDialog(FileKind purpose) {
    if (purpose == FileKind::kNone) return;
    FileRequest r = fileRequest(purpose, state_.doc, sessionPath_, options_.mocapDir);
    if (!lastDialogFolder_.empty()) r.startDir = lastDialogFolder_;  // where the user last was, as Blender does
    dialog_.open(std::move(r.title), r.mode, std::move(r.extensions), r.startDir, r.defaultName);
    purpose_ = purpose;
}

bool EditorApp::popupOpen() const {
    return dialog_.isOpen() || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
}

void EditorApp::guardUnsaved(std::function<void()> action, std::string what) {
    prompts_.guard(dirty(), std::move(action), std::move(what));
}

std::string EditorApp::runAfterAsking(bool unsaved, std::function<std::string()> run, std::string what) {
    if (!unsaved) return run();
    prompts_.guard(
        true, [run = std::move(run)] { run(); }, std::move(what));
    return "";
}

void EditorApp::prompts() {
    if (std::exchange(quitAsked_, false)) guardUnsaved([this] { quitConfirmed_ = true; }, "quitting");
    EditorPrompts::Hooks hooks;
    hooks.sessionPath = sessionPath_;
    hooks.save = [this](const std::string& path) { return saveSession(path).empty(); };
    hooks.askForSessionFile = [this] { openDialog(FileKind::kSaveSession); };
    hooks.restore = [this](const std::string& path) { restoreAutosave(path); };
    hooks.recordControl = [this](const std::string& name) { state_.recordControl(name); };
    prompts_.draw(dialog_.isOpen(), hooks);
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
    state_.profile.beginFrame();
    pollJobs();
    if (autosave_.due(secondsNow(), dirty(), state_.doc.revision())) autosaveNow();
    TimelinePanel::advance(state_, io.DeltaTime);

    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    shortcuts();
    drawMenuBar(*this, showMessages_, latent_.busy() ? "latent map..." : "");
    state_.messages.update(state_.uiSeconds, state_.doc.revision());
    layout_.draw(state_, *viewport_, latent_, timeline_, width, height);
    if (const int picked = viewport_->takePickedJoint(); picked >= 0) jointWindow_.selectJoint(picked);
    jointWindow_.draw(*this);
    trainClips_.draw(*this);
    viewport_->setJointPicking(jointWindow_.shown());
    state_.gizmoJoint = jointWindow_.shown() ? jointWindow_.joint() : -1;
    state_.gizmoFollowPrior = jointWindow_.followPrior();
    drawHelpWindow(showHelp_, layout_.leftWidth() * 0.5f, float(height) * 0.5f, options_.autosaveSeconds);
    runRequests();
    dialogs();
    prompts();
    drawMessagesWindow(showMessages_, state_.messages, state_.uiSeconds);
    ImGui::Render();

    // The viewport's scene is blitted and the latent map's textures are drawn by reference: their
    // versions belong to the signature as much as ImGui's vertices do.
    const std::uint64_t signature =
        frameSignature(*ImGui::GetDrawData(), {viewport_->sceneDraws(), latent_.imageVersion(), width, height});
    frameDrawn_ = redrawRequested_ || signature != lastFrameSignature_;
    if (!frameDrawn_) return;
    redrawRequested_ = false;
    lastFrameSignature_ = signature;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    // In the panels' colour: they draw no background (EditorLayout), and the viewport's scene covers
    // the rest. Colour only: the window's depth is never read (the scene has its own, ImGui none),
    // and on llvmpipe clearing it costs a pass over the whole window.
    const ImVec4 panel = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
    glClearColor(panel.x, panel.y, panel.z, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    const PhaseTimer timer(state_.profile, state_.profile.imguiRenderSeconds);
    viewport_->presentTo(height);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

render::Image EditorApp::capture(int width, int height) const {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return render::readFramebuffer(width, height);
}

}  // namespace mgp::ui
