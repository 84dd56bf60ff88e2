#include "ui/windows/messages_window.h"

#include <imgui.h>

namespace mgp::ui {

// View > Messages: the status line's history, newest first.
void drawMessagesWindow(bool& open, const MessageLog& log, double now) {
    if (!open) return;
    ImGui::SetNextWindowSize(ImVec2(520, 260), ImGuiCond_Appearing);
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::Begin("Messages", &open, ImGuiWindowFlags_NoSavedSettings)) {
        const auto& h = log.history();
        if (h.empty()) ImGui::TextDisabled("(no messages yet)");
        for (auto it = h.rbegin(); it != h.rend(); ++it) {
            ImGui::TextDisabled("%6.0f s ago", now - it->postedAt);
            ImGui::SameLine();
            if (it->error)
                ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1), "%s", it->text.c_str());
            else
                ImGui::TextUnformatted(it->text.c_str());
        }
    }
    ImGui::End();
}

}  // namespace mgp::ui
