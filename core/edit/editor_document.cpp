#include "edit/editor_document.h"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <utility>

#include "motion/drag_falloff.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"

namespace mgp {

namespace {
constexpr int kRefineBudgetIterations = 1000;  // idle refinement per target, then stop
constexpr int kAcceptIterations = 300;         // extra iterations on release if not converged

bool finitePose(const Pose& p) {
    if (!p.rootCm.allFinite()) return false;
    for (const auto& a : p.anglesDeg)
        if (!a.allFinite()) return false;
    return true;
}
}  // namespace

EditorDocument::EditorDocument() = default;
EditorDocument::~EditorDocument() {
    // The jobs call back into members declared after them: stop them first.
    regenerate_.cancel();
    regenerate_.join();
    models_.clear();
}

void EditorDocument::setClip(Clip clip, bool synthetic) {
    cancelDrag();
    latentDrag_ = false;
    latentBefore_.reset();
    regenerate_.cancel();
    regenerate_.join();
    regenerate_.take();
    history_.clear();
    paths_.reset();
    ++revision_;
    unwrapClip(clip);
    clip_ = std::move(clip);
    falloffStepLabel_.clear();
    lastRegenerateQuality_.reset();
    try {
        contacts_ = detectFootContacts(clip_);
    } catch (const std::exception&) {
        contacts_ = {};  // no feet to hold: regeneration holds pins only
    }
    contactReleased_.fill(false);
    falloffRadius_ = defaultFalloffRadius(clip_.fps);
    synthetic_ = synthetic;
    frame_ = 0;
    edits_.clear();
    pins_.fill(false);
    latentPath_.clear();
    readout_ = {};
    comparePose_.reset();
    clearModel();
    compareModel_.reset();
}

void EditorDocument::setFrame(int frame) {
    if (!hasClip()) return;
    if (drag_.active) endDrag();
    if (latentDrag_) endLatentDrag();
    frame_ = std::clamp(frame, 0, clip_.frameCount() - 1);
    updatePinPositions();
    comparePose_.reset();
}

const Pose& EditorDocument::currentPose() const {
    if (drag_.active) return drag_.pose;
    const auto it = edits_.find(frame_);
    return it != edits_.end() ? it->second.pose : clip_.frames[frame_];
}

void EditorDocument::clearEdit(int frame) {
    if (!edits_.count(frame)) return;
    EditStep step;
    step.label = "reset frame " + std::to_string(frame + 1) + " to the captured pose";
    step.before[frame] = edits_.at(frame);
    step.after[frame] = std::nullopt;
    applyFrames(step.after);
    pushStep(std::move(step));
}

std::string EditorDocument::pastePose(const Pose& pose) {
    if (!hasClip()) return "no clip to paste onto";
    Pose pasted = pose;
    pasted.rootCm = currentPose().rootCm;
    return setCurrentPose(pasted, "paste pose on frame " + std::to_string(frame_ + 1));
}

std::string EditorDocument::setCurrentPose(const Pose& pose, const std::string& stepLabel) {
    if (!hasClip()) return "no clip to edit";
    if (regenerating()) return "wait for the regeneration to finish before editing a pose";
    if (pose.anglesDeg.size() != currentPose().anglesDeg.size())
        return "expected a pose of this clip's skeleton, found one with " + std::to_string(pose.anglesDeg.size()) +
               " bones (copied from another clip?)";
    cancelDrag();
    EditRecord rec;
    rec.pose = pose;
    EditStep step;
    step.label = stepLabel;
    step.before[frame_] = editAt(frame_);
    step.after[frame_] = rec;
    applyFrames(step.after);
    pushStep(std::move(step));
    return "";
}

void EditorDocument::restoreEdits(std::map<int, EditRecord> edits) {
    cancelDrag();
    latentDrag_ = false;
    latentBefore_.reset();
    edits_ = std::move(edits);
    history_.clear();
    updatePinPositions();
    ++revision_;
}

std::optional<EditRecord> EditorDocument::editAt(int frame) const {
    const auto it = edits_.find(frame);
    return it == edits_.end() ? std::nullopt : std::optional<EditRecord>(it->second);
}

Eigen::Vector3d EditorDocument::effectorPosition(Effector e) const {
    if (!hasEffector(e)) return Eigen::Vector3d::Zero();
    return effectorCm(clip_.skeleton, currentPose(), e);
}

// ---- model ---------------------------------------------------------------------------------

void EditorDocument::setModel(gp::ModelVersionPtr version, bool adoptClip) {
    if (!version) {
        clearModel();
        return;
    }
    if (adoptClip) {
        setClip(version->model->clip, false);
        clip_.name = version->model->clip.name;
    }
    cancelDrag();
    latentDrag_ = false;
    regenerate_.cancel();  // a running regeneration solves on the old model: its result is dropped
    regenerate_.join();
    regenerate_.take();
    if (!adoptClip) history_.forgetModels();  // the steps' versions belong to the old model
    installWorker(std::move(version));
    ++revision_;
}

void EditorDocument::installWorker(gp::ModelVersionPtr version) {
    models_.install(std::move(version));
    solver_.reset();
    latentPath_.clear();
    cacheFrame_ = -1;
}

void EditorDocument::clearModel() {
    cancelDrag();
    latentDrag_ = false;
    latentBefore_.reset();
    regenerate_.cancel();  // its result would belong to the old model
    history_.forgetModels();
    models_.clear();
    solver_.reset();
    cacheFrame_ = -1;
}

void EditorDocument::setAdaptiveEnabled(bool on) {
    if (models_.setAdaptiveEnabled(on)) ++revision_;
}

void EditorDocument::setCompareMode(CompareMode mode) {
    if (compare_ != mode) ++revision_;
    compare_ = mode;
    comparePose_.reset();
    if (drag_.active) solveCompare();
}

Eigen::VectorXd EditorDocument::currentLatent() {
    const gp::ModelVersionPtr v = model();
    if (!v) return {};
    if ((drag_.active || latentDrag_) && drag_.x.size() > 0) return drag_.x;
    const auto it = edits_.find(frame_);
    if (it != edits_.end() && it->second.x.size() == v->model->latentDim()) return it->second.x;
    if (cacheFrame_ != frame_ || cacheVersion_ != v->number || cacheModel_ != v->model.get()) {
        cacheX_ = latentStartForFrame(*v, frame_);
        cacheFrame_ = frame_;
        cacheVersion_ = v->number;
        cacheModel_ = v->model.get();
    }
    return cacheX_;
}

// ---- pins ----------------------------------------------------------------------------------

void EditorDocument::togglePin(Effector e) { setPinned(e, !pinned(e)); }

void EditorDocument::setPinned(Effector e, bool on) {
    if (!hasEffector(e)) return;
    if (pins_[static_cast<int>(e)] != on) ++revision_;
    pins_[static_cast<int>(e)] = on;
    if (on) pinPositions_[static_cast<int>(e)] = effectorPosition(e);
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
    forwardKinematics(clip_.skeleton, currentPose(), fk);
    for (int i = 0; i < kEffectorCount; ++i)
        if (pins_[i]) pinPositions_[i] = effectorCm(clip_.skeleton, fk, static_cast<Effector>(i));
}

// ---- drag ----------------------------------------------------------------------------------

std::vector<IkConstraint> EditorDocument::constraintsFor(const Eigen::Vector3d& target) const {
    std::vector<IkConstraint> cs;
    cs.push_back({drag_.effector, target, false});
    for (int i = 0; i < kEffectorCount; ++i) {
        const auto e = static_cast<Effector>(i);
        if (pins_[i] && e != drag_.effector) cs.push_back({e, pinPositions_[i], true});
    }
    for (const IkConstraint& c : drag_.contactPins)
        if (!pins_[static_cast<int>(c.effector)] && c.effector != drag_.effector) cs.push_back(c);
    return cs;
}

bool EditorDocument::inContact(Effector foot) const {
    if (!hasClip() || (foot != Effector::kLFoot && foot != Effector::kRFoot)) return false;
    // A contact the user switched off on the timeline is not held by a drag either.
    return contacts_.at(foot, frame_) != nullptr;
}

void EditorDocument::setContactReleased(Effector foot, bool released) {
    if (contactReleased_[static_cast<int>(foot)] != released) ++revision_;
    contactReleased_[static_cast<int>(foot)] = released;
}

std::string EditorDocument::beginDrag(Effector e) {
    finishRunningFalloff();
    if (!hasClip()) return "no clip is open";
    if (!hasEffector(e)) return std::string("this skeleton has no ") + effectorName(e);
    if (drag_.active) endDrag();
    if (latentDrag_) endLatentDrag();
    drag_ = Drag{};
    drag_.effector = e;
    const auto it = edits_.find(frame_);
    if (it != edits_.end()) drag_.before = it->second;
    drag_.startPose = currentPose();
    drag_.pose = drag_.startPose;
    drag_.targetCm = effectorPosition(e);
    const gp::ModelVersionPtr v = model();
    if (v) {
        drag_.versionBefore = v->number;
        drag_.startX = currentLatent();
        drag_.x = drag_.startX;
        if (!solver_ || solver_->version() != v) solver_ = std::make_unique<ConstrainedIkSolver>(v);
    }
    updatePinPositions();
    for (Effector f : {Effector::kLFoot, Effector::kRFoot})
        if (f != e && hasEffector(f) && !contactReleased(f) && inContact(f))
            drag_.contactPins.push_back({f, effectorCm(clip_.skeleton, drag_.startPose, f), true});
    latentPath_.clear();
    if (drag_.x.size() > 0) latentPath_.push_back(drag_.x);
    drag_.active = true;
    readout_ = {};
    comparePose_.reset();
    return "";
}

void EditorDocument::dragTo(const Eigen::Vector3d& targetCm, int maxIterations) {
    if (!drag_.active || !targetCm.allFinite()) return;
    drag_.targetCm = targetCm;
    drag_.refineBudget = kRefineBudgetIterations;
    readout_.iterations = 0;
    if (solver_) solveLearned(maxIterations, false);
    else solvePlain();
    solveCompare();
}

bool EditorDocument::refine(int maxIterations) {
    if (!drag_.active || !solver_ || drag_.converged || drag_.refineBudget <= 0) return false;
    drag_.refineBudget -= maxIterations;
    const double before = result_.objective;
    solveLearned(maxIterations, false);
    // Stop refining once an extra round no longer changes F.
    if (std::abs(before - result_.objective) <= 1e-9 * std::max(1.0, std::abs(before))) drag_.converged = true;
    return true;
}

void EditorDocument::solveLearned(int maxIterations, bool /*fromDragStart*/) {
    request_.start = drag_.pose;
    request_.startX = drag_.x;
    request_.constraints = constraintsFor(drag_.targetCm);
    request_.maxIterations = maxIterations;
    // The root rotation is held (stiffly) near where the drag began, not where the last event left it.
    request_.rootReferenceDeg = drag_.startPose.anglesDeg.empty() ? std::nullopt
                                                                  : std::optional<Eigen::Vector3d>(drag_.startPose.anglesDeg[0]);
    if (!solver_->validate(request_).empty()) return;
    solver_->solve(request_, result_);
    if (!finitePose(result_.pose) || !result_.x.allFinite()) return;  // keep the last good pose
    drag_.pose = result_.pose;
    drag_.x = result_.x;
    drag_.converged = result_.converged;
    if (latentPath_.empty() || (latentPath_.back() - drag_.x).norm() > 1e-6) latentPath_.push_back(drag_.x);
    readout_.valid = true;
    readout_.learned = true;
    readout_.constraints = result_.constraints;
    readout_.reached = result_.reached;
    readout_.sigma2 = result_.sigma2;
    readout_.lik = result_.lik;
    readout_.iterations += result_.iterations;
    readout_.converged = result_.converged;
    readout_.stop = result_.stop;
    readout_.diagnostic = result_.diagnostic;
}

void EditorDocument::solvePlain() {
    PlainIkJob job;
    job.skeleton = &clip_.skeleton;
    job.start = drag_.pose;
    job.constraints = constraintsFor(drag_.targetCm);
    job.maxIterations = 100;
    if (!job.validate().empty()) return;
    job.solve();
    if (!finitePose(job.pose)) return;
    drag_.pose = job.pose;
    drag_.converged = true;
    readout_.valid = true;
    readout_.learned = false;
    readout_.constraints = job.results;
    readout_.reached = job.reached;
    readout_.sigma2 = readout_.lik = 0.0;
    readout_.iterations = job.iterations;
    readout_.diagnostic = "plain IK (no model): " + job.diagnostic;
}

void EditorDocument::solveCompare() {
    comparePose_.reset();
    if (!drag_.active || compare_ == CompareMode::kNone) return;
    if (compare_ == CompareMode::kPlainIk) {
        PlainIkJob job;
        job.skeleton = &clip_.skeleton;
        job.start = drag_.startPose;
        job.constraints = constraintsFor(drag_.targetCm);
        if (!job.validate().empty()) return;
        job.solve();
        if (finitePose(job.pose)) comparePose_ = job.pose;
        return;
    }
    if (!compareModel_) return;
    if (compareModel_->model->clip.skeleton.jointCount() != clip_.skeleton.jointCount()) return;
    if (!compareSolver_ || compareSolver_->version() != compareModel_)
        compareSolver_ = std::make_unique<ConstrainedIkSolver>(compareModel_);
    ConstrainedIkRequest req;
    req.start = drag_.startPose;
    req.startX = latentStartForFrame(*compareModel_, std::min(frame_, compareModel_->model->clip.frameCount() - 1));
    req.constraints = constraintsFor(drag_.targetCm);
    req.maxIterations = 100;
    if (!compareSolver_->validate(req).empty()) return;
    const ConstrainedIkResult r = compareSolver_->solve(req);
    if (finitePose(r.pose)) comparePose_ = r.pose;
}

std::optional<DragRecord> EditorDocument::endDrag() {
    if (!drag_.active) return std::nullopt;
    if (solver_ && !drag_.converged && readout_.valid) solveLearned(kAcceptIterations, false);
    DragRecord rec;
    rec.frame = frame_;
    rec.effector = drag_.effector;
    rec.before = drag_.before;
    rec.after.pose = drag_.pose;
    rec.after.x = drag_.x;
    rec.modelVersionBefore = drag_.versionBefore;
    drag_.active = false;
    comparePose_.reset();
    EditStep step;
    step.label = std::string("drag ") + effectorName(rec.effector) + " on frame " + std::to_string(frame_ + 1);
    step.before[frame_] = rec.before;
    step.after[frame_] = rec.after;
    const gp::ModelVersionPtr solvedOn = solver_ ? solver_->version() : nullptr;
    const bool learnedPose = models_.hasModel() && solver_ && readout_.valid && readout_.learned && result_.y.allFinite() &&
                             result_.x.allFinite();
    const gp::AdmissionVerdict verdict =
        learnedPose ? gp::admitPose(solvedOn->range, result_.reached, result_.sigma2, result_.lik) : gp::AdmissionVerdict{};
    if (learnedPose && models_.updating() && !verdict.admitted)
        models_.noteRefused(frame_, *solvedOn, verdict.reason);  // kept as an edit, not taught to the model
    lastDrag_.frame = frame_;
    lastDrag_.pose = drag_.pose;
    lastDrag_.reached = readout_.valid ? readout_.reached : true;
    if (learnedPose && verdict.admitted) {
        AdaptiveSample s;
        s.x = drag_.x;
        s.yKept = result_.y;
        s.clipFrame = frame_;
        if (const long seq = models_.post(std::move(s)); seq > 0) step.samples.push_back(seq);
    }
    applyFrames(step.after);
    const std::string label = step.label;
    pushStep(std::move(step));
    startDragFalloff(rec, label);
    return rec;
}

void EditorDocument::setContactEnabled(std::size_t index, bool on) {
    if (index >= contacts_.contacts.size() || contacts_.contacts[index].enabled == on) return;
    contacts_.contacts[index].enabled = on;
    ++revision_;
}

void EditorDocument::startDragFalloff(const DragRecord& rec, const std::string& stepLabel) {
    const gp::ModelVersionPtr v = model();
    if (falloffRadius_ < 1 || !v || regenerate_.running()) return;
    const Clip& mc = v->model->clip;
    if (mc.frameCount() != clip_.frameCount() || mc.skeleton.jointCount() != clip_.skeleton.jointCount()) return;
    std::string problem;
    MotionEditJob job = dragFalloffJob(v, rec.effector, rec.frame, effectorCm(clip_.skeleton, rec.after.pose, rec.effector),
                                       falloffRadius_, pinnedEffectors(), &problem);
    if (!problem.empty()) return;  // the drag stays a one-frame edit
    job.contacts = std::make_shared<const ContactSet>(contacts_);
    if (regenerate_.start(std::move(job)).empty()) falloffStepLabel_ = stepLabel;
}

void EditorDocument::cancelDrag() {
    if (!drag_.active) return;
    drag_.active = false;
    comparePose_.reset();
}

Pose EditorDocument::poseFromLatent(const Eigen::VectorXd& x, const Pose& base) const {
    const gp::ModelVersionPtr v = model();
    Eigen::VectorXd mean;
    double var = 0.0;
    v->posterior->predict(x, mean, var);
    const Eigen::VectorXd full = v->model->fullPose(mean);
    Pose p = base;
    PoseLayout(clip_.skeleton).apply(full.data(), p);
    return p;
}

bool EditorDocument::beginLatentDrag() {
    if (!hasModel() || !hasClip()) return false;
    if (drag_.active) endDrag();
    const auto it = edits_.find(frame_);
    latentBefore_ = it != edits_.end() ? std::optional<EditRecord>(it->second) : std::nullopt;
    drag_ = Drag{};
    drag_.x = currentLatent();
    drag_.pose = currentPose();
    latentPath_.clear();
    latentPath_.push_back(drag_.x);
    latentDrag_ = true;
    return true;
}

void EditorDocument::latentDragTo(const Eigen::VectorXd& x) {
    if (!latentDrag_ || !x.allFinite() || x.size() != drag_.x.size()) return;
    const Pose p = poseFromLatent(x, clip_.frames[frame_]);
    if (!finitePose(p)) return;
    drag_.x = x;
    drag_.pose = p;
    edits_[frame_] = EditRecord{p, x};
    latentPath_.push_back(x);
}

void EditorDocument::endLatentDrag() {
    if (!latentDrag_) return;
    latentDrag_ = false;
    EditStep step;
    step.label = "latent pose on frame " + std::to_string(frame_ + 1);
    step.before[frame_] = latentBefore_;
    step.after[frame_] = editAt(frame_);
    if (step.after[frame_] && latentPath_.size() > 1) pushStep(std::move(step));
    updatePinPositions();
}

// ---- undo / redo ---------------------------------------------------------------------------

void EditorDocument::pushStep(EditStep step) {
    history_.push(std::move(step));
    ++revision_;
    models_.pruneVersions(history_.oldestUnresolvedSample());  // versions no remaining step can ask for
}

void EditorDocument::applyFrames(const std::map<int, std::optional<EditRecord>>& frames) {
    for (const auto& [frame, record] : frames) {
        if (record) edits_[frame] = *record;
        else edits_.erase(frame);
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
    // A new drag or a path regeneration right after a drag waits for that drag's falloff (tens of
    // milliseconds) and applies it first, so the earlier drag is never left as a one-frame spike.
    if (falloffStepLabel_.empty() || !regenerate_.running()) return;
    regenerate_.join();
    pollRegenerate();
}

void EditorDocument::dropRunningFalloff() {
    // Undo or redo right after a drag does not wait for the drag's falloff: the spread is dropped
    // (the drag's own frame stays in its step) and the undo goes on. A path regeneration is the
    // user's explicit request and still has to be waited for or cancelled.
    if (falloffStepLabel_.empty() || !regenerate_.running()) return;
    regenerate_.cancel();
    regenerate_.join();
    regenerate_.take();
    regenerate_.takeMessage();
    falloffStepLabel_.clear();
}

std::string EditorDocument::undo() {
    pollRegenerate();  // a regeneration that just finished is the latest step
    dropRunningFalloff();
    cancelDrag();
    if (latentDrag_) endLatentDrag();
    if (regenerating()) return "a regeneration is running: wait for it or cancel it";
    EditStep* step = history_.topUndo();
    if (!step) return "nothing to undo";
    models_.resolveStep(*step);
    applyFrames(step->before);
    installVersion(step->modelBefore);
    history_.moveUndoToRedo();
    ++revision_;
    return "";
}

std::string EditorDocument::redo() {
    pollRegenerate();
    dropRunningFalloff();
    cancelDrag();
    if (latentDrag_) endLatentDrag();
    if (regenerating()) return "a regeneration is running: wait for it or cancel it";
    EditStep* step = history_.topRedo();
    if (!step) return "nothing to redo";
    applyFrames(step->after);
    installVersion(step->modelAfter);
    history_.moveRedoToUndo();
    ++revision_;
    return "";
}

std::optional<Pose> EditorDocument::beforeGhost() const {
    const EditStep* s = history_.topUndo();
    if (!s) return std::nullopt;
    const auto it = s->before.find(frame_);
    if (it == s->before.end()) return std::nullopt;
    return it->second ? it->second->pose : clip_.frames[frame_];
}

// ---- path editing --------------------------------------------------------------------------

std::string EditorDocument::beginPathEdit(Effector e) { return paths_.begin(e, frame_); }

std::string EditorDocument::startRegenerate(int maxIterations) {
    const std::optional<PathEdit>& path = paths_.edit();
    if (!path) return "no path is being edited";
    const gp::ModelVersionPtr v = model();
    if (!v) return "regeneration needs a model: train one or open one first";
    const Clip& mc = v->model->clip;
    if (mc.frameCount() != clip_.frameCount() || mc.skeleton.jointCount() != clip_.skeleton.jointCount())
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
    job.contacts = std::make_shared<const ContactSet>(contacts_);  // the user may have switched some off
    return regenerate_.start(std::move(job));
}

std::string EditorDocument::pollRegenerate(std::string* error) {
    if (regenerate_.running()) return "";
    std::optional<MotionEditJob> job = regenerate_.take();
    if (!job) {
        if (error) *error = regenerate_.takeMessage();
        return "";
    }
    lastRegenerateQuality_ = job->quality;
    // A drag's falloff joins the drag's own undo step when that step is still the latest.
    if (const std::string dragLabel = std::exchange(falloffStepLabel_, std::string()); !dragLabel.empty()) {
        EditStep* top = history_.topUndo();
        if (!top || top->label != dragLabel) return "";  // undone or superseded: drop the falloff
        for (std::size_t i = 0; i < job->solvedFrames.size(); ++i) {
            const int t = job->solvedFrames[i];
            if (!top->before.count(t)) top->before[t] = editAt(t);
            top->after[t] = EditRecord{job->frames[t], job->results[i].x};
        }
        applyFrames(top->after);
        ++revision_;
        char summary[160];
        std::snprintf(summary, sizeof summary, "drag spread over frames %d-%d (falloff %d frames)", job->keyFrames.front() + 2,
                      job->keyFrames.back(), falloffRadius_);
        return summary;
    }
    EditStep step;
    char label[96];
    std::snprintf(label, sizeof label, "regenerate %s, frames %d-%d", effectorName(job->effector),
                  job->keyFrames.front() + 2, job->keyFrames.back());
    step.label = label;
    for (std::size_t i = 0; i < job->solvedFrames.size(); ++i) {
        const int t = job->solvedFrames[i];
        step.before[t] = editAt(t);
        step.after[t] = EditRecord{job->frames[t], job->results[i].x};
    }
    // As the CLI's `edit --adaptive`: the moved keys' poses join the model, not the in-betweens.
    if (models_.hasModel()) {
        for (std::size_t k = 1; k + 1 < job->keyFrames.size(); ++k) {
            if (job->keyOffsetsCm[k].isZero()) continue;
            const int t = job->keyFrames[k];
            const auto it = std::find(job->solvedFrames.begin(), job->solvedFrames.end(), t);
            const LearnedIkResult& r = job->results[static_cast<std::size_t>(it - job->solvedFrames.begin())];
            if (!r.x.allFinite() || !r.y.allFinite()) continue;
            if (const long seq = models_.post({r.x, r.y, t}); seq > 0) step.samples.push_back(seq);
        }
    }
    applyFrames(step.after);
    pushStep(std::move(step));
    const SpanQuality& q = job->quality;
    char summary[320];
    std::snprintf(summary, sizeof summary,
                  "regenerated %zu frames, max residual %.3f cm; angle 2nd difference p95 %.1f° (captured %.1f°), max %.1f° "
                  "(captured %.1f°); %zu contact(s) held%s",
                  job->solvedFrames.size(), job->maxResidualCm, q.edited.p95Deg, q.captured.p95Deg, q.edited.maxDeg,
                  q.captured.maxDeg, job->held.size(), models_.updating() ? " (adaptive update queued)" : "");
    return summary;
}

void EditorDocument::waitIdle() {
    regenerate_.join();
    models_.waitIdle();
}

}  // namespace mgp

namespace mgp {

namespace {
bool samePose(const Pose& a, const Pose& b) {
    return a.rootCm == b.rootCm && a.anglesDeg == b.anglesDeg;
}
}  // namespace

std::optional<gp::AdmissionVerdict> EditorDocument::currentPoseVerdict() const {
    const gp::ModelVersionPtr v = model();
    if (!v || !hasClip()) return std::nullopt;
    if (drag_.active) {
        if (!readout_.valid || !readout_.learned) return std::nullopt;
        return gp::admitPose(v->range, readout_.reached, readout_.sigma2, readout_.lik);
    }
    const auto it = edits_.find(frame_);
    if (it == edits_.end()) return std::nullopt;
    const EditRecord& e = it->second;
    if (e.x.size() != v->posterior->latentDim() || !e.x.allFinite()) return std::nullopt;
    if (v->model->clip.skeleton.jointCount() != clip_.skeleton.jointCount()) return std::nullopt;
    const PoseLayout layout(clip_.skeleton);
    const Eigen::VectorXd y = v->model->keptPose(layout.extract(e.pose));
    const double lik = v->posterior->evaluate(e.x, y, nullptr, nullptr);
    Eigen::VectorXd mean;
    double sigma2 = 0.0;
    v->posterior->predict(e.x, mean, sigma2);
    // Edits from regeneration, falloff or a latent drag have no hard targets left to miss.
    const bool reached = !(lastDrag_.frame == frame_ && samePose(lastDrag_.pose, e.pose)) || lastDrag_.reached;
    return gp::admitPose(v->range, reached, sigma2, lik);
}

}  // namespace mgp
