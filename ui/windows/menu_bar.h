#pragma once
// The editor's main menu bar. Every item runs an action of the action table (editor_actions.h),
// which gives it its shortcut text and enabled state; only the view switches (checkboxes bound
// to EditorState) and the recent-files list are drawn here directly.
namespace mgp::ui {

class EditorCommands;

// Between NewFrame and Render. `showMessages` is View > Messages.
// Training and adaptive updates show at the right end of the bar; `latentBusyText` ("latent
// map...", "" or null when idle) comes after them.
void drawMenuBar(EditorCommands& app, bool& showMessages, const char* latentBusyText);

}  // namespace mgp::ui
