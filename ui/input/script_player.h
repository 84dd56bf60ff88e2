#pragma once
// Plays a GuiScript (gui_script.h) into an InputState and the editor's actions
// (editor_actions.h), frame by frame. Arguments are parsed strictly: "move 12abc 5" is an
// error naming the script line, never a mouse at x = 12.
#include <string>
#include <vector>

#include "ui/input/gui_script.h"
#include "ui/input/input_state.h"

namespace mgp::ui {

class EditorCommands;

class ScriptPlayer {
public:
    explicit ScriptPlayer(GuiScript script);
    // Applies the events of `frame` (before EditorApp::frame). Screenshot actions are returned in
    // `screenshots` and must be written after the frame is drawn.
    void apply(int frame, InputState& input, EditorCommands& app, std::vector<std::string>& screenshots);
    int lastFrame() const { return script_.lastFrame(); }
    const std::vector<std::string>& errors() const { return errors_; }

private:
    // One event: "" or the error.
    std::string play(const ScriptEvent& e, InputState& input, EditorCommands& app,
                     std::vector<std::string>& screenshots);

    GuiScript script_;
    std::size_t next_ = 0;
    std::vector<std::string> errors_;
};

}  // namespace mgp::ui
