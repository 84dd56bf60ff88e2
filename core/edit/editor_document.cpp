#include "edit/editor_document.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "edit/held_effectors.h"
#include "edit/latent_refit.h"
#include "edit/regeneration_step.h"
#include "ik/learned_ik.h"
#include "ik/locality.h"
#include "motion/drag_falloff.h"
#include "motion/pose_layer.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"

namespace mgp {

namespace {
bool samePose(const Pose& a, const Pose& b) { return a.rootCm == b.rootCm && a.anglesDeg == b.anglesDeg; }

// The latent point of the model's training row that holds pose y (kept columns) for clip frame
// `frame` of the primary (open) clip, if an update added one; the last such row when there are several.
std::optional<Eigen::VectorXd> taughtLatent(const gp::GpModel& m, int frame, const Eigen::VectorXd& y) {
    for (Eigen::Index r = m.X.rows() - 1; r >= 0; --r) {
        if (m.trainingFrames[static_cast<std::size_t>(r)] != frame || m.rowClip(static_cast<int>(r)) != 0) continue;
        if (m.Y.cols() == y.size() && (m.Y.row(r).transpose() - y).cwiseAbs().maxCoeff() <= 1e-9)
            return Eigen::VectorXd(m.X.row(r).transpose());
    }
    return std::nullopt;
}
// The hand, foot or head that a whole-pose change (paste, mirror, rotate) moves furthest: the
// spread displaces its path, and the prior and the smoothness carry the rest of the body along.
Effector mostMovedEffector(const Skeleton& skeleton, const Pose& from, const Pose& to) {
    Effector best = Effector::kRHand;
    double farthest = -1.0;
    for (int k = 0; k < kEffectorCount; ++k) {
        const auto e = static_cast<Effector>(k);
        if (!skeleton.hasEffector(e)) continue;
        const double moved = (effectorCm(skeleton, to, e) - effectorCm(skeleton, from, e)).norm();
        if (moved > farthest) {
            best = e;
            farthest = moved;
        }
    }
    return best;
}
}  // namespace

EditorDocument::EditorDocument() = default;
EditorDocument::~EditorDocument() {
    // The jobs call back into members declared after them: stop them first.
    regenerate_.cancel();
    regenerate_.join();
    models_.clear();
}

void EditorDocument::stopRegeneration() {
    regenerate_.cancel();
    regenerate_.join();
    regenerate_.take();
    fill_.cancel();
    fill_.waitIdle();
    fill_.take();
    fill_.takeMessage();  // "cancelled" of a fill nobody asked to stop
}

void EditorDocument::setClip(Clip clip, bool synthetic) {
    drag_.finish();
    latentBefore_.reset();
    stopRegeneration();
    history_.clear();
    paths_.reset();
    keys_.clear();
    ++revision_;
    store_.reset(std::move(clip), synthetic);
    editLineage_.clear();
    falloffStepLabel_.clear();
    lastRegenerateQuality_.reset();
    lastRegenerateKeys_.clear();
    contactReleased_.fill(false);
    falloffRadius_ = defaultFalloffRadius(store_.clip().fps);
    frame_ = 0;
    pins_.fill(false);
    clearModel();
    drag_.clear();
    compareModel_.reset();
}

void EditorDocument::setFrame(int frame) {
    if (!hasClip()) return;
    if (drag_.active()) endDrag();
    if (drag_.latentActive()) endLatentDrag();
    frame_ = std::clamp(frame, 0, frameCount() - 1);
    updatePinPositions();
}

const Pose& EditorDocument::currentPose() const { return drag_.active() ? drag_.pose() : store_.pose(frame_); }

void EditorDocument::clearEdit(int frame) {
    if (!store_.isEdited(frame)) return;
    EditStep step;
    step.label = "reset frame " + std::to_string(frame + 1) + " to the captured pose";
    step.before[frame] = store_.editAt(frame);
    step.after[frame] = std::nullopt;
    applyFrames(step.after);
    pushStep(std::move(step));
}

std::string EditorDocument::pastePose(const Pose& pose) {
    if (!hasClip()) return "no clip to paste onto";
    Pose pasted = pose;
    pasted.rootCm = currentPose().rootCm;
    return setCurrentPose(pasted, "paste pose on frame " + std::to_string(frame_ + 1), PoseHolds::kResolve);
}

std::vector<IkConstraint> EditorDocument::keptInPlace() const {
    std::vector<IkConstraint> out = holdConstraints();
    for (const IkConstraint& c : contactHolds())
        if (std::none_of(out.begin(), out.end(), [&](const IkConstraint& o) { return o.effector == c.effector; }))
            out.push_back(c);
    return out;
}

std::string EditorDocument::setCurrentPose(const Pose& given, const std::string& stepLabel, PoseHolds holds,
                                           const std::vector<Effector>& followLayer) {
    if (!hasClip()) return "no clip to edit";
    finishRunningFalloff();  // a previous pose change's spread lands first, as before a drag
    if (regenerating()) return "wait for the regeneration to finish before editing a pose";
    if (given.anglesDeg.size() != currentPose().anglesDeg.size())
        return "expected a pose of this clip's skeleton, found one with " + std::to_string(given.anglesDeg.size()) +
               " bones (copied from another clip?)";
    cancelDrag();
    Pose pose = given;
    Eigen::VectorXd x;  // the pose's point on the model, so that the legend, the map and the spread see it
    bool keptHolds = holds == PoseHolds::kSolved && !keptInPlace().empty();
    const gp::ModelVersionPtr v = model();
    if (v && v->model->clip.skeleton.jointCount() == clip().skeleton.jointCount()) {
        const PoseLayout layout(clip().skeleton);
        x = refitLatent(*v, frame_, v->model->keptPose(layout.extract(given)));
        const std::vector<IkConstraint> kept =
            holds == PoseHolds::kResolve ? keptInPlace() : std::vector<IkConstraint>{};
        if (!kept.empty() && x.allFinite()) {
            // The new pose as the animator gave it, re-solved under the prior so that every pin,
            // placed effector and planted foot of this frame stays where it was (as the spread keeps
            // them on the neighbours). If they cannot all be met, the pose is kept as given.
            ConstrainedIkSolver solver(v);
            ConstrainedIkRequest request;
            request.start = given;
            request.startX = x;
            request.constraints = kept;
            request.maxIterations = 300;
            request.locality = kDefaultLocality * bodyStiffness_;
            request.floorCm = store_.contacts().floorCm;
            const ConstrainedIkResult r = solver.solve(request);
            if (r.reached && allFinite(r.pose)) {
                pose = r.pose;
                keptHolds = true;
                x = r.x.allFinite() ? r.x : refitLatent(*v, frame_, v->model->keptPose(layout.extract(pose)));
            }
        }
    }
    DragRecord change;  // spread over the neighbours as a drag's release is (startDragFalloff)
    change.frame = frame_;
    change.before = store_.editAt(frame_);
    change.effector = mostMovedEffector(clip().skeleton, store_.pose(frame_), pose);
    change.after.pose = pose;
    // What was placed here stays held (held where the new pose puts it). The pose change itself
    // places nothing: its spread marks no effector placed (MotionEditJob::placesEffector).
    if (change.before) change.after.moved = change.before->moved;
    if (x.size() > 0 && x.allFinite()) change.after.x = x;
    EditStep step;
    step.label = stepLabel;
    step.before[frame_] = change.before;
    step.after[frame_] = change.after;
    applyFrames(step.after);
    pushStep(std::move(step));
    startDragFalloff(change, stepLabel, true, keptHolds, followLayer);
    return "";
}

void EditorDocument::restoreEdits(std::map<int, EditRecord> edits) {
    drag_.finish();
    latentBefore_.reset();
    editLineage_.clear();
    for (const auto& [frame, edit] : edits) editLineage_[frame] = lineage_;  // saved with the model they belong to
    store_.replaceAll(std::move(edits));
    history_.clear();
    updatePinPositions();
    ++revision_;
}

void EditorDocument::restoreHistory(std::vector<EditStep> undo, std::vector<EditStep> redo) {
    history_.restore(std::move(undo), std::move(redo));
    ++revision_;
}

Eigen::Vector3d EditorDocument::effectorPosition(Effector e) const {
    if (!hasEffector(e)) return Eigen::Vector3d::Zero();
    return effectorCm(clip().skeleton, currentPose(), e);
}

// ---- model ---------------------------------------------------------------------------------

void EditorDocument::setModel(gp::ModelVersionPtr version, bool adoptClip) {
    refining_ = false;
    deferred_.clear();
    installModel(std::move(version), adoptClip);
}

void EditorDocument::installRefinement(gp::ModelVersionPtr version, bool adoptClip) {
    std::vector<DeferredPose> waiting = std::move(deferred_);
    installModel(std::move(version), adoptClip);
    refining_ = hasModel();
    if (adoptClip) waiting.clear();  // a new clip: the poses belonged to the old one
    deferred_ = std::move(waiting);
}

int EditorDocument::finishRefinement(gp::ModelVersionPtr version, bool adoptClip) {
    const std::vector<DeferredPose> waiting = adoptClip ? std::vector<DeferredPose>{} : latestPerFrame(deferred_);
    setModel(std::move(version), adoptClip);
    const gp::ModelVersionPtr v = model();
    if (!v) return 0;
    int posted = 0;
    for (const DeferredPose& p : waiting) {
        if (p.frame >= frameCount() || !samePose(store_.pose(p.frame), p.edited)) continue;  // undone or edited since
        const std::optional<DeferredTeaching> t = teachingOnModel(*v, p);
        if (!t) continue;
        if (!t->verdict.admitted) {
            models_.noteRefused(p.frame, *v, t->verdict.reason);
            continue;
        }
        if (models_.post(t->sample) > 0) ++posted;
    }
    return posted;
}

long EditorDocument::teach(AdaptiveSample sample, const Pose& edited, std::vector<Effector> moved) {
    if (!refining_) return models_.post(std::move(sample));
    if (models_.updating())
        deferred_.push_back(
            {sample.clipFrame, std::move(sample.yKept), edited, std::move(moved), balanceOf(sample.clipFrame, edited)});
    return 0;
}

void EditorDocument::installModel(gp::ModelVersionPtr version, bool adoptClip) {
    if (!version) {
        clearModel();
        return;
    }
    if (adoptClip) {
        setClip(version->model->clip, false);
        store_.mutableClip().name = version->model->clip.name;
    }
    drag_.finish();
    stopRegeneration();                       // a running regeneration solves on the old model: its result is dropped
    if (!adoptClip) history_.forgetModels();  // the steps' versions belong to the old model
    ++lineage_;
    installWorker(std::move(version));
    ++revision_;
}

void EditorDocument::installWorker(gp::ModelVersionPtr version) {
    models_.install(std::move(version));
    drag_.forgetModel();
    cacheFrame_ = -1;
}

void EditorDocument::clearModel() {
    refining_ = false;
    deferred_.clear();
    drag_.finish();
    latentBefore_.reset();
    regenerate_.cancel();  // its result would belong to the old model
    history_.forgetModels();
    models_.clear();
    drag_.forgetModel();
    cacheFrame_ = -1;
}

void EditorDocument::setAdaptiveEnabled(bool on) {
    if (models_.setAdaptiveEnabled(on)) ++revision_;
}

void EditorDocument::setCompareMode(CompareMode mode) {
    if (compare_ != mode) ++revision_;
    compare_ = mode;
    drag_.setCompare(compare_, compareModel_, frame_);
}

Eigen::VectorXd EditorDocument::currentLatent() {
    const gp::ModelVersionPtr v = model();
    if (!v) return {};
    if ((drag_.active() || drag_.latentActive()) && drag_.x().size() > 0) return drag_.x();
    return frameLatent(*v);
}

const Eigen::VectorXd& EditorDocument::frameLatent(const gp::ModelVersion& v) const {
    const auto it = store_.edits().find(frame_);
    const EditRecord* edit = it != store_.edits().end() ? &it->second : nullptr;
    const auto lineage = editLineage_.find(frame_);
    const bool current = edit && lineage != editLineage_.end() && lineage->second == lineage_;
    if (cacheFrame_ == frame_ && cacheVersion_ == v.number && cacheModel_ == v.model.get() &&
        cacheEdited_ == (edit != nullptr) && cacheCurrent_ == current && (!edit || samePose(cachePose_, edit->pose)))
        return cacheX_;
    cacheX_ = latentStartForFrame(v, frame_);
    if (edit && v.model->clip.skeleton.jointCount() == clip().skeleton.jointCount()) {
        // A taught pose is a training row with its own point; an edit solved on this model's
        // lineage keeps its x; one solved on an earlier model (a retrain, a refinement) is fitted here.
        const Eigen::VectorXd y = v.model->keptPose(PoseLayout(clip().skeleton).extract(edit->pose));
        const std::optional<Eigen::VectorXd> taught = taughtLatent(*v.model, frame_, y);
        const bool own = current && edit->x.size() == v.model->latentDim();
        const Eigen::VectorXd x = taught ? *taught : own ? edit->x : refitLatent(v, frame_, y, &edit->x);
        if (x.allFinite()) cacheX_ = x;
        cachePose_ = edit->pose;
    }
    cacheFrame_ = frame_;
    cacheVersion_ = v.number;
    cacheModel_ = v.model.get();
    cacheEdited_ = edit != nullptr;
    cacheCurrent_ = current;
    return cacheX_;
}

// ---- pins ----------------------------------------------------------------------------------

void EditorDocument::togglePin(Effector e) { setPinned(e, !pinned(e)); }

void EditorDocument::setPinned(Effector e, bool on) {
    if (!hasEffector(e)) return;
    if (pins_[static_cast<int>(e)] != on) ++revision_;
    pins_[static_cast<int>(e)] = on;
    if (on) pinPositions_[static_cast<int>(e)] = effectorPosition(e);
    if (drag_.active()) drag_.setPins(holdConstraints());
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
    if (drag_.active()) drag_.setPins(holdConstraints());
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
    drag_.begin(clip().skeleton, e, start, v, v ? currentLatent() : Eigen::VectorXd(), holdConstraints(),
                contactHolds());
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
    pushStep(std::move(step));
    startDragFalloff(rec, label);
    return rec;
}

void EditorDocument::setContactEnabled(std::size_t index, bool on) {
    if (store_.setContactEnabled(index, on)) ++revision_;
}

void EditorDocument::setBodyStiffness(double scale) {
    bodyStiffness_ = std::isfinite(scale) ? std::max(0.0, scale) : 1.0;
    drag_.setLocality(kDefaultLocality * bodyStiffness_);
}

void EditorDocument::startDragFalloff(const DragRecord& rec, const std::string& stepLabel, bool wholePose,
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
    if (wholePose) {
        // Where the frame kept its pins, placements and planted feet, the neighbours keep them
        // where they were before the layer moved them.
        if (holdInPlace) {
            base->holdFrames = base->frames;
            base->followLayer = followLayer;
        }
        // A whole-pose change is layered over the span first (motion/pose_layer.h): the spread
        // re-solves from that blend, so every joint, not only the most-moved effector, joins in.
        addPoseLayer(base->frames, rec.frame, falloffRadius_, base->frames[dragged], rec.after.pose);
        const int first = std::max(0, rec.frame - falloffRadius_),
                  last = std::min(frameCount() - 1, rec.frame + falloffRadius_);
        for (int t = first; t <= last; ++t)
            base->x[static_cast<std::size_t>(t)] = Eigen::VectorXd();  // their poses moved
        base->frames[dragged] = rec.after.pose;
        base->x[dragged] = rec.after.x;
    }
    std::string problem;
    MotionEditJob job = dragFalloffJob(v, rec.effector, rec.frame, rec.after.pose, rec.after.x, falloffRadius_,
                                       pinnedEffectors(), &problem, std::move(base));
    if (!problem.empty()) {  // the change stays a one-frame edit: say so
        falloffSkipped_ =
            stepLabel + ": kept on frame " + std::to_string(rec.frame + 1) + " alone, not spread (" + problem + ")";
        return;
    }
    job.contacts = std::make_shared<const ContactSet>(store_.contacts());
    // What earlier gestures placed on the spread's frames stays where the edited motion has it
    // (after a whole-pose change: where its layer moved it, so that the span stays smooth).
    // A whole-pose change keeps every placement on its records, the displaced effector's too (the
    // solve does not hold that one: it follows its displaced path).
    job.heldPlaced =
        heldRuns(store_, job.keyFrames.front(), job.keyFrames.back(), wholePose ? Effector::kCount : rec.effector);
    job.placesEffector = !wholePose;
    job.spanWeights.locality = kDefaultSpanLocality * bodyStiffness_;
    if (regenerate_.start(std::move(job)).empty()) falloffStepLabel_ = stepLabel;
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

// ---- undo / redo ---------------------------------------------------------------------------

void EditorDocument::pushStep(EditStep step) {
    history_.push(std::move(step));
    ++revision_;
    models_.pruneVersions(history_.oldestUnresolvedSample());  // versions no remaining step can ask for
}

void EditorDocument::applyFrames(const FrameEdits& frames) {
    store_.apply(frames);
    for (const auto& [frame, edit] : frames) {
        if (edit)
            editLineage_[frame] = lineage_;
        else
            editLineage_.erase(frame);
    }
    updatePinPositions();
}

void EditorDocument::installVersion(const gp::ModelVersionPtr& version) {
    if (models_.restore(version)) cacheFrame_ = -1;
}

std::string EditorDocument::undoLabel() const {
    const EditStep* s = history_.topUndo();
    return s ? s->label : "";
}

std::string EditorDocument::redoLabel() const {
    const EditStep* s = history_.topRedo();
    return s ? s->label : "";
}

void EditorDocument::finishRunningFalloff() {
    // A new drag, pose change or path regeneration right after a drag waits for that drag's
    // falloff (tens of milliseconds) and applies it first, so the earlier drag is never left as a
    // one-frame spike. A spread that has finished but not been collected yet is applied too:
    // otherwise the new step would sit on top of the drag's and the spread would be dropped.
    if (falloffStepLabel_.empty()) return;
    regenerate_.join();
    pollRegenerate();
}

void EditorDocument::dropRunningFalloff() {
    // Undo or redo right after a drag does not wait for the drag's falloff: the spread is dropped
    // (the drag's own frame stays in its step) and the undo goes on. A path regeneration is the
    // user's explicit request and still has to be waited for or cancelled.
    if (falloffStepLabel_.empty() || !regenerate_.running()) return;
    stopRegeneration();
    regenerate_.takeMessage();
    falloffStepLabel_.clear();
}

std::string EditorDocument::undoOrRedo(bool undo) {
    pollRegenerate();  // a regeneration or a fill that just finished is the latest step
    pollFill();
    dropRunningFalloff();
    cancelDrag();
    endLatentDrag();
    if (regenerating()) return "a regeneration is running: wait for it or cancel it";
    EditStep* step = undo ? history_.topUndo() : history_.topRedo();
    if (!step) return undo ? "nothing to undo" : "nothing to redo";
    if (undo) models_.resolveStep(*step);
    applyFrames(undo ? step->before : step->after);
    installVersion(undo ? step->modelBefore : step->modelAfter);
    if (undo)
        history_.moveUndoToRedo();
    else
        history_.moveRedoToUndo();
    ++revision_;
    return "";
}

std::string EditorDocument::undo() { return undoOrRedo(true); }

std::string EditorDocument::redo() { return undoOrRedo(false); }

std::optional<Pose> EditorDocument::beforeGhost() const {
    const EditStep* s = history_.topUndo();
    if (!s) return std::nullopt;
    const auto it = s->before.find(frame_);
    if (it == s->before.end()) return std::nullopt;
    return it->second ? it->second->pose : clip().frames[frame_];
}

// ---- path editing --------------------------------------------------------------------------

std::string EditorDocument::beginPathEdit(Effector e) { return paths_.begin(e, frame_); }

std::string EditorDocument::startRegenerate(int maxIterations) {
    const std::optional<PathEdit>& path = paths_.edit();
    if (!path) return "no path is being edited";
    const gp::ModelVersionPtr v = model();
    if (!v) return "regeneration needs a model: train one or open one first";
    const Clip& mc = v->model->clip;
    if (mc.frameCount() != frameCount() || mc.skeleton.jointCount() != clip().skeleton.jointCount())
        return "expected a model trained on this clip, found one trained on " + mc.name;
    finishRunningFalloff();
    pollRegenerate();  // never drop a finished result nobody took yet
    cancelDrag();
    MotionEditJob job;
    job.version = v;
    job.effector = path->effector;
    job.keyFrames = path->keyFrames;
    job.keyOffsetsCm = path->keyOffsetsCm;
    job.mode = path->mode;
    job.maxIterations = maxIterations;
    job.pins = pinnedEffectors();  // a pin holds its effector at the captured position on every frame of the span
    job.contacts = std::make_shared<const ContactSet>(store_.contacts());  // the user may have switched some off
    job.spanWeights.locality = kDefaultSpanLocality * bodyStiffness_;
    // The path is re-solved from the capture, but what earlier gestures placed on its inner frames
    // (held effectors, edit/held_effectors.h) stays where the edited motion has it
    // (EditBase::placedFrames); pins and planted feet are held as before.
    job.heldPlaced = heldRuns(store_, path->keyFrames.front() + 1, path->keyFrames.back() - 1, path->effector);
    if (!job.heldPlaced.empty()) {
        auto base = std::make_shared<EditBase>();
        base->frames = mc.frames;
        base->placedFrames.reserve(static_cast<std::size_t>(frameCount()));
        for (int t = 0; t < frameCount(); ++t) base->placedFrames.push_back(store_.pose(t));
        job.base = std::move(base);
    }
    return regenerate_.start(std::move(job));
}

std::string EditorDocument::pollRegenerate(std::string* error) {
    if (regenerate_.running()) return "";
    std::optional<MotionEditJob> job = regenerate_.take();
    if (!job) {
        if (error) *error = regenerate_.takeMessage();
        return std::exchange(falloffSkipped_, std::string());
    }
    // A drag's falloff joins the drag's own undo step when that step is still the latest.
    if (const std::string dragLabel = std::exchange(falloffStepLabel_, std::string()); !dragLabel.empty()) {
        EditStep* top = history_.topUndo();
        if (!top || top->label != dragLabel) return "";  // undone or superseded: drop the falloff
        mergeFalloff(*job, store_, *top);
        applyFrames(top->after);
        ++revision_;
        return falloffSummary(*job, falloffRadius_, dragLabel);
    }
    lastRegenerateQuality_ = job->quality;  // the Path panel's report: path regenerations only
    lastRegenerateKeys_ = job->keys;
    EditStep step = regenerationStep(*job, store_);
    if (models_.hasModel())
        for (AdaptiveSample& sample : movedKeySamples(*job)) {
            const auto it = step.after.find(sample.clipFrame);
            if (it == step.after.end() || !it->second) continue;  // a moved key is always a regenerated frame
            if (const long seq = teach(std::move(sample), it->second->pose, it->second->moved); seq > 0)
                step.samples.push_back(seq);
        }
    applyFrames(step.after);
    pushStep(std::move(step));
    return regenerationSummary(*job, models_.updating());
}

// ---- keys and in-betweening ----------------------------------------------------------------

void EditorDocument::toggleKey(int frame) {
    if (!hasClip() || frame < 0 || frame >= frameCount()) return;
    if (!keys_.erase(frame)) keys_.insert(frame);
    ++revision_;
}

std::string EditorDocument::restoreKeys(std::set<int> keys) {
    for (int k : keys)
        if (k < 0 || k >= frameCount())
            return "expected key frames in 1.." + std::to_string(frameCount()) + ", found " + std::to_string(k + 1);
    keys_ = std::move(keys);
    ++revision_;
    return "";
}

std::optional<InbetweenGap> EditorDocument::keyGapAt(int frame) const {
    auto after = keys_.upper_bound(frame);
    if (after == keys_.begin() || after == keys_.end()) return std::nullopt;
    const int a = *std::prev(after), b = *after;
    if (a + 1 >= b) return std::nullopt;
    return InbetweenGap{a, b};
}

std::vector<InbetweenGap> EditorDocument::keyGapsIn(int first, int last) const {
    std::vector<InbetweenGap> gaps;
    for (auto k = keys_.lower_bound(first); k != keys_.end() && std::next(k) != keys_.end() && *std::next(k) <= last;
         ++k)
        if (*k + 1 < *std::next(k)) gaps.push_back({*k, *std::next(k)});
    return gaps;
}

std::string EditorDocument::startFill(InbetweenMethod method, std::optional<std::pair<int, int>> range) {
    const gp::ModelVersionPtr v = model();
    if (!v) return "fill between keys needs a model: train one or open one first";
    std::vector<InbetweenGap> gaps;
    if (range) {
        gaps = keyGapsIn(range->first, range->second);
        if (gaps.empty())
            return "expected two keys with frames between inside frames " + std::to_string(range->first + 1) + "-" +
                   std::to_string(range->second + 1) + " (K marks a key)";
    } else if (const std::optional<InbetweenGap> gap = keyGapAt(frame_)) {
        gaps = {*gap};
    } else {
        return "expected a key before the playhead and one after it with frames between (K marks a key)";
    }
    finishRunningFalloff();  // a drag's spread finishes first (it is part of the drag)
    pollRegenerate();        // never drop a finished result nobody took yet
    if (regenerating()) return "a regeneration is running: wait for it or cancel it";
    cancelDrag();
    InbetweenJob job;
    job.version = v;
    job.clip = clip();
    // The capture the clip is a take of, judged on the unedited clip (edited frames would hide it):
    // its frames in the gap are never read, whatever was edited.
    job.sameCapture = gp::findCapture(*v->model, clip());
    for (int t = 0; t < frameCount(); ++t)
        job.clip.frames[static_cast<std::size_t>(t)] = poseAt(t);  // the edited motion
    job.gaps = std::move(gaps);
    job.method = method;
    if (const std::string problem = job.validate(); !problem.empty()) return problem;
    if (!fill_.startIfIdle(std::move(job))) return "a fill is already running";
    return "";
}

std::string EditorDocument::pollFill(std::string* error) {
    if (fill_.busy()) return "";
    std::optional<InbetweenJob> job = fill_.take();
    if (!job) {
        if (error) *error = fill_.takeMessage();
        return "";
    }
    const int first = job->gaps.front().a, last = job->gaps.back().b;
    // The keys or the frames between changed while it ran (nothing should, drags wait): the result
    // belongs to another motion, so it is dropped rather than pasted over the change.
    for (int t = first; t <= last; ++t)
        if (!samePose(poseAt(t), job->clip.frames[static_cast<std::size_t>(t)])) {
            if (error) *error = "the motion between the keys changed while filling: fill again";
            return "";
        }
    EditStep step;
    step.label = "fill frames " + std::to_string(first + 2) + "-" + std::to_string(last);
    double seconds = 0.0, held = 0.0;
    for (std::size_t g = 0; g < job->gaps.size(); ++g) {
        for (int t = job->gaps[g].a + 1; t < job->gaps[g].b; ++t) {
            const std::size_t i = static_cast<std::size_t>(t);
            step.after[t] = EditRecord{job->frames[i], i < job->x.size() ? job->x[i] : Eigen::VectorXd(), {}};
        }
        seconds += job->reports[g].seconds;
        held = std::max(held, job->reports[g].maxHeldResidualCm);
    }
    step.before = store_.current(step.after);
    applyFrames(step.after);
    pushStep(std::move(step));
    const InbetweenJob::GapReport& r = job->reports.front();
    const std::size_t n = job->gaps.size();
    char summary[240];
    if (r.sourceClip.empty())
        std::snprintf(summary, sizeof summary, "filled frames %d-%d, %zu gap%s (%s)", first + 2, last, n,
                      n == 1 ? "" : "s", inbetweenMethodName(job->method));
    else if (n == 1)
        std::snprintf(summary, sizeof summary,
                      "filled frames %d-%d from %s frames %d-%d in %.2f s (feet held within %.2f cm)", first + 2, last,
                      r.sourceClip.c_str(), r.sourceFirst + 1, r.sourceLast + 1, seconds, held);
    else
        std::snprintf(summary, sizeof summary, "filled frames %d-%d, %zu gaps, in %.2f s (feet held within %.2f cm)",
                      first + 2, last, n, seconds, held);
    return summary;
}

void EditorDocument::waitIdle() {
    fill_.waitIdle();
    regenerate_.join();
    models_.waitIdle();
}

Balance EditorDocument::balanceOf(int frame, const Pose& edited) const {
    return judgeBalance(clip().skeleton, clip().frames[frame], edited, store_.contacts(), frame);
}

std::optional<AdmissionVerdict> EditorDocument::currentPoseVerdict() const {
    const gp::ModelVersionPtr v = model();
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
    // Edits from regeneration, falloff or a latent drag have no hard targets left to miss.
    const bool lastDragged = lastDrag_.frame == frame_ && samePose(lastDrag_.pose, e.pose);
    return admitPose(*v, e.pose, e.moved, !lastDragged || lastDrag_.reached, lastDragged && lastDrag_.belowFloor,
                     sigma2, lik, balanceOf(frame_, e.pose));
}

}  // namespace mgp
