// EditorDocument: the admission verdicts the readout, the range tint and its legend show
// (eval/admission.h, edit/steady_verdict.h).
#include <algorithm>
#include <cstdlib>

#include "edit/editor_document.h"
#include "skeleton/pose_layout.h"

namespace mgp {

Balance EditorDocument::balanceOf(int frame, const Pose& edited) const {
    return judgeBalance(clip().skeleton, clip().frames[frame], edited, store_.contacts(), frame);
}

EditorDocument::DragOutcome EditorDocument::dragOutcomeAt(int frame, const Pose& pose) const {
    // Edits from regeneration, falloff or a latent drag have no hard targets left to miss.
    const bool lastDragged = lastDrag_.frame == frame && posesIdentical(lastDrag_.pose, pose);
    return {lastDragged, !lastDragged || lastDrag_.reached, lastDragged && lastDrag_.belowFloor};
}

std::optional<AdmissionVerdict> EditorDocument::currentPoseVerdict() const { return poseVerdictOn(model()); }

std::optional<AdmissionVerdict> EditorDocument::poseVerdictOn(const gp::ModelVersionPtr& v) const {
    if (!v || !hasClip()) return std::nullopt;
    if (drag_.active()) {
        const SolveReadout& r = drag_.readout();
        if (!r.valid || !r.learned) return std::nullopt;
        return admitPose(*v, drag_.pose(), movedEffectors(r.constraints), r.reached, anyBelowFloor(r.constraints),
                         r.sigma2, r.lik, balanceOf(frame_, drag_.pose()));
    }
    const auto it = store_.edits().find(frame_);
    if (it == store_.edits().end()) return std::nullopt;
    const EditRecord& e = it->second;
    if (e.x.size() != v->posterior->latentDim() || !e.x.allFinite()) return std::nullopt;
    if (v->model->clip.skeleton.jointCount() != clip().skeleton.jointCount()) return std::nullopt;
    const PoseLayout layout(clip().skeleton);
    const Eigen::VectorXd y = v->model->keptPose(layout.extract(e.pose));
    // Judged at the pose's point on this model (frameLatent): a taught pose's training row, or its x
    // fitted here when the edit was solved on another model (a retrain, a refinement).
    const Eigen::VectorXd& x = frameLatent(*v);
    const double lik = v->posterior->evaluate(x, y, nullptr, nullptr);
    Eigen::VectorXd mean;
    double sigma2 = 0.0;
    v->posterior->predict(x, mean, sigma2);
    const DragOutcome d = dragOutcomeAt(frame_, e.pose);
    return admitPose(*v, e.pose, e.moved, d.reached, d.belowFloor, sigma2, lik, balanceOf(frame_, e.pose));
}

std::optional<AdmissionVerdict> EditorDocument::judgedEditAt(int frame, const gp::ModelVersionPtr& v) const {
    const auto it = store_.edits().find(frame);
    if (!v || !hasClip() || it == store_.edits().end()) return std::nullopt;
    const EditRecord& e = it->second;
    // As currentPoseVerdict: an edit without a latent point on this model (plain IK) is not judged.
    if (e.x.size() != v->posterior->latentDim() || !e.x.allFinite()) return std::nullopt;
    if (v->model->clip.skeleton.jointCount() != clip().skeleton.jointCount()) return std::nullopt;
    std::vector<bool> contactsOn;
    for (const FootContact& c : store_.contacts().contacts) contactsOn.push_back(c.enabled);
    const DragOutcome d = dragOutcomeAt(frame, e.pose);
    JudgedEdit& cached = judgedEdits_[frame];
    if (cached.verdict && cached.model == v->model.get() && cached.version == v->number &&
        cached.clipFrames == clip().frames.data() && cached.contactsOn == contactsOn && cached.reached == d.reached &&
        cached.belowFloor == d.belowFloor && cached.moved == e.moved && posesIdentical(cached.pose, e.pose))
        return cached.verdict;
    cached = JudgedEdit{v->model.get(), v->number, clip().frames.data(), contactsOn,  e.pose,
                        e.moved,        d.reached, d.belowFloor,         std::nullopt};
    // σ² and L_IK are shown, not judged: the class needs no latent point.
    cached.verdict = admitPose(*v, e.pose, e.moved, d.reached, d.belowFloor, 0.0, 0.0, balanceOf(frame, e.pose));
    return cached.verdict;
}

std::optional<ShownVerdict> EditorDocument::shownPoseVerdict() const {
    const gp::ModelVersionPtr v = model();  // one version for the frame and its neighbours
    const std::optional<AdmissionVerdict> own = poseVerdictOn(v);
    if (!own) return std::nullopt;
    ShownVerdict out;
    out.own = *own;
    out.first = out.last = frame_;
    // A live solve is judged as it is. So is a pose that missed its target, went through the floor
    // or tipped off balance, and the pose the last drag left: steadying smooths the capture-range
    // judgement through a span, it never hides what a gesture did.
    if (drag_.active() || !steadiable(own->judgement)) return out;
    if (const auto it = store_.edits().find(frame_);
        it != store_.edits().end() && dragOutcomeAt(frame_, it->second.pose).lastDragged)
        return out;
    // The window: edited frames within two of this one, joined to it by edited frames.
    const auto judgedRun = [&](int step) {  // nearest first, stopping at the first captured frame
        std::vector<std::optional<AdmissionVerdict>> run;
        for (int f = frame_ + step; f >= 0 && f < frameCount() && std::abs(f - frame_) <= 2; f += step) {
            std::optional<AdmissionVerdict> j = judgedEditAt(f, v);
            if (!j) break;
            run.push_back(std::move(j));
        }
        return run;
    };
    const std::vector<std::optional<AdmissionVerdict>> before = judgedRun(-1), after = judgedRun(+1);
    out.first = frame_ - static_cast<int>(before.size());
    out.last = frame_ + static_cast<int>(after.size());
    std::vector<VerdictClass> classes;
    for (auto it = before.rbegin(); it != before.rend(); ++it) classes.push_back(verdictClass(**it));
    classes.push_back(verdictClass(*own));
    for (const auto& j : after) classes.push_back(verdictClass(*j));
    const VerdictClass shown = steadyClass(classes, before.size());
    if (shown == verdictClass(*own)) return out;
    // The nearest frame of the window with the shown class (the earlier one on a tie).
    for (std::size_t d = 1; d <= 2; ++d) {
        if (d <= before.size() && verdictClass(*before[d - 1]) == shown) {
            out.steadied = before[d - 1];
            out.steadiedFrame = frame_ - static_cast<int>(d);
            return out;
        }
        if (d <= after.size() && verdictClass(*after[d - 1]) == shown) {
            out.steadied = after[d - 1];
            out.steadiedFrame = frame_ + static_cast<int>(d);
            return out;
        }
    }
    return out;
}

}  // namespace mgp
