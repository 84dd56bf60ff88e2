#include "edit/editor_document.h"

#include <algorithm>
#include <utility>

#include "edit/latent_refit.h"
#include "ik/learned_ik.h"
#include "ik/locality.h"
#include "ik/plain_ik.h"
#include "motion/drag_falloff.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"

namespace mgp {

namespace {
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
    judgedEdits_.clear();
    falloffStepId_ = 0;
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
            // The prior's solve keeps the root translation: a pose whose legs cannot reach the
            // planted feet from there (a crouch pasted onto a stride) is settled onto them by
            // moving the hips (settleOnHolds), from the prior's best try. It holds each held
            // foot by its ball, so the given pose's ankle would tip the foot onto its toe (heels
            // up 6 cm on a throw's pose pasted onto a stance): the settle brings the ankles back
            // too, by the legs alone where the holds are met (moving the hips would move the
            // free foot as well).
            // Only the planted feet keep their soles: a foot pinned in the air turns as the new pose turns it.
            std::vector<Effector> planted;
            for (const IkConstraint& c : contactHolds()) planted.push_back(c.effector);
            const Pose& tried = keptHolds ? pose : allFinite(r.pose) ? r.pose : given;
            if (std::optional<Pose> settled =
                    settleOnHolds(clip().skeleton, tried, -1, kept, &currentPose(), 500, !keptHolds, &planted);
                settled && worstHoldMissCm(clip().skeleton, *settled, kept) <= kReachedToleranceCm) {
                pose = std::move(*settled);
                keptHolds = true;
                x = refitLatent(*v, frame_, v->model->keptPose(layout.extract(pose)));
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
    const long stepId = pushStep(std::move(step));
    startDragFalloff(change, stepId, stepLabel, true, keptHolds, followLayer);
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
        if (p.frame >= frameCount() || !posesIdentical(store_.pose(p.frame), p.edited))
            continue;  // undone or edited since
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
    judgedEdits_.clear();
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
    judgedEdits_.clear();
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
        cacheEdited_ == (edit != nullptr) && cacheCurrent_ == current &&
        (!edit || posesIdentical(cachePose_, edit->pose)))
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

// ---- undo / redo ---------------------------------------------------------------------------

long EditorDocument::pushStep(EditStep step) {
    const long id = history_.push(std::move(step));
    ++revision_;
    models_.pruneVersions(history_.oldestUnresolvedSample());  // versions no remaining step can ask for
    return id;
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
    if (models_.restore(version)) {
        cacheFrame_ = -1;
        judgedEdits_.clear();
    }
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
    if (falloffStepId_ == 0) return;
    regenerate_.join();
    pollRegenerate();
}

void EditorDocument::dropRunningFalloff() {
    // Undo or redo right after a drag does not wait for the drag's falloff: the spread is dropped
    // (the drag's own frame stays in its step) and the undo goes on. A path regeneration is the
    // user's explicit request and still has to be waited for or cancelled.
    if (falloffStepId_ == 0 || !regenerate_.running()) return;
    stopRegeneration();
    regenerate_.takeMessage();
    falloffStepId_ = 0;
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

void EditorDocument::waitIdle() {
    fill_.waitIdle();
    regenerate_.join();
    models_.waitIdle();
}

}  // namespace mgp
