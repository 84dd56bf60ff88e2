#include "ui/shell/editor_session.h"

#include <algorithm>

#include "session/session_mapping.h"

namespace mgp::ui {

namespace {

// An integer of a session's ui object, clamped to what the View menu offers; `fallback` if absent.
int clampedInt(const nlohmann::json& o, const char* key, int fallback, int lo, int hi) {
    const auto it = o.find(key);
    return it != o.end() && it->is_number_integer() ? std::clamp(it->get<int>(), lo, hi) : fallback;
}

// View > Onion skins and Motion trails as the session saved them (older sessions: off).
void applyOverlays(EditorState& s, const nlohmann::json& ui) {
    s.showOnionSkin = false;
    s.onionSkin = {};
    const auto onion = ui.find("onion_skin");
    if (onion != ui.end() && onion->is_object()) {
        const auto show = onion->find("show");
        s.showOnionSkin = show != onion->end() && show->is_boolean() && show->get<bool>();
        s.onionSkin.before = clampedInt(*onion, "before", s.onionSkin.before, 0, render::kMaxOnionGhosts);
        s.onionSkin.after = clampedInt(*onion, "after", s.onionSkin.after, 0, render::kMaxOnionGhosts);
        s.onionSkin.spacing = clampedInt(*onion, "spacing", s.onionSkin.spacing, 1, render::kMaxOnionSpacing);
    }
    for (bool& on : s.trails) on = false;
    s.trailHalfSpan = EditorState::kDefaultTrailHalfSpan;
    s.showCapturedTrails = true;
    const auto trails = ui.find("trails");
    if (trails == ui.end() || !trails->is_object()) return;
    const auto parts = trails->find("parts");
    if (parts != trails->end() && parts->is_array())
        for (const nlohmann::json& name : *parts) {
            render::TrailPart part{};
            if (name.is_string() && render::parseTrailPart(name.get<std::string>(), part))
                s.trails[static_cast<int>(part)] = true;
        }
    s.trailHalfSpan =
        clampedInt(*trails, "frames_each_side", EditorState::kDefaultTrailHalfSpan, 1, EditorState::kMaxTrailHalfSpan);
    const auto captured = trails->find("captured");
    s.showCapturedTrails = captured == trails->end() || !captured->is_boolean() || captured->get<bool>();
}

}  // namespace

SessionData editorSession(const EditorState& s) {
    SessionData d = sessionFromDocument(s.doc);
    d.selectedEffector = s.selected ? static_cast<int>(*s.selected) : -1;
    d.camera.yawDeg = s.camera.yawDeg;
    d.camera.pitchDeg = s.camera.pitchDeg;
    d.camera.distanceCm = s.camera.distanceCm;
    d.camera.fovYDeg = s.camera.fovYDeg;
    d.camera.targetCm = {s.camera.targetCm.x, s.camera.targetCm.y, s.camera.targetCm.z};
    d.camera.followCharacter = s.followCharacter;
    d.ui = {{"show_captured_path", s.showCapturedPath},
            {"show_before_ghost", s.showBeforeGhost},
            {"show_nearest_ghost", s.showNearestGhost},
            {"show_interpolation_ghost", s.showInterpolationGhost},
            {"show_balance", s.showBalance},
            {"clip_label", s.clipLabel},
            {"model_label", s.modelLabel}};
    nlohmann::json trails = nlohmann::json::array();
    for (int i = 0; i < render::kTrailPartCount; ++i)
        if (s.trails[i]) trails.push_back(render::trailPartName(static_cast<render::TrailPart>(i)));
    d.ui["onion_skin"] = {{"show", s.showOnionSkin},
                          {"before", s.onionSkin.before},
                          {"after", s.onionSkin.after},
                          {"spacing", s.onionSkin.spacing}};
    d.ui["trails"] = {{"parts", trails}, {"frames_each_side", s.trailHalfSpan}, {"captured", s.showCapturedTrails}};
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
    if (d.selectedEffector >= 0 && d.selectedEffector < kEffectorCount)
        s.selected = static_cast<Effector>(d.selectedEffector);
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
    s.showInterpolationGhost = flag("show_interpolation_ghost", false);
    s.showBalance = flag("show_balance", false);
    applyOverlays(s, d.ui);
    s.clipLabel = text("clip_label", s.doc.clip().name);
    s.modelLabel = s.doc.hasModel() ? text("model_label", "from session") : "";
}

}  // namespace mgp::ui
