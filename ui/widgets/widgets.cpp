#include "ui/widgets/widgets.h"

#include <imgui.h>

namespace mgp::ui {

void sameLineIfFits(const char* label, float extra) {
    const ImGuiStyle& st = ImGui::GetStyle();
    const float next = ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * st.FramePadding.x + extra;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + st.ItemSpacing.x + next <= right) ImGui::SameLine();
}

}  // namespace mgp::ui
