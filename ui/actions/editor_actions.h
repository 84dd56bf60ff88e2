#pragma once
// The editor's actions, in one table: each has a name (the script verb `action NAME ARGS`), its
// arguments, a shortcut, an enabled predicate and run(args). The menus, the keyboard shortcuts,
// the F1 help window, the script player and docs/guide.md's action table all read this table, so
// a new action is added once. Scripts run an action whatever its predicate says, so they get
// the action's own error ("nothing to undo") instead of silence. Actions ask the editor shell
// for what they do through EditorCommands (editor_commands.h).
#include <functional>
#include <string>
#include <vector>

#include "ui/actions/shortcuts.h"

namespace mgp::ui {

class EditorCommands;

using ActionArgs = std::vector<std::string>;  // the arguments after the action's name

struct KeyChord {
    int key = 0;              // a GLFW key code (ASCII for letters)
    unsigned mods = kNoMods;  // exactly these modifiers (shortcuts.h)
    bool repeat = false;      // also fires on key repeat
};

struct EditorAction {
    std::string name;              // the script verb
    std::string args;              // argument synopsis ("PATH", "[ITERS]"), "" none
    std::string shortcut;          // as menus and F1 show it ("Ctrl+Shift+Z"), "" none
    std::vector<KeyChord> chords;  // the keys that run it (may be fewer than `shortcut` names)
    std::string summary;           // what it does, one line (F1 and docs/guide.md)
    // Whether the menu item is enabled and the shortcut fires; null = always.
    std::function<bool(const EditorCommands&)> enabled;
    // The shortcut also fires when disabled, so the user hears why ("nothing to undo").
    bool keyWhenDisabled = false;
    std::function<std::string(EditorCommands&, const ActionArgs&)> run;  // "" or the error
};

class ActionTable {
public:
    static const ActionTable& editor();  // the editor's actions, in menu order

    const std::vector<EditorAction>& actions() const { return actions_; }
    const EditorAction* find(const std::string& name) const;  // null if unknown
    bool enabled(const std::string& name, const EditorCommands& app) const;

    // args[0] is the name: "" or the error (an unknown name included).
    std::string run(EditorCommands& app, const std::vector<std::string>& args) const;
    // Runs the actions whose chord went down this frame (between NewFrame and Render); errors go
    // to the status line.
    void runShortcuts(EditorCommands& app) const;
    // A menu item for the action: `label` and its shortcut, greyed out unless enabled (and
    // `alsoEnabled`); runs it with `args` when clicked, errors to the status line.
    void menuItem(EditorCommands& app, const std::string& name, const std::string& label, const ActionArgs& args = {},
                  bool selected = false, bool alsoEnabled = true) const;
    // docs/guide.md's table of script actions (markdown), generated from the table.
    std::string markdownTable() const;

private:
    std::vector<EditorAction> actions_;
};

}  // namespace mgp::ui
