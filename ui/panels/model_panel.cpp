#include "ui/panels/model_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <numeric>
#include <string>
#include <vector>

#include "skeleton/pose_layout.h"
#include "ui/widgets/widgets.h"

namespace mgp::ui {

namespace {
const char* formatLabel(const Clip& c) {
    switch (c.format) {
        case ClipFormat::kAmc: return "ASF/AMC";
        case ClipFormat::kBvh: return "BVH";
        case ClipFormat::kSynthetic: return "synthetic";
        case ClipFormat::kGltf: return "glTF";
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

// 4 significant digits, without the trailing "." that %#g leaves on e.g. "1991.".
std::string sig4(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%#.4g", v);
    std::string out = buf;
    if (!out.empty() && out.back() == '.') out.pop_back();
    return out;
}

// "lfemur rx": the pose DOF behind weight index k (keptColumns maps it into the pose vector).
std::string dofName(const gp::GpModel& m, const PoseLayout& layout, int k) {
    return layout.dofName(m.clip.skeleton, m.keptColumns[k]);
}

// The value index under the mouse for the plot item just drawn, or -1 (ImGui's own rule, so
// our tooltip names the sample ImGui highlights; a line plot has count − 1 segments).
int hoveredPlotIndex(int count, bool lines) {
    if (!ImGui::IsItemHovered() || count < (lines ? 2 : 1)) return -1;
    const float pad = ImGui::GetStyle().FramePadding.x;
    const float x0 = ImGui::GetItemRectMin().x + pad, x1 = ImGui::GetItemRectMax().x - pad;
    const float t = std::clamp((ImGui::GetIO().MousePos.x - x0) / std::max(x1 - x0, 1.0f), 0.0f, 0.9999f);
    return static_cast<int>(t * float(lines ? count - 1 : count));
}

// α, γ, η, β (docs/maths.md §3) and the noise they imply.
void drawParameters(const gp::GpModel& m) {
    const gp::Kernel k = m.kernel();
    if (ImGui::BeginTable("params", 3, ImGuiTableFlags_SizingFixedFit)) {
        auto row = [](const char* name, double value, const char* meaning) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(name);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(sig4(value).c_str());
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", meaning);
        };
        row("alpha", k.alpha(), "RBF variance");
        row("gamma", k.gamma(), "RBF inverse width");
        if (k.hasEta()) row("eta", k.eta(), "angular variance");
        row("beta", k.beta(), "noise precision");
        ImGui::EndTable();
    }
    // W scales each column, so DOF k's own noise is σ/w_k; Σ ln w = 0 makes σ the noise of a DOF
    // with the geometric-mean weight.
    const double sigma = 1.0 / std::sqrt(k.beta());
    ImGui::Text("noise sigma = 1/sqrt(beta) = %s deg", sig4(sigma).c_str());
    if (ImGui::IsItemHovered() && m.D() > 0)
        tooltip(
            "Noise std of a DOF with w = 1 (the geometric mean of W).\n"
            "DOF k has sigma / w_k: %s .. %s deg here.",
            sig4(sigma / m.w.maxCoeff()).c_str(), sig4(sigma / m.w.minCoeff()).c_str());
}

// min/max of w, the 3 most and least weighted DOFs by name, and w per DOF as bars.
void drawWeights(const gp::GpModel& m) {
    const int D = m.D();
    if (D == 0) return;
    std::vector<int> order(D);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return m.w[a] > m.w[b]; });
    const PoseLayout layout(m.clip.skeleton);
    ImGui::Text("w  min %s  max %s", sig4(m.w.minCoeff()).c_str(), sig4(m.w.maxCoeff()).c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("(%d DOFs)", D);
    if (ImGui::BeginTable("wextremes", 2, ImGuiTableFlags_SizingStretchSame)) {
        ImGui::TableSetupColumn("most weighted");
        ImGui::TableSetupColumn("least weighted");
        ImGui::TableHeadersRow();
        for (int i = 0; i < std::min(3, D); ++i) {
            ImGui::TableNextRow();
            for (const int k : {order[i], order[D - 1 - i]}) {
                ImGui::TableNextColumn();
                ImGui::Text("%-11s %s", dofName(m, layout, k).c_str(), sig4(m.w[k]).c_str());
            }
        }
        ImGui::EndTable();
    }
    std::vector<float> wf(D);
    for (int k = 0; k < D; ++k) wf[k] = float(m.w[k]);
    // PlotEx treats only 0 (not −1) as "default width": give the full width explicitly.
    ImGui::PlotHistogram("##w", wf.data(), D, 0, nullptr, 0.0f, float(m.w.maxCoeff()),
                         ImVec2(ImGui::GetContentRegionAvail().x, 44));
    const int h = hoveredPlotIndex(D, false);
    if (h >= 0) tooltip("%s  w = %s", dofName(m, layout, h).c_str(), sig4(m.w[h]).c_str());
    ImGui::TextDisabled("w per DOF, pose order (hover for names)");
}

// L_GP per outer iteration (GpModel::objectiveHistory); log10 when all positive and > 2 decades.
void drawConvergence(const gp::GpModel& m) {
    const std::vector<double>& hist = m.objectiveHistory;
    if (hist.empty()) {
        ImGui::TextDisabled("no history (model file from an older version)");
        return;
    }
    const auto [lo, hi] = std::minmax_element(hist.begin(), hist.end());
    const bool logScale = *lo > 0.0 && *hi / *lo > 100.0;
    const int n = static_cast<int>(hist.size());
    std::vector<float> v(n);
    for (int i = 0; i < n; ++i) v[i] = float(logScale ? std::log10(hist[i]) : hist[i]);
    ImGui::Text("L_GP %s -> %s", sig4(hist.front()).c_str(), sig4(hist.back()).c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("%s%s", m.converged ? "converged" : "not converged", logScale ? ", log" : "");
    // y axis: the max and min values in a column left of the plot (inside they hide the line).
    const std::string top = sig4(*hi), bottom = sig4(*lo);
    const float axisW = std::max(ImGui::CalcTextSize(top.c_str()).x, ImGui::CalcTextSize(bottom.c_str()).x) + 6;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::SetCursorPosX(ImGui::GetCursorPosX() + axisW);
    ImGui::PlotLines("##conv", v.data(), n, 0, nullptr, FLT_MAX, FLT_MAX, ImVec2(ImGui::GetContentRegionAvail().x, 64));
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImU32 grey = ImGui::GetColorU32(ImGuiCol_TextDisabled);
    dl->AddText(ImVec2(origin.x, ImGui::GetItemRectMin().y), grey, top.c_str());
    dl->AddText(ImVec2(origin.x, ImGui::GetItemRectMax().y - ImGui::GetTextLineHeight()), grey, bottom.c_str());
    const int h = hoveredPlotIndex(n, true);
    if (h == 0)
        tooltip("L_init = %.6g (before training)", hist[0]);
    else if (h > 0)
        tooltip("iteration %d: L_GP = %.6g", h, hist[h]);
    ImGui::TextDisabled("x: iteration 0 (L_init) .. %d, L_GP after Step 6", n - 1);
}

// "HH:MM:SS" local time.
std::string timeOfDay(std::chrono::system_clock::time_point when) {
    const std::time_t t = std::chrono::system_clock::to_time_t(when);
    std::tm tm{};
    localtime_r(&t, &tm);
    char buf[16];
    std::strftime(buf, sizeof buf, "%H:%M:%S", &tm);
    return buf;
}

// The adaptive updates of this session, newest first.
void drawAdaptiveHistory(const std::vector<AdaptiveHistoryEntry>& history) {
    if (history.empty()) {
        ImGui::TextDisabled("none yet: drag a handle with a model loaded");
        return;
    }
    struct Column {
        const char* name;
        const char* tip;
    };
    static const Column kColumns[] = {
        {"time", "when the update finished (local time)"},
        {"frame", "the edited frame (as the timeline shows it)"},
        {"s", "how long the update took, seconds"},
        {"+act", "points that entered the active set"},
        {"pose", "whether the edited pose itself entered the active set"},
        {"version", "model version before -> after"},
        {"result", "accepted or rejected (hover a row for the diagnostic)"},
    };
    constexpr int kCols = static_cast<int>(sizeof kColumns / sizeof kColumns[0]);
    const float rowH = ImGui::GetTextLineHeightWithSpacing();
    const float height = rowH * float(std::min<std::size_t>(history.size(), 6) + 1) + 4;
    const ImGuiTableFlags flags = ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_BordersInnerV;
    if (!ImGui::BeginTable("adaptive", kCols, flags, ImVec2(0, height))) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    for (const Column& c : kColumns) ImGui::TableSetupColumn(c.name);
    ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
    for (int c = 0; c < kCols; ++c) {
        ImGui::TableSetColumnIndex(c);
        ImGui::TableHeader(kColumns[c].name);
        if (ImGui::IsItemHovered()) tooltip("%s", kColumns[c].tip);
    }
    for (auto it = history.rbegin(); it != history.rend(); ++it) {
        const AdaptiveHistoryEntry& e = *it;
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(timeOfDay(e.when).c_str());
        ImGui::TableNextColumn();
        ImGui::Text("%d", e.frame + 1);
        ImGui::TableNextColumn();
        ImGui::Text("%.2f", e.seconds);
        ImGui::TableNextColumn();
        ImGui::Text("+%d", e.activeChanged);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(e.newPointActive ? "in" : "-");
        ImGui::TableNextColumn();
        ImGui::Text("%d->%d", e.versionBefore, e.versionAfter);
        ImGui::TableNextColumn();
        if (e.accepted)
            ImGui::TextColored(ImVec4(0.35f, 0.9f, 0.4f, 1), "ok");
        else
            ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.5f, 1), "rejected");
        if (ImGui::IsItemHovered())
            tooltip("%s\nN = %d, M = %d after the update\nL_GP %.6g -> %.6g", e.diagnostic.c_str(), e.rowsAfter,
                    e.activeSize, e.objectiveBefore, e.objectiveAfter);
    }
    ImGui::EndTable();
}

}  // namespace

