#include "edit/editor_document.h"

#include <algorithm>
#include <cstdio>
#include <cmath>

#include "skeleton/forward_kinematics.h"

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
EditorDocument::~EditorDocument() = default;

void EditorDocument::setClip(Clip clip, bool synthetic) {
    cancelDrag();
    unwrapClip(clip);
    clip_ = std::move(clip);
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
    edits_.erase(frame);
    updatePinPositions();
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
    worker_.reset();
    worker_ = std::make_unique<AdaptiveWorker>(version);
    worker_->setEnabled(adaptive_);
    worker_->setListener([this](const AdaptiveReport& r) {
        std::lock_guard<std::mutex> lock(statusMutex_);
        AdaptiveHistoryEntry h;
        h.when = std::chrono::system_clock::now();
        h.frame = r.frame;
        h.accepted = r.result.accepted;
        h.diagnostic = r.result.diagnostic;
        h.seconds = r.seconds;
        h.versionBefore = r.versionBefore;
        h.versionAfter = r.published->number;
        h.rowsAfter = r.modelRows;
        h.activeSize = static_cast<int>(r.published->model->active.size());
        h.activeChanged = r.result.activeChanged;
        h.newPointActive = r.result.newPointActive;
        h.objectiveBefore = r.result.objectiveBefore;
        h.objectiveAfter = r.result.objectiveAfter;
        adaptiveHistory_.push_back(std::move(h));
        char buf[160];
        std::snprintf(buf, sizeof buf, "update %s in %.2f s (N = %d)", r.result.accepted ? "accepted" : "rejected",
                      r.seconds, r.modelRows);
        adaptiveStatus_ = buf;
        if (!r.result.accepted && !r.result.diagnostic.empty()) adaptiveStatus_ += ": " + r.result.diagnostic;
    });
    solver_.reset();
    latentPath_.clear();
    cacheFrame_ = -1;
    std::lock_guard<std::mutex> lock(statusMutex_);
    adaptiveStatus_.clear();
    adaptiveHistory_.clear();
}

void EditorDocument::clearModel() {
    cancelDrag();
    worker_.reset();
    solver_.reset();
    cacheFrame_ = -1;
}

gp::ModelVersionPtr EditorDocument::model() const { return worker_ ? worker_->current() : nullptr; }

void EditorDocument::setAdaptiveEnabled(bool on) {
    adaptive_ = on;
    if (worker_) worker_->setEnabled(on);
}

std::string EditorDocument::adaptiveStatus() const {
    std::lock_guard<std::mutex> lock(statusMutex_);
    return adaptiveStatus_;
}

int EditorDocument::adaptiveUpdates() const {
    std::lock_guard<std::mutex> lock(statusMutex_);
    return static_cast<int>(adaptiveHistory_.size());
}

std::vector<AdaptiveHistoryEntry> EditorDocument::adaptiveHistory() const {
    std::lock_guard<std::mutex> lock(statusMutex_);
    return adaptiveHistory_;
}

void EditorDocument::setCompareMode(CompareMode mode) {
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
    return cs;
}

std::string EditorDocument::beginDrag(Effector e) {
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
        if (!solver_ || solver_->version() != v) solver_ = std::make_unique<LearnedIkSolver>(v);
    }
    updatePinPositions();
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
        compareSolver_ = std::make_unique<LearnedIkSolver>(compareModel_);
    LearnedIkRequest req;
    req.start = drag_.startPose;
    req.startX = latentStartForFrame(*compareModel_, std::min(frame_, compareModel_->model->clip.frameCount() - 1));
    req.constraints = constraintsFor(drag_.targetCm);
    req.maxIterations = 100;
    if (!compareSolver_->validate(req).empty()) return;
    const LearnedIkResult r = compareSolver_->solve(req);
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
    edits_[frame_] = rec.after;
    drag_.active = false;
    comparePose_.reset();
    if (worker_ && solver_ && readout_.valid && readout_.learned && result_.y.allFinite() && result_.x.allFinite()) {
        AdaptiveSample s;
        s.x = drag_.x;
        s.yKept = result_.y;
        s.clipFrame = frame_;
        worker_->post(std::move(s));
    }
    updatePinPositions();
    return rec;
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
    v->point->predict(x, mean, var);
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
    latentDrag_ = false;
    updatePinPositions();
}

void EditorDocument::waitIdle() {
    if (worker_) worker_->waitIdle();
}

}  // namespace mgp
