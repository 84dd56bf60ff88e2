#pragma once
// Help > Controls (F1): the mouse gestures of the viewport, path editing and latent map, and
// every action's shortcut, listed from the action table (editor_actions.h).
namespace mgp::ui {

// Draws the window while `open` (its close box clears it), first placed centred on (x, y).
void drawHelpWindow(bool& open, float x, float y, double autosaveSeconds);

}  // namespace mgp::ui
