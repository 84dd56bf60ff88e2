#include "ui/shell/editor_prompts.h"

#include <imgui.h>

#include <ctime>
#include <filesystem>

#include "ui/input/input_state.h"

namespace mgp::ui {

void EditorPrompts::guard(bool unsaved, std::function<void()> action, std::string what) {
    if (!unsaved) {
        action();
        return;
    }
    pending_ = std::move(action);
    pendingWhat_ = std::move(what);
}

void EditorPrompts::draw(bool dialogOpen, const Hooks& hooks) {
    modelClip(dialogOpen);
    unsavedChanges(dialogOpen, hooks);
    restoreAutosave(dialogOpen, hooks);
}

void EditorPrompts::askModelClip(std::vector<std::string> lines, std::function<void()> openIt) {
    modelClipLines_ = std::move(lines);
    openModelClip_ = std::move(openIt);
}

void EditorPrompts::modelClip(bool dialogOpen) {
    const char* title = "Model trained on another clip";
    if (openModelClip_ && !dialogOpen && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) ImGui::OpenPopup(title);
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    askingModelClip_ = ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    if (!askingModelClip_) return;
    for (const std::string& line : modelClipLines_) ImGui::TextUnformatted(line.c_str());
    // Keys answer only once the question has been on screen: the Enter that confirmed the file
    // dialog is still down on the frame the question appears.
    const bool keys = !ImGui::IsWindowAppearing();
    if (ImGui::Button("Open with its clip", ImVec2(160, 0)) || (keys && ImGui::IsKeyPressed(key::kEnter, false))) {
        std::function<void()> openIt = std::exchange(openModelClip_, nullptr);
        ImGui::CloseCurrentPopup();
        openIt();  // may ask about unsaved changes next
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(110, 0)) || (keys && ImGui::IsKeyPressed(key::kEscape, false))) {
        openModelClip_ = nullptr;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void EditorPrompts::unsavedChanges(bool dialogOpen, const Hooks& hooks) {
    const bool otherPopup = dialogOpen || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);
    if (pending_ && !otherPopup) ImGui::OpenPopup("Unsaved changes");
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    asking_ = ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    if (!asking_) return;
    const std::string file = std::filesystem::path(hooks.sessionPath).filename().string();
    ImGui::Text("This session has changes that are not saved%s.",
                hooks.sessionPath.empty() ? "" : (" to " + file).c_str());
    ImGui::Text("Save them before %s?", pendingWhat_.c_str());
    const bool save = ImGui::Button("Save", ImVec2(110, 0));
    if (hooks.recordControl) hooks.recordControl("unsaved: Save");
    if (save) {
        std::function<void()> action = std::exchange(pending_, nullptr);
        if (hooks.sessionPath.empty()) {
            hooks.askForSessionFile();  // the action runs once the file is saved
            afterSave_ = std::move(action);
        } else if (hooks.save(hooks.sessionPath)) {
            action();
        }
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    const bool discard = ImGui::Button("Don't save", ImVec2(110, 0));
    if (hooks.recordControl) hooks.recordControl("unsaved: Don't save");
    if (discard) {
        std::exchange(pending_, nullptr)();
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel", ImVec2(110, 0)) || ImGui::IsKeyPressed(key::kEscape, false)) {
        pending_ = nullptr;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void EditorPrompts::restoreAutosave(bool dialogOpen, const Hooks& hooks) {
    if (!restoreOffer_.empty() && !dialogOpen && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId))
        ImGui::OpenPopup("Restore autosave");
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal("Restore autosave", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    if (restoreOffer_.empty()) {  // answered elsewhere (a script, File menu)
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    const AutosaveCandidate c = restoreOffer_.front();
    ImGui::Text("MotionGP did not quit normally last time.");
    ImGui::Text("An autosave of its work was left at\n%s", c.path.c_str());
    const std::time_t when = static_cast<std::time_t>(c.mtimeSeconds);
    char stamp[64];
    std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M:%S", std::localtime(&when));
    ImGui::TextDisabled("written %s by editor process %d", stamp, c.pid);
    if (ImGui::Button("Restore", ImVec2(110, 0))) {
        const std::string path = c.path;
        ImGui::CloseCurrentPopup();
        hooks.restore(path);
        restoreOffer_.clear();
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard", ImVec2(110, 0))) {
        discardAutosave(c.path);
        restoreOffer_.erase(restoreOffer_.begin());
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Not now", ImVec2(110, 0))) {
        restoreOffer_.clear();  // kept on disk: offered again next start
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace mgp::ui
