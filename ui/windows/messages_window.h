#pragma once
// View > Messages: the status line's history (message_log.h), newest first, errors in red.
#include "ui/shell/message_log.h"

namespace mgp::ui {

// Draws the window while `open` (its close box clears it); `now` is the UI time in seconds.
void drawMessagesWindow(bool& open, const MessageLog& log, double now);

}  // namespace mgp::ui
