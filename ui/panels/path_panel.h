#pragma once
// The Path panel (docs/maths.md §12): pick an effector, start or end a path edit, edit its keys
// (1-based frame, offset in cm from the captured path, go to, remove, add at the current frame,
// default keys), choose direct or displacement mode, show the captured path and the before ghost
// in the viewport, and regenerate the span in the background (progress and Cancel). The path
// itself is the document's (EditorDocument "path editing"); this panel holds no state of its own.
// Compact: meant for a ~380×180 px tab in the right column.
#include "ui/shell/editor_state.h"

namespace mgp::ui {

void drawPathPanel(EditorState& state);

}  // namespace mgp::ui
