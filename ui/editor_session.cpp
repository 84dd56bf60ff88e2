#include "editor_session.h"

#include "edit/session_mapping.h"

namespace mgp::ui {

SessionData editorSession(const EditorState& s) {
    SessionData d = sessionFromDocument(s.doc);
    d.selectedEffector = s.selected ? static_cast<int>(*s.selected) : -1;
    d.camera.yawDeg = s.camera.yawDeg;
    d.camera.pitchDeg = s.camera.pitchDeg;
    d.camera.distanceCm = s.camera.distanceCm;
    d.camera.fovYDeg = s.camera.fovYDeg;
    d.camera.targetCm = {s.camera.targetCm.x, s.camera.targetCm.y, s.camera.targetCm.z};
    d.camera.followCharacter = s.followCharacter;
    d.ui = {{"show_captured_path", s.showCapturedPath}, {"show_before_ghost", s.showBeforeGhost},
            {"show_nearest_ghost", s.showNearestGhost}, {"show_balance", s.showBalance}, {"clip_label", s.clipLabel},
            {"model_label", s.modelLabel}};
    return d;
}

void applyEditorSession(EditorState& s, const SessionData& d) {
    auto text = [&](const char* key, const std::string& fallback) {
        const auto it = d.ui.find(key);
        return it != d.ui.end() && it->is_string() ? it->get<std::string>() : fallback;
    };
    auto flag = [&](const char* key, bool fallback) {
        const auto it = d.ui.find(key);
        return it != d.ui.end() && it->is_boolean() ? it->get<bool>() : fallback;
    };
    s.selected.reset();
    if (d.selectedEffector >= 0 && d.selectedEffector < kEffectorCount) s.selected = static_cast<Effector>(d.selectedEffector);
    s.camera.yawDeg = float(d.camera.yawDeg);
    s.camera.pitchDeg = float(d.camera.pitchDeg);
    s.camera.distanceCm = float(d.camera.distanceCm);
    s.camera.fovYDeg = float(d.camera.fovYDeg);
    s.camera.targetCm = glm::vec3(d.camera.targetCm.x(), d.camera.targetCm.y(), d.camera.targetCm.z());
    s.followCharacter = d.camera.followCharacter;
    s.cameraNeedsFraming = false;
    s.cameraRestored = true;
    s.playing = false;
    s.showCapturedPath = flag("show_captured_path", true);
    s.showBeforeGhost = flag("show_before_ghost", false);
    s.showNearestGhost = flag("show_nearest_ghost", false);
    s.showBalance = flag("show_balance", false);
    s.clipLabel = text("clip_label", s.doc.clip().name);
    s.modelLabel = s.doc.hasModel() ? text("model_label", "from session") : "";
}

}  // namespace mgp::ui
