#pragma once
// EditorApp: the whole editor UI for one GL context. It owns the ImGui context (OpenGL3
// backend only: input comes from an InputState, filled by the GLFW window or by a GuiScript, so
// the same code runs in a window and on the offscreen EGL context), the document and the panels.
// Call frame() once per frame with the context current; it draws into framebuffer 0.
//
// Default layout (1280×800): menu bar; viewport in the centre; Model panel, latent map and IK
// readout on the right; timeline and status line at the bottom (editor_layout.h). What the
// menus, shortcuts and scripts can do is the action table (editor_actions.h); it, the menu bar,
// the windows and the script player reach the editor through EditorCommands
// (editor_commands.h), which EditorApp implements. The modal questions are editor_prompts.h; the
// script player is script_player.h.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/png_capture.h"
#include "session/autosave_policy.h"
#include "session/recent_files.h"
#include "ui/actions/editor_commands.h"
#include "ui/input/input_replay.h"
#include "ui/input/input_state.h"
#include "ui/input/script_player.h"
#include "ui/panels/latent_map_panel.h"
#include "ui/panels/timeline_panel.h"
#include "ui/panels/viewport_panel.h"
#include "ui/shell/editor_layout.h"
#include "ui/shell/editor_prompts.h"
#include "ui/shell/editor_state.h"
#include "ui/shell/file_requests.h"
#include "ui/windows/file_dialog.h"
#include "ui/windows/joint_rotation_window.h"
#include "ui/windows/train_clips_window.h"

namespace mgp::ui {

struct EditorOptions {
    bool builtinFont = false;  // ImGui's built-in bitmap font (goldens) instead of DejaVu Sans
    std::string mocapDir;      // where File > Open starts ("" = current directory)
    // After a crash: offer the autosave a dead editor left behind (the interactive editor).
    bool offerAutosaveRestore = false;
    double autosaveSeconds = 120.0;  // autosave interval while there are unsaved changes
    bool recentFiles = false;        // read and update the user's recent-files list
    // HiDPI: the monitor's content scale (2 on a 200 % display): fonts, spacing and panel sizes.
    float uiScale = 1.0f;
    // Where the splitters' positions are remembered ("" = not remembered; the interactive
    // editor uses configDir()/layout.json).
    std::string layoutFile;
};

class EditorApp : public EditorCommands {
public:
    explicit EditorApp(EditorOptions options = {});  // needs a current GL 3.3 core context
    ~EditorApp();
    EditorApp(const EditorApp&) = delete;
    EditorApp& operator=(const EditorApp&) = delete;

