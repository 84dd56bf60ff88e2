#include "ui/windows/file_dialog.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <utility>

namespace fs = std::filesystem;

namespace mgp::ui {

void FileDialog::open(std::string title, Mode mode, std::vector<std::string> extensions, const std::string& startDir,
                      const std::string& defaultName) {
    title_ = std::move(title);
    mode_ = mode;
    extensions_ = std::move(extensions);
    std::error_code ec;
    const std::string start =
        !startDir.empty() && fs::is_directory(startDir, ec) ? startDir : fs::current_path(ec).string();
    list(start);
    std::snprintf(path_, sizeof path_, "%s", defaultName.c_str());
    error_.clear();
    open_ = true;
    justOpened_ = true;
    focusName_ = true;
}

void FileDialog::list(const std::string& dir) {
    std::error_code ec;
    dir_ = fs::weakly_canonical(dir, ec).string();
    if (ec) dir_ = dir;
    dirs_.clear();
    files_.clear();
    for (fs::directory_iterator it(dir_, fs::directory_options::skip_permission_denied, ec), end; !ec && it != end;
         it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code e2;
        if (it->is_directory(e2)) {
            dirs_.push_back(name);
        } else {
            std::string ext = it->path().extension().string();
            std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
            if (extensions_.empty() || std::find(extensions_.begin(), extensions_.end(), ext) != extensions_.end())
                files_.push_back(name);
        }
    }
    std::sort(dirs_.begin(), dirs_.end());
    std::sort(files_.begin(), files_.end());
}

std::optional<std::string> FileDialog::draw() {
    if (!open_) return std::nullopt;
    if (justOpened_) {
        ImGui::OpenPopup(title_.c_str());
        justOpened_ = false;
    }
    std::optional<std::string> chosen;
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x * 0.5f, vp->WorkPos.y + vp->WorkSize.y * 0.5f),
                            ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(620, 460), ImGuiCond_Appearing);
    bool keep = true;
    if (ImGui::BeginPopupModal(title_.c_str(), &keep)) {
        ImGui::TextDisabled("%s", dir_.c_str());
        if (ImGui::Button("Up")) list(fs::path(dir_).parent_path().string());
        ImGui::BeginChild("entries", ImVec2(0, -60), true);
        std::string go;
        for (const std::string& d : dirs_)
            if (ImGui::Selectable((d + "/").c_str(), false, ImGuiSelectableFlags_AllowDoubleClick) &&
                ImGui::IsMouseDoubleClicked(0))
                go = d;
        for (const std::string& f : files_) {
            const bool sel = std::strcmp(path_, (fs::path(dir_) / f).string().c_str()) == 0;
            if (ImGui::Selectable(f.c_str(), sel, ImGuiSelectableFlags_AllowDoubleClick)) {
                std::snprintf(path_, sizeof path_, "%s", (fs::path(dir_) / f).string().c_str());
                if (ImGui::IsMouseDoubleClicked(0)) chosen = path_;
            }
        }
        if (dirs_.empty() && files_.empty()) ImGui::TextDisabled("(no matching files)");
        ImGui::EndChild();
        if (!go.empty()) list((fs::path(dir_) / go).string());
        ImGui::SetNextItemWidth(-170);
        if (std::exchange(focusName_, false)) ImGui::SetKeyboardFocusHere();
        const bool enter = ImGui::InputText("##path", path_, sizeof path_,
                                            ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
        ImGui::SameLine();
        const bool ok = ImGui::Button(mode_ == Mode::kOpen ? "Open" : "Save", ImVec2(75, 0));
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(75, 0))) {
            open_ = false;
            ImGui::CloseCurrentPopup();
        }
        if ((ok || enter) && path_[0]) {
            std::error_code ec;
            fs::path p(path_);
            if (p.is_relative()) p = fs::path(dir_) / p;
            if (fs::is_directory(p, ec))
                list(p.string());
            else if (mode_ == Mode::kOpen && !fs::exists(p, ec))
                error_ = "no such file: " + p.string();
            else
                chosen = p.string();
        }
        if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
            open_ = false;
            ImGui::CloseCurrentPopup();
        }
        if (!error_.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", error_.c_str());
        if (chosen) {
            open_ = false;
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    } else {
        open_ = false;  // closed from outside (another modal replaced it): never stay "open"
    }
    if (!keep) open_ = false;
    return chosen;
}

}  // namespace mgp::ui
