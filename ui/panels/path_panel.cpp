#include "ui/panels/path_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "ui/widgets/widgets.h"

namespace mgp::ui {

namespace {

void reportError(EditorState& s, const std::string& err) {
    if (!err.empty()) s.setStatus(err, true);
}

// Moves key `key` to `frame` (0-based). The document keeps offsets only for frames that stay
// keys, so the moved key's offset is put back: retiming a key should not reset its shape.
void retimeKey(EditorState& s, int key, int frame) {
    const PathEdit path = *s.doc.paths().edit();
    std::vector<int> frames = path.keyFrames;
    frames[key] = frame;
    const std::string err = s.doc.paths().setKeyFrames(frames);
    if (!err.empty()) return reportError(s, err);
    s.doc.paths().setKeyOffset(key, path.keyOffsetsCm[key]);
}

void keyTable(EditorState& s) {
    EditorDocument& doc = s.doc;
    const int keys = static_cast<int>(doc.paths().edit()->keyFrames.size());
    // Every key's row, in the tab's own scrolling (no scroll area of its own inside it).
    const ImGuiTableFlags flags =
        ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    // Slim rows (1-pixel frame padding): the four default keys fit under the span report at 1280×800.
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(ImGui::GetStyle().FramePadding.x, 1.0f));
    if (!ImGui::BeginTable("keys", 5, flags)) {
        ImGui::PopStyleVar();
        return;
    }
    ImGui::TableSetupColumn("#");
    ImGui::TableSetupColumn("Frame", ImGuiTableColumnFlags_WidthFixed, 78.0f);
    ImGui::TableSetupColumn("Offset (cm)", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("");
    ImGui::TableSetupColumn("");
    ImGui::TableHeadersRow();
    int removeKey = -1;
    for (int k = 0; k < keys; ++k) {
        // Read per row: a row's edit may have changed the path.
        const PathEdit& path = *doc.paths().edit();
        if (k >= static_cast<int>(path.keyFrames.size())) break;
        ImGui::PushID(k);
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        char label[16];
        std::snprintf(label, sizeof label, "%d", k + 1);
        // A key the last regeneration missed is red, with by how much.
        const MotionEditJob::KeyResult* missed = nullptr;
        for (const MotionEditJob::KeyResult& r : doc.lastRegenerateKeys())
            if (r.frame == path.keyFrames[k] && !r.reached) missed = &r;
        if (missed) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.3f, 1.0f));
        if (ImGui::Selectable(label, s.selectedKey == k)) s.selectedKey = s.listPickedKey = k;
        if (missed) {
            ImGui::PopStyleColor();
            if (ImGui::IsItemHovered())
                tooltip("The last regeneration missed this key by %.1f cm (out of reach with the feet and pins held?)",
                        missed->errorCm);
        }
        ImGui::TableNextColumn();
        int frame = path.keyFrames[k] + 1;
        ImGui::SetNextItemWidth(-1);
        // Applied on Enter or the +/- buttons, so a half-typed number is not validated.
        if (ImGui::InputInt("##frame", &frame, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue) &&
            frame - 1 != path.keyFrames[k])
            retimeKey(s, k, frame - 1);
        ImGui::TableNextColumn();
        const Eigen::Vector3d& o = doc.paths().edit()->keyOffsetsCm[k];
        float v[3] = {float(o.x()), float(o.y()), float(o.z())};
        ImGui::SetNextItemWidth(-1);
        if (ImGui::DragFloat3("##offset", v, 0.1f, -500.0f, 500.0f, "%.1f"))
            reportError(s, doc.paths().setKeyOffset(k, Eigen::Vector3d(v[0], v[1], v[2])));
        if (ImGui::IsItemHovered())
            tooltip("x, y (up), z offset from the captured path, cm (drag or Ctrl+click to type)");
        ImGui::TableNextColumn();
        if (ImGui::SmallButton("Go")) {
            doc.setFrame(doc.paths().edit()->keyFrames[k]);
            s.selectedKey = s.listPickedKey = k;
        }
        if (ImGui::IsItemHovered()) tooltip("Go to this key's frame");
        ImGui::TableNextColumn();
        ImGui::BeginDisabled(keys <= 2);
        if (ImGui::SmallButton("x")) removeKey = k;
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            tooltip(keys <= 2 ? "A path needs at least two keys" : "Remove this key");
        ImGui::PopID();
    }
    ImGui::EndTable();
    ImGui::PopStyleVar();
    s.recordControl("key table");
    if (removeKey >= 0) {
        std::vector<int> frames = doc.paths().edit()->keyFrames;
        frames.erase(frames.begin() + removeKey);
        reportError(s, doc.paths().setKeyFrames(frames));
        if (s.selectedKey >= removeKey) s.selectedKey = s.selectedKey == removeKey ? -1 : s.selectedKey - 1;
    }
}

