#include "ui/widgets/widgets.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cstdarg>

namespace mgp::ui {

void tooltip(const char* fmt, ...) {
    const ImGuiStyle& st = ImGui::GetStyle();
    const float margin = 2.0f * (st.WindowPadding.x + st.DisplaySafeAreaPadding.x);
    const float wrap = std::max(ImGui::GetFontSize() * 8.0f,
                                std::min(ImGui::GetFontSize() * 35.0f, ImGui::GetIO().DisplaySize.x - margin));
    // Replaces a tooltip set earlier in the frame, as ImGui::SetTooltip does (BeginTooltip would
    // append to it).
    ImGui::BeginTooltipEx(ImGuiTooltipFlags_OverridePreviousTooltip, ImGuiWindowFlags_None);
    ImGui::PushTextWrapPos(wrap);
    va_list args;
    va_start(args, fmt);
    ImGui::TextV(fmt, args);
    va_end(args);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

void textEllipsized(const ImVec4& colour, const std::string& text) {
    const float room = ImGui::GetContentRegionAvail().x;
    std::string shown = text;
    if (ImGui::CalcTextSize(shown.c_str()).x > room) {
        const float ellipsis = ImGui::CalcTextSize("...").x;
        while (!shown.empty() && ImGui::CalcTextSize(shown.c_str()).x + ellipsis > room) {
            // Whole UTF-8 characters (°, σ): continuation bytes go with their lead byte.
            while (!shown.empty() && (static_cast<unsigned char>(shown.back()) & 0xC0) == 0x80) shown.pop_back();
            if (!shown.empty()) shown.pop_back();
        }
        shown += "...";
    }
    ImGui::TextColored(colour, "%s", shown.c_str());
    if (shown != text && ImGui::IsItemHovered()) tooltip("%s", text.c_str());
}

void sameLineIfFits(const char* label, float extra) {
    const ImGuiStyle& st = ImGui::GetStyle();
    const float next = ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * st.FramePadding.x + extra;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + st.ItemSpacing.x + next <= right) ImGui::SameLine();
}

}  // namespace mgp::ui
