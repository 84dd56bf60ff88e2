#pragma once
// Keyboard shortcuts that match their modifiers exactly: Ctrl+T is not Ctrl+Alt+T, and P is not
// Shift+P. Call between ImGui::NewFrame and ImGui::Render.
namespace mgp::ui {

enum Modifiers : unsigned { kNoMods = 0, kCtrl = 1, kShift = 2, kAlt = 4 };

// `key` (a GLFW key code, ASCII for letters) went down this frame (or repeats, when `repeat`)
// while exactly `mods` were held.
bool chordPressed(int key, unsigned mods = kNoMods, bool repeat = false);

}  // namespace mgp::ui