// The last regeneration's span report (core/motion/motion_quality.h): edited next to captured.
void regenerateReport(EditorState& s) {
    const EditorDocument& doc = s.doc;
    const auto& q = doc.lastRegenerateQuality();
    if (!q) return;
    // A section the animator can fold to bring the keys up (the tab scrolls as one); each row says
    // the edited value and, in brackets, the captured one.
    if (!ImGui::CollapsingHeader("Last regeneration: edited (captured)###lastregen", ImGuiTreeNodeFlags_DefaultOpen))
        return;
    if (!ImGui::BeginTable("regen_report", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) return;
    auto row = [](const char* label, const char* fmt, double edited, double captured, bool hasCaptured) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(label);
        ImGui::TableNextColumn();
        char value[64], reference[64] = "";
        std::snprintf(value, sizeof value, fmt, edited);
        if (hasCaptured) std::snprintf(reference, sizeof reference, fmt, captured);
        if (hasCaptured)
            ImGui::Text("%s  (%s)", value, reference);
        else
            ImGui::TextUnformatted(value);
    };
    row("2nd difference p95", "%.1f°", q->edited.p95Deg, q->captured.p95Deg, true);
    row("2nd difference max", "%.1f°", q->edited.maxDeg, q->captured.maxDeg, true);
    row("worst key error", "%.3f cm", q->worstKeyErrorCm, 0.0, false);
    row("worst pose change", "%.1f°", q->worstPoseChangeDeg, 0.0, false);
    for (const ContactTravel& c : q->contacts) {
        char label[64];
        std::snprintf(label, sizeof label, "%s contact %d-%d travel", effectorName(c.foot), c.first + 1, c.last + 1);
        row(label, "%.1f cm", c.editedCm, c.capturedCm, true);
    }
    ImGui::EndTable();
    s.recordControl("span report");
}

void regenerateRow(EditorState& s) {
    EditorDocument& doc = s.doc;
    if (doc.regenerating()) {
        const int done = doc.regenerateDone(), total = doc.regenerateTotal();
        char overlay[48];
        std::snprintf(overlay, sizeof overlay, "%d / %d frames", done, total);
        ImGui::ProgressBar(total > 0 ? float(done) / float(total) : 0.0f, ImVec2(-70.0f, 0), overlay);
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(-1, 0))) doc.cancelRegenerate();
        return;
    }
    ImGui::BeginDisabled(!doc.hasModel());
    const bool clickedRegenerate = ImGui::Button("Regenerate");
    s.recordControl("Regenerate");
    if (clickedRegenerate) {
        const std::string err = doc.startRegenerate();
        if (err.empty())
            s.setStatus("regenerating the edited span...");
        else
            reportError(s, err);
    }
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        tooltip(doc.hasModel() ? "Solve every frame between the first and last key as one problem: learned IK, "
                                 "smoothness, planted feet and pins held (one undo step)"
                               : "Regeneration needs a model: train one or open one first");
    regenerateReport(s);
}

}  // namespace