    // Each returns "" or the error (also shown in the status line). Nothing here throws.
    std::string openClip(const std::string& path) override;
    void openSyntheticClip(const std::string& why) override;
    // Opens a model with the clip it was trained on. When that is not the open clip, it asks
    // first (Open its clip, or Cancel) and returns "" while the question is up.
    // `askedAboutUnsaved`: the caller already asked (before a file dialog, a recent file).
    std::string openModel(const std::string& path, bool askedAboutUnsaved = false) override;
    std::string saveModel(const std::string& path) override;
    // Makes the model's training clip `name` the open clip at `frame` (0-based), the model staying
    // (gp::withPrimaryClip); asks about unsaved changes first. "" or the error.
    std::string openModelClip(const std::string& name, int frame) override;
    // Trainings replace the model when they finish: with a model no file holds, they start after
    // asking about it (and return "" while the question is up).
    std::string startTraining() override;  // on the open clip with state().trainOptions
    // On clips checked by gp::prepareTrainingClips (the open clip first) with state().trainOptions:
    // Model > Train on clips... (train_clips_window.h).
    std::string startTraining(std::vector<gp::TrainingClip> clips, const gp::FrameSelection& selection) override;
    std::string startCompareTraining() override;  // the compare model: the other kernel, same options
    // Sessions (core/session/session_file.h): clip reference, model, edits, camera, UI state.
    std::string openSession(const std::string& path, bool addToRecent = true) override;
    std::string saveSession(const std::string& path) override;  // becomes the current session file
    void saveSessionOrAsk() override;    // to the current session file, or the Save dialog when there is none
    std::string autosaveNow() override;  // to this editor's autosave file
    // Restores an autosave (the newest one a dead editor left behind when `path` is "").
    std::string restoreAutosave(const std::string& path = "") override;
    // Exports: the edited motion as BVH (the CLI's exporter) and the 3-D view as PNG.
    // The edited motion as BVH, glTF or FBX (by the path's extension; `defaultExtension` when it has
    // none). FBX runs on the export worker; pollExport reports it.
    std::string exportMotion(const std::string& path, const std::string& defaultExtension) override;
    std::string exportPng(const std::string& path) override;
    // Opens the file dialog for `kind`; with `what` ("opening a model") after asking about
    // unsaved changes, since the document will be replaced.
    void askForFile(FileKind kind, const std::string& what = "") override;
    // Runs `action` now, or after asking about unsaved changes ("Save them before <what>?").
    void guardUnsaved(std::function<void()> action, std::string what) override;
    // Runs `run` now and returns its error when nothing is `unsaved`; else asks as guardUnsaved
    // does and returns "" while the question is up (an error after it goes to the status line).
    std::string runAfterAsking(bool unsaved, std::function<std::string()> run, std::string what) override;
    void copyPose() override;          // the current frame's pose to the pose clipboard
    std::string pastePose() override;  // onto the current frame (root position kept), one undo step
    bool hasCopiedPose() const override { return poseClipboard_.has_value(); }
    std::string mirrorPose() override;  // the current frame's pose mirrored left/right, one undo step
    // Rotate joint: no arguments shows the window; JOINT and one angle (degrees) per axis it
    // animates, in x, y, z order, sets them as one undo step (with the window's prior option).
    std::string rotateJoint(const std::vector<std::string>& args) override;
    JointRotationWindow& jointWindow() override { return jointWindow_; }
    TrainClipsWindow& trainClipsWindow() { return trainClips_; }
    const TrainClipsWindow& trainClipsWindow() const { return trainClips_; }
    // The `train-clips` action: no arguments shows Train on clips...; CLIPS (comma-separated names
    // or paths) [A:B|all] [K] [M] [T] ticks those clips, sets the range and options and trains.
    std::string trainOnClips(const std::vector<std::string>& args) override;
    const JointRotationWindow& jointWindow() const { return jointWindow_; }
    void toggleHelp() override { showHelp_ = !showHelp_; }
    const RecentFiles* recentFiles() const override { return recent_.get(); }  // null when turned off
    void openRecent(const std::string& path) override;                         // after asking about unsaved changes
    bool layoutCustomized() const override { return layout_.customized(); }
    void resetLayout() override { layout_.reset(); }

    // Unsaved work: edits since the last save or open, or a model this editor trained or changed
    // that no model file or session holds (it outlives opening a clip and switching clips, and so
    // does the question).
    bool dirty() const override { return state_.doc.revision() != savedRevision_ || modelUnsaved(); }
    bool modelUnsaved() const;
    // A compare model (trained here) that no session file holds: a new compare training asks first.
    bool compareModelUnsaved() const;
    bool askingAboutUnsavedChanges() const { return prompts_.askingUnsaved(); }  // the modal is up
    bool askingAboutModelClip() const { return prompts_.askingModelClip(); }     // the modal is up
    const FileDialog& fileDialog() const override { return dialog_; }
    bool popupOpen() const;  // a menu, a modal or the file dialog is open (as of the last frame)
    float uiScale() const override { return scale_; }
    bool offeringAutosave() const { return prompts_.offeringAutosave(); }
    const std::string& sessionPath() const { return sessionPath_; }

    // One UI frame of width×height pixels; dt in seconds. A frame that would draw exactly the
    // pixels of the previous one (the same frame signature, ui/shell/frame_signature.h) leaves framebuffer
    // 0 as it is and reports frameDrawn() false, unless requestRedraw() was called since.
    void frame(InputState& input, double dt, int width, int height);
    bool frameDrawn() const { return frameDrawn_; }
    // The next frame draws even when it matches the last one: the framebuffer's contents were lost
    // (a window was exposed, buffers swapped before a screenshot) or overwritten by someone else.
    void requestRedraw() { redrawRequested_ = true; }
    // Reads the whole window (call right after frame()). After a frame that was not drawn,
    // framebuffer 0 still holds the last drawn one: the same pixels offscreen, but a window's back
    // buffer is undefined after a swap, so call requestRedraw() before that frame there.
    render::Image capture(int width, int height) const;
    // Blocks until training, adaptive updates and the latent image are finished (scripts, tests).
    void waitIdle() override;

