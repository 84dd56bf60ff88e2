#pragma once
// Small ImGui layout helpers shared by the panels.
namespace mgp::ui {

// Puts the next widget (a button labelled `label`, plus `extra` pixels such as a check box) on
// the current line only if it fits in the window's width; else it starts a new line.
void sameLineIfFits(const char* label, float extra = 0.0f);

}  // namespace mgp::ui
