#pragma once
// EditorApp: the whole editor UI for one GL context. It owns the ImGui context (OpenGL3
// backend only: input comes from an InputState, filled by the GLFW window or by a GuiScript, so
// the same code runs in a window and on the offscreen EGL context), the document and the panels.
// Call frame() once per frame with the context current; it draws into framebuffer 0.
//
// Default layout (1280×800): menu bar; viewport in the centre; Model panel, latent map and IK
// readout on the right; timeline and status line at the bottom.
#include <memory>
#include <string>
#include <vector>

#include "editor_state.h"
#include "file_dialog.h"
#include "gui_script.h"
#include "input_state.h"
#include "latent_map_panel.h"
#include "png_capture.h"
#include "timeline_panel.h"
#include "viewport_panel.h"

namespace mgp::ui {

struct EditorOptions {
    bool builtinFont = false;   // ImGui's built-in bitmap font (goldens) instead of DejaVu Sans
    std::string mocapDir;       // where File > Open starts ("" = current directory)
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
    bool quitRequested() const { return state_.requestQuit; }
    EditorState& state() { return state_; }
    const EditorState& state() const { return state_; }
    bool latentMapUpToDate() const { return latent_.upToDate(state_); }
    // Window pixel of an effector handle (as last drawn).
    bool handleScreenPosition(Effector e, float& x, float& y) const;
    // Runs a named UI action (the script's `action` verb); "" or the error.
    std::string runAction(const std::vector<std::string>& args);

private:
    void pollJobs();
    void shortcuts();
    void menus();
    void layout(int width, int height);
    void dialogs();

    EditorOptions options_;
    EditorState state_;
    std::unique_ptr<ViewportPanel> viewport_;
    LatentMapPanel latent_;
    TimelinePanel timeline_;
    FileDialog dialog_;
    enum class DialogPurpose { kNone, kClip, kModel, kSaveModel } purpose_ = DialogPurpose::kNone;
    bool showHelp_ = false;
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
    std::vector<int> releaseNext_;
    std::vector<std::string> errors_;
};

}  // namespace mgp::ui
