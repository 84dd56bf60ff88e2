#pragma once
// The offscreen editor the GUI tests drive (label `gl`): an EGL context, an EditorApp with the
// built-in font, input fed exactly as a --script run feeds it. makeHarness opens the shipped 35_01
// and, unless told not to, the committed model tests/fixtures/walk35_fas_m100_t3.model (FASGPLVM,
// M = 100, T = 3): a model file, not a model trained at test time, so the pictures that show it are
// the same on every CPU.
#include <initializer_list>
#include <memory>
#include <string>

#include "render/gl_context.h"
#include "ui/input/gui_script.h"
#include "ui/shell/editor_app.h"

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
    // It draws with ImGui's built-in font (no dependence on system fonts) unless `editorFont`:
    // then with the editor's own, DejaVu Sans, as a user sees it (layout tests).
    void restartApp(ui::EditorOptions options = {}, bool editorFont = false);
};

// Presses and releases key `k` (with modifiers `mods` held) within one frame, as `xdotool key`
// does, then runs 3 frames: the input replay spreads the events over them.
void tapKey(Harness& h, int k, std::initializer_list<int> mods = {});

// A left click at window pixel (x, y) as a --script run plays it (move, press on frame 2,
// release on frame 4), over 7 frames.
void clickAt(Harness& h, float x, float y);

// Answers the unsaved-changes question with the button "Save", "Don't save" or "Cancel" (a click),
// after drawing it; requires the question to be up.
void answerUnsaved(Harness& h, const std::string& button);

// nullptr (the test is then reported skipped, with the reason: the caller returns) when no
// offscreen context can be made, or when llvmpipeOnly and the context is not llvmpipe.
std::unique_ptr<Harness> makeHarness(bool llvmpipeOnly, bool withModel = true);

const std::string& mocapDir();   // the shipped clips (assets/mocap)
std::string fixtureModelPath();  // the committed walk model

}  // namespace mgp::test
