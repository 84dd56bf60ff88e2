// EditorDocument's pins, held effectors and drags (editor_document.h, sections "pins",
// "held effectors" and "drag"): what a drag holds, the drag itself and its falloff, and the
// admission verdict of the current frame's pose.
#include "edit/editor_document.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "edit/held_effectors.h"
#include "ik/locality.h"
#include "motion/drag_falloff.h"
#include "motion/pose_layer.h"
#include "motion/support_polygon.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"

namespace mgp {

// ---- pins ----------------------------------------------------------------------------------

void EditorDocument::togglePin(Effector e) { setPinned(e, !pinned(e)); }

void EditorDocument::setPinned(Effector e, bool on) {
    if (!hasEffector(e)) return;
    if (pins_[static_cast<int>(e)] != on) ++revision_;
    pins_[static_cast<int>(e)] = on;
    if (on) pinPositions_[static_cast<int>(e)] = effectorPosition(e);
    if (drag_.active()) setDragPins();
}

std::vector<IkConstraint> EditorDocument::pinConstraints() const {
    std::vector<IkConstraint> out;
    for (int i = 0; i < kEffectorCount; ++i)
        if (pins_[i]) out.push_back({static_cast<Effector>(i), pinPositions_[i], true});
    return out;
}

std::vector<Effector> EditorDocument::heldEffectors() const {
    return hasClip() ? heldOn(store_, frame_) : std::vector<Effector>{};
}

bool EditorDocument::held(Effector e) const { return hasClip() && isHeld(store_, frame_, e); }

bool EditorDocument::anythingHeld() const { return anyHeld(store_); }

std::vector<IkConstraint> EditorDocument::holdConstraints() const {
    std::vector<IkConstraint> out = pinConstraints();
    for (Effector e : heldEffectors())
        if (hasEffector(e) && !pinned(e)) out.push_back({e, effectorPosition(e), true});  // a pin wins: held once
    return out;
}

std::string EditorDocument::releaseBlocked() {
    if (!hasClip()) return "no clip is open";
    if (drag_.active()) return "finish the drag before releasing";  // its record is written on release
    finishRunningFalloff();
    if (regenerating()) return "wait for the regeneration to finish before releasing";
    return "";
}

std::string EditorDocument::applyRelease(const FrameEdits& change, std::string label) {
    EditStep step;
    step.label = std::move(label);
    step.before = store_.current(change);
    step.after = change;
    applyFrames(step.after);
    pushStep(std::move(step));
    return "";
}

std::string EditorDocument::releaseHeld(Effector e) {
    if (std::string blocked = releaseBlocked(); !blocked.empty()) return blocked;
    const FrameEdits change = releaseRun(store_, frame_, e);
    if (change.empty()) return std::string(effectorName(e)) + " is not held on frame " + std::to_string(frame_ + 1);
    const int first = change.begin()->first + 1, last = change.rbegin()->first + 1;
    const std::string frames = first == last ? "frame " + std::to_string(first)
                                             : "frames " + std::to_string(first) + "-" + std::to_string(last);
    return applyRelease(change, std::string("release ") + effectorName(e) + " on " + frames);
}

std::string EditorDocument::releaseAllHeld() {
    if (std::string blocked = releaseBlocked(); !blocked.empty()) return blocked;
    const FrameEdits change = releaseEverywhere(store_);
    if (change.empty()) return "nothing is held";
    return applyRelease(change, "release everything held (" + std::to_string(change.size()) + " frames)");
}

std::vector<Effector> EditorDocument::pinnedEffectors() const {
    std::vector<Effector> out;
    for (int i = 0; i < kEffectorCount; ++i)
        if (pins_[i]) out.push_back(static_cast<Effector>(i));
    return out;
}

void EditorDocument::updatePinPositions() {
    if (!hasClip()) return;
    FkState fk;
    forwardKinematics(clip().skeleton, currentPose(), fk);
    for (int i = 0; i < kEffectorCount; ++i)
        if (pins_[i]) pinPositions_[i] = effectorCm(clip().skeleton, fk, static_cast<Effector>(i));
    if (drag_.active()) setDragPins();
}

// ---- drag ----------------------------------------------------------------------------------

std::vector<IkConstraint> EditorDocument::contactHolds() const {
    std::vector<IkConstraint> out;
    for (Effector f : {Effector::kLFoot, Effector::kRFoot})
        if (hasEffector(f) && !contactReleased(f) && inContact(f)) out.push_back({f, effectorPosition(f), true});
    return out;
}

bool EditorDocument::inContact(Effector foot) const {
    if (!hasClip() || (foot != Effector::kLFoot && foot != Effector::kRFoot)) return false;
    // A contact the user switched off on the timeline is not held by a drag either.
    return store_.contacts().at(foot, frame_) != nullptr;
}

void EditorDocument::setContactReleased(Effector foot, bool released) {
    if (contactReleased_[static_cast<int>(foot)] != released) ++revision_;
    contactReleased_[static_cast<int>(foot)] = released;
}

std::optional<BalanceRegion> EditorDocument::dragBalance(Effector dragged, const Pose& pose,
                                                         const std::vector<IkConstraint>& holds,
                                                         const std::vector<IkConstraint>& feet) const {
    // Balance where the captured frame stands balanced on the feet this drag pins (not the dragged one).
    std::vector<IkConstraint> pinned = holds;
    pinned.insert(pinned.end(), feet.begin(), feet.end());
    pinned.erase(std::remove_if(pinned.begin(), pinned.end(),
                                [dragged](const IkConstraint& c) { return c.effector == dragged; }),
                 pinned.end());
    FkState fk;
    forwardKinematics(clip().skeleton, pose, fk);
    return balanceRegion(clip().skeleton, clip().frames[frame_], fk, store_.contacts(), frame_, pinned);
}

void EditorDocument::setDragPins() {
    // The pins changed during a drag: so may the feet the support stands on.
    const std::vector<IkConstraint> holds = holdConstraints();
    drag_.setBalance(dragBalance(drag_.effector(), drag_.pose(), holds, contactHolds()));
    drag_.setPins(holds);
}

std::string EditorDocument::beginDrag(Effector e) {
    finishRunningFalloff();
    if (!hasClip()) return "no clip is open";
    if (filling()) return "a fill between keys is running: wait for it or cancel it";
    if (!hasEffector(e)) return std::string("this skeleton has no ") + effectorName(e);
    if (drag_.active()) endDrag();
    if (drag_.latentActive()) endLatentDrag();
    dragBefore_ = store_.editAt(frame_);
    const gp::ModelVersionPtr v = model();
    dragVersionBefore_ = v ? v->number : 0;
    const Pose start = currentPose();
    updatePinPositions();
    drag_.setCompare(compare_, compareModel_, frame_);
    drag_.setFloor(store_.contacts().floorCm);
    const std::vector<IkConstraint> holds = holdConstraints(), feet = contactHolds();
    drag_.setBalance(dragBalance(e, start, holds, feet));
    drag_.begin(clip().skeleton, e, start, v, v ? currentLatent() : Eigen::VectorXd(), holds, feet);
    return "";
}

void EditorDocument::dragTo(const Eigen::Vector3d& targetCm, int maxIterations) {
    drag_.dragTo(targetCm, maxIterations);
}

bool EditorDocument::refine(int maxIterations) { return drag_.refine(maxIterations); }

std::optional<DragRecord> EditorDocument::endDrag() {
    if (!drag_.active()) return std::nullopt;
    drag_.settle();
    DragRecord rec;
    rec.frame = frame_;
    rec.effector = drag_.effector();
    rec.before = dragBefore_;
    rec.after.pose = drag_.pose();
    rec.after.x = drag_.x();
    // The frame keeps what earlier gestures placed on it (held through this drag) and now this effector.
    rec.after.moved = withHeld(rec.before ? rec.before->moved : std::vector<Effector>{}, {rec.effector});
    rec.modelVersionBefore = dragVersionBefore_;
    drag_.finish();
    EditStep step;
    step.label = std::string("drag ") + effectorName(rec.effector) + " on frame " + std::to_string(frame_ + 1);
    step.before[frame_] = rec.before;
    step.after[frame_] = rec.after;
    const SolveReadout& r = drag_.readout();
    const gp::ModelVersionPtr& solvedOn = drag_.model();
    const bool learnedPose = models_.hasModel() && drag_.learned() && r.valid && r.learned &&
                             drag_.keptPose().allFinite() && drag_.x().allFinite();
    const AdmissionVerdict verdict =
        learnedPose ? admitPose(*solvedOn, rec.after.pose, rec.after.moved, r.reached, anyBelowFloor(r.constraints),
                                r.sigma2, r.lik, balanceOf(frame_, rec.after.pose))
                    : AdmissionVerdict{};
    if (learnedPose && models_.updating() && !verdict.admitted)
        models_.noteRefused(frame_, *solvedOn, verdict.reason);  // kept as an edit, not taught to the model
    lastDrag_.frame = frame_;
    lastDrag_.pose = rec.after.pose;
    lastDrag_.reached = r.valid ? r.reached : true;
    lastDrag_.belowFloor = r.valid && anyBelowFloor(r.constraints);
    if (learnedPose && verdict.admitted) {
        AdaptiveSample s;
        s.x = drag_.x();
        s.yKept = drag_.keptPose();
        s.clipFrame = frame_;
        if (const long seq = teach(std::move(s), rec.after.pose, rec.after.moved); seq > 0) step.samples.push_back(seq);
    }
    applyFrames(step.after);
    const std::string label = step.label;
    const long stepId = pushStep(std::move(step));
    startDragFalloff(rec, stepId, label);
    return rec;
}

void EditorDocument::setContactEnabled(std::size_t index, bool on) {
    if (store_.setContactEnabled(index, on)) ++revision_;
}

void EditorDocument::setBodyStiffness(double scale) {
    bodyStiffness_ = std::isfinite(scale) ? std::max(0.0, scale) : 1.0;
    drag_.setLocality(kDefaultLocality * bodyStiffness_);
}

void EditorDocument::startDragFalloff(const DragRecord& rec, long stepId, const std::string& stepLabel, bool wholePose,
                                      bool holdInPlace, const std::vector<Effector>& followLayer) {
    const gp::ModelVersionPtr v = model();
    if (falloffRadius_ < 1 || !v || regenerate_.running()) return;
    const Clip& mc = v->model->clip;
    if (mc.frameCount() != frameCount() || mc.skeleton.jointCount() != clip().skeleton.jointCount()) return;
    // The spread fades into the motion as it was before this drag, so what earlier gestures put on
    // the neighbouring frames stays there (the dragged frame as it was before the drag: the
    // displacement is measured from it).
    auto base = std::make_shared<EditBase>();
    base->frames.reserve(static_cast<std::size_t>(frameCount()));
    base->x.assign(static_cast<std::size_t>(frameCount()), Eigen::VectorXd());
    for (int t = 0; t < frameCount(); ++t) base->frames.push_back(store_.pose(t));
    for (const auto& [t, record] : store_.edits())
        if (record.x.size() == v->model->latentDim()) base->x[static_cast<std::size_t>(t)] = record.x;
    const auto dragged = static_cast<std::size_t>(rec.frame);
    base->frames[dragged] = rec.before ? rec.before->pose : clip().frames[dragged];
    base->x[dragged] = rec.before && rec.before->x.size() == v->model->latentDim() ? rec.before->x : Eigen::VectorXd();
    // A whole-pose change spreads at least over the falloff, wider where a hand or foot changes
    // so much that the falloff's blend would rush it, as measured on the motion it is layered over
    // (poseLayerRadiusOver).
    const int radius = wholePose ? poseLayerRadiusOver(clip().skeleton, base->frames, rec.frame, rec.after.pose,
                                                       falloffRadius_, clip().fps)
                                 : falloffRadius_;
    if (wholePose) {
        // Where the frame kept its pins, placements and planted feet, the neighbours keep them
        // where they were before the layer moved them.
        if (holdInPlace) {
            base->holdFrames = base->frames;
            base->followLayer = followLayer;
        }
        // A whole-pose change is layered over the span first (motion/pose_layer.h): the spread
        // re-solves from that blend, so every joint, not only the most-moved effector, joins in.
        addPoseLayer(clip().skeleton, base->frames, rec.frame, radius, base->frames[dragged], rec.after.pose);
        const int first = std::max(0, rec.frame - radius), last = std::min(frameCount() - 1, rec.frame + radius);
        for (int t = first; t <= last; ++t)
            base->x[static_cast<std::size_t>(t)] = Eigen::VectorXd();  // their poses moved
        base->frames[dragged] = rec.after.pose;
        base->x[dragged] = rec.after.x;
    }
    std::string problem;
    MotionEditJob job = dragFalloffJob(v, rec.effector, rec.frame, rec.after.pose, rec.after.x, radius,
                                       pinnedEffectors(), &problem, std::move(base));
    if (!problem.empty()) {  // the change stays a one-frame edit: say so
        falloffSkipped_ =
            stepLabel + ": kept on frame " + std::to_string(rec.frame + 1) + " alone, not spread (" + problem + ")";
        return;
    }
    job.contacts = std::make_shared<const ContactSet>(store_.contacts());
    // What earlier gestures placed on the spread's frames stays where the edited motion has it
    // (after a whole-pose change: where its layer moved it, so that the span stays smooth).
    // A whole-pose change keeps every placement on its records and holds it, the displaced
    // effector's too (its path follows the layer only off its holds).
    job.heldPlaced =
        heldRuns(store_, job.keyFrames.front(), job.keyFrames.back(), wholePose ? Effector::kCount : rec.effector);
    job.placesEffector = !wholePose;
    job.spanWeights.locality = kDefaultSpanLocality * bodyStiffness_;
    if (regenerate_.start(std::move(job)).empty()) {
        falloffStepId_ = stepId;
        spreadFalloff_ = falloffRadius_;
        spreadRadius_ = radius;
    }
}

void EditorDocument::cancelDrag() {
    if (drag_.active()) drag_.finish();  // a latent drag is ended by endLatentDrag only
}

bool EditorDocument::beginLatentDrag() {
    if (!hasModel() || !hasClip() || filling()) return false;
    if (drag_.active()) endDrag();
    latentBefore_ = store_.editAt(frame_);
    drag_.beginLatent(clip().skeleton, model(), currentLatent(), currentPose());
    return true;
}

void EditorDocument::latentDragTo(const Eigen::VectorXd& x) {
    if (!drag_.latentTo(x, clip().frames[frame_])) return;
    store_.set(frame_, EditRecord{drag_.pose(), x, {}});
    editLineage_[frame_] = lineage_;
}

void EditorDocument::endLatentDrag() {
    if (!drag_.latentActive()) return;
    drag_.finish();
    EditStep step;
    step.label = "latent pose on frame " + std::to_string(frame_ + 1);
    step.before[frame_] = latentBefore_;
    step.after[frame_] = store_.editAt(frame_);
    if (step.after[frame_] && drag_.latentPath().size() > 1) pushStep(std::move(step));
    updatePinPositions();
}

}  // namespace mgp
