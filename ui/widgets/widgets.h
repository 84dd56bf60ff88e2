#pragma once
// Small ImGui layout helpers shared by the panels.
#include <string>

struct ImVec4;

namespace mgp::ui {

// A hover tooltip (printf-style, as ImGui::SetTooltip) whose lines wrap at 35 em or the window's
// width less a margin, whichever is smaller, so that ImGui can keep it wholly on screen.
void tooltip(const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

// One line of `text` in `colour`: where it is wider than the room left on the line it ends in "..."
// and shows whole in a tooltip on hover.
void textEllipsized(const ImVec4& colour, const std::string& text);

// Puts the next widget (a button labelled `label`, plus `extra` pixels such as a check box) on
// the current line only if it fits in the window's width; else it starts a new line.
void sameLineIfFits(const char* label, float extra = 0.0f);

}  // namespace mgp::ui
