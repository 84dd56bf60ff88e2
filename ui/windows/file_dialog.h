#pragma once
// A small file dialog built with ImGui (a modal popup): folders first, then files with one of
// the wanted extensions; a path field accepts a typed path. Mode Open needs an existing file,
// Save accepts a new name.
#include <optional>
#include <string>
#include <vector>

namespace mgp::ui {

class FileDialog {
public:
    enum class Mode { kOpen, kSave };
    // Opens the dialog (shown from the next draw()) with `defaultName` in the name field, which
    // has the keyboard focus (typing replaces the name).
    void open(std::string title, Mode mode, std::vector<std::string> extensions, const std::string& startDir,
              const std::string& defaultName = "");
    // Draws it if open; returns the chosen path once.
    std::optional<std::string> draw();
    bool isOpen() const { return open_; }
    const std::string& title() const { return title_; }
    const char* typedPath() const { return path_; }
    const std::string& folder() const { return dir_; }  // the folder listed

private:
    void list(const std::string& dir);
    std::string title_;
    Mode mode_ = Mode::kOpen;
    std::vector<std::string> extensions_;
    std::string dir_;
    std::vector<std::string> dirs_, files_;
    char path_[1024] = {};
    bool open_ = false, justOpened_ = false, focusName_ = false;
    std::string error_;
};

}  // namespace mgp::ui
