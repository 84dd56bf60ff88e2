#include "model_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace mgp::ui {

namespace {
const char* formatLabel(const Clip& c) {
    switch (c.format) {
        case ClipFormat::kAmc: return "ASF/AMC";
        case ClipFormat::kBvh: return "BVH";
        case ClipFormat::kSynthetic: return "synthetic";
    }
    return "?";
}

void progressRow(TrainingJob& job, const char* id) {
    const TrainingProgress p = job.progress();
    char overlay[96];
    if (p.etaSeconds >= 0)
        std::snprintf(overlay, sizeof overlay, "%s  iteration %d / %d   ETA %.0f s", p.kernel.c_str(), p.iteration,
                      p.total, p.etaSeconds);
    else
        std::snprintf(overlay, sizeof overlay, "%s  iteration %d / %d   (%.1f s)", p.kernel.c_str(), p.iteration,
                      p.total, p.elapsedSeconds);
    ImGui::ProgressBar(p.total > 0 ? float(p.iteration) / p.total : 0.0f, ImVec2(-70.0f, 0), overlay);
    ImGui::SameLine();
    ImGui::PushID(id);
    if (ImGui::Button("Cancel", ImVec2(-1, 0))) job.cancel();
    ImGui::PopID();
}
}  // namespace

void drawModelPanel(EditorState& s) {
    EditorDocument& doc = s.doc;
    if (doc.hasClip()) {
        const Clip& c = doc.clip();
        ImGui::Text("Clip  %s", c.name.c_str());
        ImGui::SameLine();
        ImGui::TextDisabled("%s, %d frames, %.0f fps", formatLabel(c), c.frameCount(), c.fps);
        if (doc.synthetic()) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1), "No mocap folder found: synthetic demo clip");
        if (c.format == ClipFormat::kBvh)
            ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1), "BVH is view-only: training on BVH is not supported yet");
    } else {
        ImGui::TextDisabled("No clip open (File > Open clip, Ctrl+O)");
    }
    ImGui::Separator();
    const gp::ModelVersionPtr v = doc.model();
    if (v) {
        const gp::GpModel& m = *v->model;
        ImGui::Text("Model %s", s.modelLabel.c_str());
        ImGui::TextDisabled("%s  N = %d  M = %zu  D = %d  version %d", m.kind == gp::KernelKind::kFas ? "FASGPLVM" : "SGPLVM",
                            m.N(), m.active.size(), m.D(), v->number);
        bool adaptive = doc.adaptiveEnabled();
        if (ImGui::Checkbox("Adaptive active set after each drag", &adaptive)) doc.setAdaptiveEnabled(adaptive);
        const int pending = doc.adaptivePending();
        const std::string st = doc.adaptiveStatus();
        if (pending > 0) ImGui::TextColored(ImVec4(0.4f, 0.8f, 1.0f, 1), "adaptive update running (%d queued)", pending);
        else if (!st.empty()) ImGui::TextDisabled("last %s", st.c_str());
    } else {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("No model: drags use plain IK until one is trained or opened");
        ImGui::PopStyleColor();
    }
    ImGui::Separator();

    // Training.
    if (s.training.running()) {
        progressRow(s.training, "main");
    } else {
        gp::TrainOptions& o = s.trainOptions;
        int kind = o.kind == gp::KernelKind::kFas ? 0 : 1;
        ImGui::RadioButton("FASGPLVM", &kind, 0);
        ImGui::SameLine();
        ImGui::RadioButton("SGPLVM", &kind, 1);
        o.kind = kind == 0 ? gp::KernelKind::kFas : gp::KernelKind::kSgplvm;
        ImGui::PushItemWidth(70);
        ImGui::InputInt("M", &o.activeSize, 0);
        ImGui::SameLine();
        ImGui::InputInt("T", &o.outerIterations, 0);
        ImGui::SameLine();
        ImGui::InputInt("S", &o.scgIterations, 0);
        ImGui::SameLine();
        ImGui::InputDouble("C", &o.tolerance, 0, 0, "%.3g");
        ImGui::PopItemWidth();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("M active set, T outer iterations, S SCG iterations per Step 6, C convergence tolerance");
        o.activeSize = std::clamp(o.activeSize, 3, 5000);
        o.outerIterations = std::clamp(o.outerIterations, 1, 1000);
        o.scgIterations = std::clamp(o.scgIterations, 1, 10000);
        if (!(o.tolerance > 0)) o.tolerance = 0.01;
        ImGui::BeginDisabled(!doc.trainable());
        if (ImGui::Button("Train  (Ctrl+T)")) s.requestTrain = true;
        ImGui::EndDisabled();
        if (!doc.trainable() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("Training needs an ASF/AMC clip (BVH is view-only for now)");
        ImGui::SameLine();
        if (ImGui::Button("Open model...")) s.requestOpenModel = true;
        ImGui::SameLine();
        ImGui::BeginDisabled(!v);
        if (ImGui::Button("Save model...")) s.requestSaveModel = true;
        ImGui::EndDisabled();
    }
    const std::string msg = s.training.message();
    if (!msg.empty() && !s.training.running() && msg.rfind("trained", 0) != 0)
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1), "%s", msg.c_str());
    ImGui::Separator();

    // Compare ghost.
    int mode = int(doc.compareMode());
    ImGui::Text("Compare ghost");
    ImGui::SameLine();
    bool changed = ImGui::RadioButton("off", &mode, 0);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("plain IK", &mode, 1);
    ImGui::SameLine();
    changed |= ImGui::RadioButton("2nd model", &mode, 2);
    if (changed) doc.setCompareMode(CompareMode(mode));
    if (doc.compareMode() == CompareMode::kSecondModel) {
        if (s.compareTraining.running()) {
            progressRow(s.compareTraining, "cmp");
        } else if (const auto cm = doc.compareModel()) {
            ImGui::TextDisabled("2nd model: %s, N = %d", cm->model->kind == gp::KernelKind::kFas ? "FASGPLVM" : "SGPLVM",
                                cm->model->N());
        } else {
            ImGui::BeginDisabled(!doc.trainable());
            if (ImGui::Button("Train 2nd model (other kernel)")) s.requestTrainCompare = true;
            ImGui::EndDisabled();
        }
    }
}

