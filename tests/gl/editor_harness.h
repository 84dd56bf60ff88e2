#pragma once
// The offscreen editor the GUI tests drive (label `gl`): an EGL context, an EditorApp with the
// built-in font, input fed exactly as a --script run feeds it. makeHarness opens 35_01 and
// trains a small model (FASGPLVM, M = 100, T = 3: about a second).
#include <memory>
#include <string>

#include "editor_app.h"
#include "gl_context.h"
#include "gui_script.h"

namespace mgp::test {

constexpr int kGuiWidth = 1280, kGuiHeight = 800;

struct Harness {
    std::unique_ptr<render::OffscreenContext> ctx;
    std::unique_ptr<ui::EditorApp> app;
    ui::InputState input;
    int frameNo = 0;

    void frame(int n = 1);
    // Plays a script from its frame 0 to its last frame + 2, one UI frame each; returns the
    // script's errors.
    std::vector<std::string> play(const ui::GuiScript& script);
    // A second editor on the same context (e.g. "after a restart"); the first one is destroyed.
    void restartApp(ui::EditorOptions options = {});
};

// nullptr (the test is then reported skipped, with the reason) when the mocap folder or an
// offscreen context is missing, or when llvmpipeOnly and the context is not llvmpipe.
std::unique_ptr<Harness> makeHarness(bool llvmpipeOnly, bool train = true);

const std::string& mocapDir();

}  // namespace mgp::test
