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

std::vector<std::string> linesBrokenAtSpaces(const std::string& text, float room,
                                             const std::function<float(std::string_view)>& width) {
    std::vector<std::string> lines;
    std::string line;
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t space = text.find(' ', at);
        const std::size_t end = space == std::string::npos ? text.size() : space;
        const std::string_view word(text.data() + at, end - at);
        const std::string joined = line.empty() ? std::string(word) : line + " " + std::string(word);
        if (!line.empty() && width(joined) > room) {
            lines.push_back(line);
            line = std::string(word);
        } else {
            line = joined;
        }
        at = end + 1;
    }
    if (!line.empty() || lines.empty()) lines.push_back(line);
    return lines;
}

void textWrappedAtSpaces(const std::string& text) {
    const float room = std::max(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize());
    const auto width = [](std::string_view s) { return ImGui::CalcTextSize(s.data(), s.data() + s.size()).x; };
    for (const std::string& line : linesBrokenAtSpaces(text, room, width)) ImGui::TextUnformatted(line.c_str());
}

void sameLineIfFits(const char* label, float extra) {
    const ImGuiStyle& st = ImGui::GetStyle();
    const float next = ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * st.FramePadding.x + extra;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (ImGui::GetItemRectMax().x + st.ItemSpacing.x + next <= right) ImGui::SameLine();
}

}  // namespace mgp::ui