void drawTrainOptions(gp::TrainOptions& o) {
    int kind = o.kind == gp::KernelKind::kFas ? 0 : 1;
    ImGui::RadioButton("FASGPLVM", &kind, 0);
    ImGui::SameLine();
    ImGui::RadioButton("SGPLVM", &kind, 1);
    o.kind = kind == 0 ? gp::KernelKind::kFas : gp::KernelKind::kSgplvm;
    // Four fields and their one-letter labels share the row, however narrow the panel.
    const float labelW =
        ImGui::CalcTextSize("M").x + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::GetStyle().ItemSpacing.x;
    ImGui::PushItemWidth(std::clamp(ImGui::GetContentRegionAvail().x / 4.0f - labelW, 30.0f, 70.0f));
    ImGui::InputInt("M", &o.activeSize, 0);
    ImGui::SameLine();
    ImGui::InputInt("T", &o.outerIterations, 0);
    ImGui::SameLine();
    ImGui::InputInt("S", &o.scgIterations, 0);
    ImGui::SameLine();
    ImGui::InputDouble("C", &o.tolerance, 0, 0, "%.3g");
    ImGui::PopItemWidth();
    if (ImGui::IsItemHovered())
        tooltip(
            "M active set, T outer iterations, S SCG iterations per Step 6, C convergence tolerance\n"
            "%s temporal prior, lambda %.3g at this T (100 up to T = 10, 30 from T = 100)",
            gp::latentPriorName(o.prior), o.resolvedPriorWeight());
    o.activeSize = std::clamp(o.activeSize, 3, 5000);
    o.outerIterations = std::clamp(o.outerIterations, 1, 1000);
    o.scgIterations = std::clamp(o.scgIterations, 1, 10000);
    if (!(o.tolerance > 0)) o.tolerance = 0.01;
}