    std::string title() const;
    // Whether the next frames change on their own (playback, a drag being refined, background
    // work to pick up); when false the window may sleep until the next input event.
    bool animating() const;
    // True once the user confirmed quitting (after the unsaved-changes prompt if needed).
    bool quitRequested() const { return quitConfirmed_; }
    void requestQuit() override { quitAsked_ = true; }      // asks about unsaved changes first
    void confirmQuit() override { quitConfirmed_ = true; }  // quits without asking
    EditorState& state() override { return state_; }
    const EditorState& state() const override { return state_; }
    const ViewportPanel& viewport() const { return *viewport_; }
    bool latentMapUpToDate() const { return latent_.upToDate(state_); }
    int latentMapLayerRenders() const { return latent_.layerRenders(); }
    // Window pixel of an effector handle (as last drawn).
    bool handleScreenPosition(Effector e, float& x, float& y) const override;
    bool keyScreenPosition(int key, float& x, float& y) const override;  // path key (0-based), as last drawn
    // Window pixel of the latent map's dot of clip `clip` frame `frame` (0-based), as last drawn.
    bool latentDotScreenPosition(const std::string& clip, int frame, float& x, float& y) const override;
    // Runs a named action (editor_actions.h; args[0] is the name): "" or the error.
    std::string runAction(const std::vector<std::string>& args) override;

private:
    void pollJobs();
    // Installs the training run's published and final models between gestures.
    void pollTraining();
    void pollExport();
    std::string reportTrainingStart(const std::string& err);  // status line for a training start: "" or err
    // Runs `work`; an exception becomes the status line's error and the returned text ("" if none).
    std::string reportingErrors(const std::function<void()>& work);
    void forgetAutosave();         // after a save or an open: this editor's autosave is stale
    void noteSavedCompareModel();  // the compare model a session file now holds
    // The document's edits count as saved; so does its model when `modelSaved` (a session or a
    // model file opened, a clip opened without one), else an unsaved model stays unsaved (a switch
    // to the model's other clip keeps the model).
    void markSaved(bool modelSaved);
    void installModel(gp::ModelVersionPtr version, const std::string& path);  // with its clip
    void remember(const std::string& path, RecentKind kind);
    std::string openAny(const std::string& path);  // by extension: session, model or clip
    void openDialog(FileKind kind);
    void shortcuts();
    void runRequests();  // the actions the panels asked for (EditorState::request)
    void dialogs();
    void prompts();

    EditorOptions options_;
    EditorState state_;
    std::uint64_t lastFrameSignature_ = 0;
    bool frameDrawn_ = true;
    bool redrawRequested_ = true;  // the first frame draws
    std::unique_ptr<ViewportPanel> viewport_;
    InputReplay replay_;  // presses and releases, at most one change per button or key per frame
    LatentMapPanel latent_;
    TimelinePanel timeline_;
    FileDialog dialog_;
    FileKind purpose_ = FileKind::kNone;  // what the open file dialog is for
    std::string lastDialogFolder_;        // the folder of the last file a dialog gave ("" = none yet)
    float scale_ = 1.0f;                  // EditorOptions::uiScale, clamped to 0.5..4
    EditorLayout layout_;
    EditorPrompts prompts_;
    bool showHelp_ = false;
    bool showMessages_ = false;
    bool trainingSeen_ = false;  // a training run this editor started has not been reported yet
    bool exportSeen_ = false;    // an export this editor started has not been reported yet
    std::string exportStage_;    // the running export's stage as last shown
    std::optional<Pose> poseClipboard_;
    JointRotationWindow jointWindow_;
    TrainClipsWindow trainClips_;

    std::string sessionPath_;                      // "" until saved or opened
    long savedRevision_ = 0;                       // doc.revision() when last saved or opened
    std::weak_ptr<const gp::GpModel> savedModel_;  // the model a file or session holds (weak: never a reused address)
    std::weak_ptr<const gp::GpModel> savedCompareModel_;  // the compare model the session file holds
    std::unique_ptr<RecentFiles> recent_;                 // null when the options turn the list off
    AutosavePolicy autosave_;
    bool quitAsked_ = false;  // Quit was chosen: the unsaved-changes question comes first
    bool quitConfirmed_ = false;
};

}  // namespace mgp::ui
