#include "ui/shell/editor_state.h"

#include <imgui.h>
#include <imgui_internal.h>

namespace mgp::ui {

void EditorState::recordControl(const std::string& name) {
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    // Visible: wholly inside what its window shows (not scrolled or clipped away, even in part).
    const ImRect clip = ImGui::GetCurrentWindow()->ClipRect;
    controls[name] = {a.x, a.y, b.x, b.y, clip.Contains(ImRect(a, b))};
}

}  // namespace mgp::ui