void drawModelPanel(EditorState& s) {
    EditorDocument& doc = s.doc;
    if (doc.hasClip()) {
        const Clip& c = doc.clip();
        ImGui::Text("Clip  %s", c.name.c_str());
        ImGui::SameLine();
        ImGui::TextDisabled("%s, %d frames, %.0f fps", formatLabel(c), c.frameCount(), c.fps);
        if (doc.synthetic())
            ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1), "No mocap folder found: synthetic demo clip");
    } else {
        ImGui::TextDisabled("No clip open (File > Open, Ctrl+O)");
    }
    ImGui::Separator();
    const gp::ModelVersionPtr v = doc.model();
    // Training and the model file first: reachable without scrolling, whatever the model shows.
    if (s.training.running()) {
        progressRow(s.training, "main");
        if (doc.refining()) {
            const TrainingProgress p = s.training.progress();
            ImGui::TextWrapped(
                "refining... (model %d, from iteration %d, L_GP %s): drag now; %d accepted pose(s) wait for "
                "the final model",
                p.published, p.publishedIteration, sig4(p.publishedObjective).c_str(), doc.waitingPoses());
        }
    } else {
        // These fields set the next training, not the loaded model's (its own are the tooltip of
        // its "N = ..." line below).
        ImGui::TextDisabled("train with");
        ImGui::SameLine();
        drawTrainOptions(s.trainOptions);
        ImGui::BeginDisabled(!doc.trainable());
        if (ImGui::Button("Train")) s.request("train");
        s.recordControl("Train");
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            tooltip(doc.trainable() ? "Train a model on this clip (Ctrl+T)" : "Open a clip first (File > Open)");
        // Short labels: the three stay on one line down to an 800-pixel window (the panel says Model).
        sameLineIfFits("Open...");
        if (ImGui::Button("Open...")) s.request("open-model");
        s.recordControl("Open model");
        if (ImGui::IsItemHovered()) tooltip("Open a model file (.model); its clip comes with it");
        sameLineIfFits("Save...");
        ImGui::BeginDisabled(!v);
        if (ImGui::Button("Save...")) s.request("save-model");
        s.recordControl("Save model");
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            tooltip(v ? "Save the model to a file" : "No model to save yet");
    }
    const std::string msg = s.training.message();
    if (!msg.empty() && !s.training.running() && msg.rfind("trained", 0) != 0)
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1), "%s", msg.c_str());
    ImGui::Separator();
    if (v) {
        const gp::GpModel& m = *v->model;
        ImGui::Text("Model %s", s.modelLabel.c_str());
        ImGui::SameLine();
        ImGui::TextDisabled("%s, version %d", m.kind == gp::KernelKind::kFas ? "FASGPLVM" : "SGPLVM", v->number);
        ImGui::TextDisabled("N = %d  active M = %zu  D = %d  latent d = %d", m.N(), m.active.size(), m.D(),
                            m.latentDim());
        if (ImGui::IsItemHovered())
            tooltip("this model was trained with M = %d, T = %d (%d run); the fields above set the next training",
                    m.settings.activeSize, m.settings.outerIterations, m.iterations);
        if (m.clipCount() > 1) {  // the training clips; the open one (the model's primary clip) first
            std::vector<int> rows(static_cast<std::size_t>(m.clipCount()), 0);
            for (int i = 0; i < m.N(); ++i) ++rows[static_cast<std::size_t>(m.rowClip(i))];
            for (int c = 0; c < m.clipCount(); ++c)
                ImGui::TextDisabled("  %s %s: %d of %d frames%s", c == 0 ? "*" : " ", m.clipName(c).c_str(),
                                    rows[static_cast<std::size_t>(c)], m.clipAt(c).frameCount(),
                                    c == 0 ? " (open)" : "");
        }
        bool adaptive = doc.models().adaptiveEnabled();
        if (ImGui::Checkbox("Adaptive active set after each drag", &adaptive)) doc.setAdaptiveEnabled(adaptive);
        const int pending = doc.models().pending();
        const std::string st = doc.models().status();
        const std::vector<AdaptiveHistoryEntry> history = doc.models().history();
        // The last update's outcome only while it describes the model shown (undo and redo
        // install other versions).
        const bool describesThis = !history.empty() && history.back().versionAfter == v->number;
        if (pending > 0)
            ImGui::TextColored(ImVec4(0.4f, 0.8f, 1.0f, 1), "adaptive update running (%d queued)", pending);
        else if (!st.empty() && describesThis) {
            // Wrapped, not cut: a refusal's reason is what the animator needs to read.
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
            textWrappedAtSpaces("last " + st);
            ImGui::PopStyleColor();
        } else if (!history.empty())
            ImGui::TextDisabled("version %d (restored by undo/redo)", v->number);
    } else {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("No model: drags use plain IK until one is trained or opened");
        ImGui::PopStyleColor();
    }
}