void drawPathPanel(EditorState& s) {
    EditorDocument& doc = s.doc;
    if (!doc.hasClip()) {
        ImGui::TextDisabled("No clip");
        return;
    }
    const auto& path = doc.paths().edit();
    if (!path || s.selectedKey >= static_cast<int>(path->keyFrames.size())) s.selectedKey = -1;
    if (!path || s.listPickedKey >= static_cast<int>(path->keyFrames.size())) s.listPickedKey = -1;

    // Effector: the path's while one is edited, else the viewport's selection (right foot by default).
    const Effector current = path ? path->effector : s.selected.value_or(Effector::kRFoot);
    ImGui::BeginDisabled(path.has_value());
    ImGui::SetNextItemWidth(80.0f);
    if (ImGui::BeginCombo("##effector", effectorName(current))) {
        for (int i = 0; i < kEffectorCount; ++i) {
            const auto e = static_cast<Effector>(i);
            if (!doc.hasEffector(e)) continue;
            if (ImGui::Selectable(effectorName(e), e == current)) s.selected = e;
        }
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (!path) {
        const bool clickedEditpath = ImGui::Button("Edit path");
        s.recordControl("Edit path");
        if (clickedEditpath) {
            const std::string err = doc.beginPathEdit(current);
            if (err.empty()) {
                s.selected = current;
                s.setStatus(std::string("editing the ") + effectorName(current) +
                            " path: drag its keys in the viewport");
            } else {
                reportError(s, err);
            }
        }
        if (ImGui::IsItemHovered()) tooltip("Four keys 14 frames apart around the current frame");
        return;
    }
    if (ImGui::Button("Done")) {
        doc.paths().end();
        s.selectedKey = s.hoveredKey = -1;
        return;
    }
    if (ImGui::IsItemHovered()) tooltip("Stop editing the path (regenerated frames stay)");
    ImGui::SameLine();
    if (ImGui::Button("Default keys")) reportError(s, doc.beginPathEdit(doc.paths().edit()->effector));
    if (ImGui::IsItemHovered()) tooltip("Four keys 14 frames apart around the current frame; offsets reset");
    sameLineIfFits("Regenerate");
    regenerateRow(s);
    if (!doc.paths().edit()) return;

    // The options on one line: the mode (Direct when unticked), then what the viewport shows beside
    // the path.
    bool displacement = doc.paths().edit()->mode == PathMode::kDisplacement;
    if (ImGui::Checkbox("displacement", &displacement))
        doc.paths().setMode(displacement ? PathMode::kDisplacement : PathMode::kDirect);
    if (ImGui::IsItemHovered())
        tooltip(
            "Ticked: a Hermite curve through the keys' offsets, added to the captured path (keeps the captured "
            "detail).\nUnticked, Direct (the paper's): a Hermite curve through the keys' positions (smooth, but "
            "loses the captured detail between keys).");
    ImGui::SameLine();
    ImGui::Checkbox("captured", &s.showCapturedPath);
    if (ImGui::IsItemHovered()) tooltip("Show the captured path (grey) beside the edited one (blue)");
    ImGui::SameLine();
    ImGui::Checkbox("before", &s.showBeforeGhost);
    if (ImGui::IsItemHovered()) tooltip("Show this frame's pose before the last undoable step, in violet");
    sameLineIfFits("Add key at current frame");
    if (ImGui::Button("Add key at current frame")) {
        std::vector<int> frames = doc.paths().edit()->keyFrames;
        if (std::find(frames.begin(), frames.end(), doc.frame()) != frames.end()) {
            s.setStatus("frame " + std::to_string(doc.frame() + 1) + " is already a key", true);
        } else {
            frames.insert(std::upper_bound(frames.begin(), frames.end(), doc.frame()), doc.frame());
            reportError(s, doc.paths().setKeyFrames(frames));
        }
    }

    keyTable(s);
}

}  // namespace mgp::ui
