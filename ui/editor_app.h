#pragma once
// EditorApp: the whole editor UI for one GL context. It owns the ImGui context (OpenGL3
// backend only: input comes from an InputState, filled by the GLFW window or by a GuiScript, so
// the same code runs in a window and on the offscreen EGL context), the document and the panels.
// Call frame() once per frame with the context current; it draws into framebuffer 0.
//
// Default layout (1280×800): menu bar; viewport in the centre; Model panel, latent map and IK
// readout on the right; timeline and status line at the bottom.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "edit/autosave.h"
#include "edit/recent_files.h"
#include "editor_state.h"
#include "file_dialog.h"
#include "gui_script.h"
#include "input_replay.h"
#include "input_state.h"
#include "latent_map_panel.h"
#include "layout_store.h"
#include "png_capture.h"
#include "timeline_panel.h"
#include "viewport_panel.h"

namespace mgp::ui {

struct EditorOptions {
    bool builtinFont = false;   // ImGui's built-in bitmap font (goldens) instead of DejaVu Sans
    std::string mocapDir;       // where File > Open starts ("" = current directory)
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

class EditorApp {
public:
    explicit EditorApp(EditorOptions options = {});  // needs a current GL 3.3 core context
    ~EditorApp();
    EditorApp(const EditorApp&) = delete;
    EditorApp& operator=(const EditorApp&) = delete;

    // Each returns "" or the error (also shown in the status line). Nothing here throws.
    std::string openClip(const std::string& path);
    void openSyntheticClip(const std::string& why);
    std::string openModel(const std::string& path);
    std::string saveModel(const std::string& path);
    std::string startTraining();  // on the open clip with state().trainOptions
    // Sessions (core/edit/session_file.h): clip reference, model, edits, camera, UI state.
    std::string openSession(const std::string& path, bool addToRecent = true);
    std::string saveSession(const std::string& path);  // becomes the current session file
    std::string autosaveNow();                         // to this editor's autosave file
    // Restores an autosave (the newest one a dead editor left behind when `path` is "").
    std::string restoreAutosave(const std::string& path = "");
    // Exports: the edited motion as BVH (the CLI's exporter) and the 3-D view as PNG.
    std::string exportBvh(const std::string& path);
    std::string exportPng(const std::string& path);
    bool dirty() const { return state_.doc.revision() != savedRevision_; }
    bool askingAboutUnsavedChanges() const { return askingUnsaved_; }  // the modal is up
    const FileDialog& fileDialog() const { return dialog_; }
    bool popupOpen() const;  // a menu, a modal or the file dialog is open (as of the last frame)
    bool messagesShown() const { return showMessages_; }   // View > Messages
    float uiScale() const { return scale_; }
    bool offeringAutosave() const { return !restoreOffer_.empty(); }
    const std::string& sessionPath() const { return sessionPath_; }

    // One UI frame of width×height pixels; dt in seconds.
    void frame(InputState& input, double dt, int width, int height);
    // Reads the whole window (call right after frame()).
    render::Image capture(int width, int height) const;
    // Blocks until training, adaptive updates and the latent image are finished (scripts, tests).
    void waitIdle();

    std::string title() const;
    // Whether the next frames change on their own (playback, a drag being refined, background
    // work to pick up); when false the window may sleep until the next input event.
    bool animating() const;
    // True once the user confirmed quitting (after the unsaved-changes prompt if needed).
    bool quitRequested() const { return quitConfirmed_; }
    void requestQuit() { state_.requestQuit = true; }
    EditorState& state() { return state_; }
    const EditorState& state() const { return state_; }
    const ViewportPanel& viewport() const { return *viewport_; }
    bool latentMapUpToDate() const { return latent_.upToDate(state_); }
    // Window pixel of an effector handle (as last drawn).
    bool handleScreenPosition(Effector e, float& x, float& y) const;
    bool keyScreenPosition(int key, float& x, float& y) const;  // path key (0-based), as last drawn
    // Runs a named UI action (the script's `action` verb); "" or the error.
    std::string runAction(const std::vector<std::string>& args);

private:
    enum class DialogPurpose { kNone, kClip, kModel, kSaveModel, kSaveSession, kExportBvh, kExportPng };
    void pollJobs();
    // Runs `work`; an exception becomes the status line's error and the returned text ("" if none).
    std::string reportingErrors(const std::function<void()>& work);
    void autosaveIfDue();
    void forgetAutosave();  // after a save or an open: this editor's autosave is stale
    void prompts();
    void markSaved();
    void remember(const std::string& path, RecentKind kind);
    std::string openAny(const std::string& path);  // by extension: session, model or clip
    void openDialog(DialogPurpose purpose);
    // Runs `action` now, or after asking about unsaved changes ("Save them before <what>?").
    void guardUnsaved(std::function<void()> action, std::string what);
    void shortcuts();
    void copyPose();          // the current frame's pose to the pose clipboard
    std::string pastePose();  // onto the current frame (root position kept), one undo step
    void menus();
    void layout(int width, int height);
    void layoutPanels(int w, int h, float menuH, float rightW, float timelineH, float modelH, float latentH);
    void dialogs();
    void messagesWindow();

    EditorOptions options_;
    EditorState state_;
    std::unique_ptr<ViewportPanel> viewport_;
    InputReplay replay_;  // presses and releases, at most one change per button or key per frame
    LatentMapPanel latent_;
    TimelinePanel timeline_;
    FileDialog dialog_;
    DialogPurpose purpose_ = DialogPurpose::kNone;
    DialogPurpose request_ = DialogPurpose::kNone;  // a dialog a menu or shortcut asked for
    float scale_ = 1.0f;  // EditorOptions::uiScale, clamped to 0.5..4
    LayoutPrefs prefs_;   // the splitters, as the user left them
    // A draggable strip between panels; returns the mouse's move along it this frame.
    float splitter(const char* id, float x, float y, float w, float h, bool vertical, bool& released);
    bool showHelp_ = false;
    bool showMessages_ = false;
    bool trainingSeen_ = false;  // a training run this editor started has not been reported yet
    std::optional<Pose> poseClipboard_;
    bool pathTabShown_ = false;

    std::string sessionPath_;  // "" until saved or opened
    long savedRevision_ = 0;   // doc.revision() when last saved or opened
    std::unique_ptr<RecentFiles> recent_;  // null when the options turn the list off
    AutosaveTimer autosave_;
    std::string autosaveFile_;
    bool quitConfirmed_ = false;
    // The unsaved-changes question: what waits for the answer, and what runs after "Save" when
    // the session still needs a file name.
    std::function<void()> pending_, afterSave_;
    std::string pendingWhat_;
    bool askingUnsaved_ = false;
    long autosavedRevision_ = 0;
    std::vector<AutosaveCandidate> restoreOffer_;
};

// Plays a GuiScript into an InputState and the app's actions, frame by frame.
class ScriptPlayer {
public:
    explicit ScriptPlayer(GuiScript script);
    // Applies the events of `frame` (before EditorApp::frame). Screenshot actions are returned in
    // `screenshots` and must be written after the frame is drawn.
    void apply(int frame, InputState& input, EditorApp& app, std::vector<std::string>& screenshots);
    int lastFrame() const { return script_.lastFrame(); }
    const std::vector<std::string>& errors() const { return errors_; }

private:
    GuiScript script_;
    std::size_t next_ = 0;
    std::vector<std::string> errors_;
};

}  // namespace mgp::ui
