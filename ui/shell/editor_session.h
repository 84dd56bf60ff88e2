#pragma once
// The editor's half of a session file: camera, selected effector, title labels and overlay
// switches, around the document's half (session/session_mapping.h).
#include "session/session_file.h"
#include "ui/shell/editor_state.h"

namespace mgp::ui {

// The whole session: the document's half plus the editor's.
SessionData editorSession(const EditorState& state);
// The editor's half, after the document took its own (applySession): the camera as saved (no
// reframing), playback stopped, labels and switches (missing ones get their defaults).
void applyEditorSession(EditorState& state, const SessionData& session);

}  // namespace mgp::ui