void drawIkReadout(EditorState& s) {
    const SolveReadout& r = s.doc.readout();
    if (!r.valid) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("Drag a hand, foot or head handle to pose. Residuals appear here.");
        ImGui::PopStyleColor();
        return;
    }
    ImGui::Text("%s%s", r.learned ? "Learned IK" : "Plain IK (no model)", s.doc.dragging() ? "  (live)" : "  (last drag)");
    ImGui::SameLine();
    if (r.reached) ImGui::TextColored(ImVec4(0.35f, 0.9f, 0.4f, 1), "reached");
    else ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.5f, 1), "not reached");
    if (ImGui::BeginTable("targets", 3, ImGuiTableFlags_SizingStretchSame | ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("target");
        ImGui::TableSetupColumn("residual cm");
        ImGui::TableSetupColumn("status");
        ImGui::TableHeadersRow();
        for (const IkConstraintResult& c : r.constraints) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%s%s", effectorName(c.effector), c.pin ? " (pin)" : "");
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", c.residualCm);
            ImGui::TableNextColumn();
            if (c.reached) ImGui::TextColored(ImVec4(0.35f, 0.9f, 0.4f, 1), "reached");
            else ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.5f, 1), "missed");
        }
        ImGui::EndTable();
    }
    if (r.learned) ImGui::Text("sigma^2(x) %.4g   L_IK %.4g   %d it", r.sigma2, r.lik, r.iterations);
    ImGui::TextDisabled("%s", r.diagnostic.c_str());
}

}  // namespace mgp::ui
