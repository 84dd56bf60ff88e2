#pragma once
// Small ImGui layout helpers shared by the panels.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

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

// Splits `text` into lines no wider than `room` (as `width` measures them), breaking only at
// spaces: ImGui's own wrapping also breaks after a full stop, which cuts "0.002 cm" in two. A word
// wider than the room keeps a line of its own.
std::vector<std::string> linesBrokenAtSpaces(const std::string& text, float room,
                                             const std::function<float(std::string_view)>& width);

// `text` wrapped at the window's right edge, broken only at spaces (see linesBrokenAtSpaces).
void textWrappedAtSpaces(const std::string& text);

// Puts the next widget (a button labelled `label`, plus `extra` pixels such as a check box) on
// the current line only if it fits in the window's width; else it starts a new line.
void sameLineIfFits(const char* label, float extra = 0.0f);

}  // namespace mgp::ui