namespace {
// The compare ghost: off, plain IK, or a second model of the other kernel (trained here).
void drawCompareGhost(EditorState& s) {
    EditorDocument& doc = s.doc;
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
            ImGui::TextDisabled("2nd model: %s, N = %d",
                                cm->model->kind == gp::KernelKind::kFas ? "FASGPLVM" : "SGPLVM", cm->model->N());
            // Training it again replaces it: the editor asks first when no session file holds it.
            ImGui::SameLine();
            ImGui::BeginDisabled(!doc.trainable());
            if (ImGui::SmallButton("Retrain")) s.request("train-compare");
            s.recordControl("retrain compare model");
            ImGui::EndDisabled();
        } else {
            ImGui::BeginDisabled(!doc.trainable());
            if (ImGui::Button("Train 2nd model (other kernel)")) s.request("train-compare");
            ImGui::EndDisabled();
        }
    }
}
}  // namespace

void drawModelDetails(EditorState& s) {
    drawCompareGhost(s);
    ImGui::Separator();
    const gp::ModelVersionPtr v = s.doc.model();
    if (!v) {
        ImGui::TextDisabled("No model yet: train one or open one (Model panel)");
        return;
    }
    const gp::GpModel& m = *v->model;
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen)) drawParameters(m);
    if (ImGui::CollapsingHeader("Scale weights W")) drawWeights(m);
    if (ImGui::CollapsingHeader("Training convergence")) drawConvergence(m);
    const std::vector<AdaptiveHistoryEntry> history = s.doc.models().history();
    char label[64];
    std::snprintf(label, sizeof label, "Adaptive updates (%zu)###adaptive", history.size());
    if (ImGui::CollapsingHeader(label)) drawAdaptiveHistory(history);
}

