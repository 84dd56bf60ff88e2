#pragma once
// Running the editor (the `gui` verb and `motiongp` with no verb).
#include <string>

namespace mgp::app {

struct GuiArgs {
    std::string clip;        // "" = the default clip (10_02 kick) or the synthetic demo clip
    std::string model;       // a saved model to open (its clip comes with it)
    int frames = 0;          // frames to run, 0 = until the window closes (offscreen: 3)
    std::string script;      // timed input events (ui/input/gui_script.h)
    std::string screenshot;  // PNG of the whole window after the last frame
    bool offscreen = false;  // EGL surfaceless context, no display needed
    int width = 1280, height = 800;
    float uiScale = 0.0f;  // fonts and panels; 0 = the monitor's content scale
    bool json = false;     // at the end, one JSON object on stdout: frames run, files written, script errors
};

// Returns the exit code; throws UsageError / ParseError / RenderError for the caller to report.
int runGui(const GuiArgs& args);

}  // namespace mgp::app
