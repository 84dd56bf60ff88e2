#pragma once
// The document's half of a session file: which clip and models, the accepted edits, the undo
// history (frames only), the adaptive-update table, the frame, pins, compare ghost, adaptive
// switch and path edit. The editor adds its own half (camera,
// selection, labels) to the same SessionData. No GL: the core tests map documents both ways.
#include <optional>
#include <string>

#include "edit/editor_document.h"
#include "session/session_file.h"

namespace mgp {

// The document as a session: clip paths made absolute, the clip file's SHA-256 (so a changed
// clip is reported on open), the latest model version and the compare model.
SessionData sessionFromDocument(const EditorDocument& doc);

// A loaded session, checked against the clip it applies to, ready to replace a document.
struct CheckedSession {
    SessionData data;          // what is left to apply (the models moved out)
    std::optional<Clip> clip;  // none: the model carries the clip
    gp::ModelVersionPtr model, compareModel;
};

// Everything that can fail before the document changes fails here (ParseError naming `file`):
// the clip, and the path edit's keys and effector against it.
CheckedSession checkSession(SessionData data, const std::string& file);

// Replaces the document with the session, taking the clip, models and edits out of `session`
// (the editor's half stays in session.data). Throws ParseError naming `file` only when the path
// edit is refused after the document changed (the caller then treats it as half-loaded).
void applySession(EditorDocument& doc, CheckedSession& session, const std::string& file);

}  // namespace mgp