namespace {
// What the current frame holds because the animator placed it there (edit/held_effectors.h), each
// with a button that releases it, and one that releases everything held in the clip.
void drawHeldEffectors(EditorState& s) {
    const std::vector<Effector> held = s.doc.heldEffectors();
    if (held.empty()) {
        ImGui::TextDisabled("held here: nothing");
        if (ImGui::IsItemHovered())
            tooltip(
                "A hand, foot or head you drag stays where you put it: later drags and their falloff hold it "
                "until you release it (Alt+click its handle).");
        return;
    }
    ImGui::TextUnformatted("held here:");
    for (Effector e : held) {
        ImGui::SameLine();
        const std::string label = std::string(effectorName(e)) + " x##release";
        if (ImGui::SmallButton(label.c_str())) s.request("release", {effectorName(e)});
        if (ImGui::IsItemHovered())
            tooltip(
                "%s was placed by an edit and is held by later drags and falloffs here. Click to release it "
                "on this frame and the neighbouring frames that hold it (one undo step).",
                effectorName(e));
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("release all")) s.request("release-all");
    if (ImGui::IsItemHovered()) tooltip("Release every held hand, foot and head on every frame (one undo step).");
}
}  // namespace

void drawIkReadout(EditorState& s) {
    // Drag falloff radius (core/motion/drag_falloff.h): 0 edits the dragged frame only.
    // The two sliders share a line (the readout below stays in view at 1280×800).
    const float sliderW = std::max(50.0f, ImGui::GetContentRegionAvail().x * 0.5f -
                                              ImGui::CalcTextSize("stiffness ").x - ImGui::GetStyle().ItemSpacing.x);
    int radius = s.doc.dragFalloff();
    ImGui::SetNextItemWidth(sliderW);
    if (ImGui::SliderInt("falloff", &radius, 0, 120, "%d frames")) s.doc.setDragFalloff(radius);
    s.recordControl("drag falloff");
    if (ImGui::IsItemHovered())
        tooltip(
            "A drag on frame t also changes t-r..t+r, fading to zero, re-solved with planted feet and pins on release "
            "(one undo step). 0: this frame only. A quarter second is 30 frames at 120 fps.");
    // Locality (core/ik/locality.h) as a multiple of the default.
    float stiffness = static_cast<float>(s.doc.bodyStiffness());
    ImGui::SameLine();
    ImGui::SetNextItemWidth(sliderW);
    if (ImGui::SliderFloat("stiffness", &stiffness, 0.0f, 3.0f, "%.2f")) s.doc.setBodyStiffness(stiffness);
    s.recordControl("body stiffness");
    if (ImGui::IsItemHovered())
        tooltip(
            "How much the rest of the body keeps its pose while you drag a hand, foot or head: 1 moves "
            "the dragged limb, and the body only as much as the target needs; 0 lets the learned model "
            "move the whole body. Drags, their falloff and Regenerate use it.");
    drawHeldEffectors(s);
    const SolveReadout& r = s.doc.readout();
    if (!r.valid) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("Drag a hand, foot or head handle to pose. Residuals appear here.");
        ImGui::PopStyleColor();
        return;
    }
    ImGui::Text("%s%s", r.learned ? "Learned IK" : "Plain IK (no model)",
                s.doc.dragging() ? "  (live)" : "  (last drag)");
    ImGui::SameLine();
    if (r.reached)
        ImGui::TextColored(ImVec4(0.35f, 0.9f, 0.4f, 1), "reached");
    else
        ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.5f, 1), "not reached");
    // One row per target: the effector, its residual and whether it was reached (no header row: the
    // unit says what the number is).
    if (ImGui::BeginTable("targets", 3, ImGuiTableFlags_SizingStretchSame | ImGuiTableFlags_RowBg)) {
        for (const IkConstraintResult& c : r.constraints) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            // An exact constraint is the user's pin, a placement an earlier edit holds, or a planted foot.
            const char* kind = !c.pin                     ? ""
                               : s.doc.pinned(c.effector) ? " (pin)"
                               : s.doc.held(c.effector)   ? " (held)"
                                                          : " (planted)";
            ImGui::Text("%s%s", effectorName(c.effector), kind);
            ImGui::TableNextColumn();
            ImGui::Text("%.3f cm", c.residualCm);
            ImGui::TableNextColumn();
            if (c.reached)
                ImGui::TextColored(ImVec4(0.35f, 0.9f, 0.4f, 1), "reached");
            else
                ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.5f, 1), c.belowFloor ? "on the floor" : "missed");
        }
        ImGui::EndTable();
    }
    // The current frame's pose judged as the viewport legend judges it (one verdict, one sigma^2 per frame); the
    // numbers behind it in the tooltip.
    if (const std::optional<ShownVerdict> shown = r.learned ? s.doc.shownPoseVerdict() : std::nullopt) {
        const AdmissionVerdict* v = &shown->own;
        // One line: the verdict and what it means for the model (the numbers in the tooltip).
        ImGui::TextWrapped("pose: %s; %s", judgementWords(shown->shown().judgement),
                           v->admitted ? "the model learns it" : "an edit only");
        bool hovered = ImGui::IsItemHovered();
        if (shown->steadied) {
            ImGui::TextDisabled("like frame %d; alone: %s", shown->steadiedFrame + 1, judgementWords(v->judgement));
            hovered = hovered || ImGui::IsItemHovered();
        }
        if (hovered)
            tooltip("%s\nsolve: %d iterations", admissionDetails(*v, *s.doc.model()->model).c_str(), r.iterations);
    } else if (r.learned) {
        ImGui::Text("%d iterations", r.iterations);
    }
    if (r.comShiftCm) {
        ImGui::Text("centre of mass moved %.1f cm", *r.comShiftCm);
        if (ImGui::IsItemHovered())
            tooltip(
                "How far the whole body's centre of mass moved sideways (over the ground) since the drag "
                "began, from de Leva's segment masses. A few cm on a standing frame can tip the character.");
    }
    if (r.nearest.row >= 0) {
        ImGui::Checkbox("##nearestghost", &s.showNearestGhost);
        s.recordControl("nearest ghost");
        if (ImGui::IsItemHovered()) tooltip("Show that captured pose as a green ghost at the current root");
        ImGui::SameLine();
        ImGui::Text("nearest: %s frame %d, %.1f deg RMS", r.nearestClip.c_str(), r.nearest.row + 1, r.nearest.rmsDeg);
        if (ImGui::IsItemHovered())
            tooltip(
                "The captured frame of the model's clip closest to this pose in joint angles "
                "(RMS over the non-root DOFs): where the pose is in the data. Tick to see it as a ghost.");
    }
    ImGui::TextDisabled("%s", r.diagnostic.c_str());
    s.recordControl("readout end");
}

}  // namespace mgp::ui
