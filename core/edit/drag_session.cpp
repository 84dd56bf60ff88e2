#include "edit/drag_session.h"

#include <algorithm>
#include <cmath>

#include "ik/learned_ik.h"
#include "ik/plain_ik.h"
#include "skeleton/centre_of_mass.h"
#include "skeleton/clip.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"

namespace mgp {

namespace {
constexpr int kRefineBudgetIterations = 1000;  // idle refinement per target, then stop
constexpr int kSettleIterations = 300;         // extra iterations on release if not converged
constexpr int kPlainIterations = 100;

bool holds(const std::vector<IkConstraint>& cs, Effector e) {
    return std::any_of(cs.begin(), cs.end(), [e](const IkConstraint& c) { return c.effector == e; });
}
}  // namespace

DragSession::DragSession() = default;
DragSession::~DragSession() = default;

void DragSession::begin(const Skeleton& skeleton, Effector e, const Pose& start, gp::ModelVersionPtr model,
                        Eigen::VectorXd startX, std::vector<IkConstraint> pins, std::vector<IkConstraint> contactPins) {
    skeleton_ = &skeleton;
    layout_.emplace(skeleton);
    model_ = std::move(model);
    active_ = true;
    latent_ = false;
    effector_ = e;
    startPose_ = start;
    startCom_ = centreOfMass(skeleton, start);
    pose_ = start;
    targetCm_ = effectorCm(skeleton, start, e);
    refineBudget_ = 0;
    converged_ = false;
    pins_ = std::move(pins);
    contactPins_ = std::move(contactPins);
    x_ = model_ ? std::move(startX) : Eigen::VectorXd();
    if (model_ && (!solver_ || solver_->version() != model_)) solver_ = std::make_unique<ConstrainedIkSolver>(model_);
    latentPath_.clear();
    if (x_.size() > 0) latentPath_.push_back(x_);
    readout_ = {};
    comparePose_.reset();
}

std::vector<IkConstraint> DragSession::constraints() const {
    std::vector<IkConstraint> cs;
    cs.push_back({effector_, targetCm_, false});
    for (const IkConstraint& p : pins_)
        if (p.effector != effector_) cs.push_back(p);
    for (const IkConstraint& c : contactPins_)
        if (!holds(pins_, c.effector) && c.effector != effector_) cs.push_back(c);
    return cs;
}

void DragSession::dragTo(const Eigen::Vector3d& targetCm, int maxIterations) {
    if (!active_ || latent_ || !targetCm.allFinite()) return;
    targetCm_ = targetCm;
    refineBudget_ = kRefineBudgetIterations;
    readout_.iterations = 0;
    if (learned())
        solveLearned(maxIterations);
    else
        solvePlain();
    solveCompare();
}

bool DragSession::refine(int maxIterations) {
    if (!active_ || latent_ || !learned() || converged_ || refineBudget_ <= 0) return false;
    refineBudget_ -= maxIterations;
    const double before = result_.objective;
    solveLearned(maxIterations);
    // Stop refining once an extra round no longer changes F.
    if (std::abs(before - result_.objective) <= 1e-9 * std::max(1.0, std::abs(before))) converged_ = true;
    return true;
}

void DragSession::settle() {
    if (active_ && !latent_ && learned() && !converged_ && readout_.valid) solveLearned(kSettleIterations);
}

void DragSession::finish() {
    active_ = false;
    balance_.reset();
    latent_ = false;
    comparePose_.reset();
}

void DragSession::clear() {
    finish();
    forgetModel();
    readout_ = {};
}

void DragSession::forgetModel() {
    solver_.reset();
    model_.reset();
    latentPath_.clear();
}

void DragSession::solveLearned(int maxIterations) {
    request_.start = pose_;
    request_.startX = x_;
    request_.constraints = constraints();
    request_.maxIterations = maxIterations;
    request_.floorCm = floorCm_;
    request_.balance = balance_;
    request_.locality = locality_;
    request_.localityReference = startPose_;
    // The root rotation is held (stiffly) near where the drag began, not where the last event left it.
    request_.rootReferenceDeg =
        startPose_.anglesDeg.empty() ? std::nullopt : std::optional<Eigen::Vector3d>(startPose_.anglesDeg[0]);
    if (!solver_->validate(request_).empty()) return;
    solver_->solve(request_, result_);
    if (!allFinite(result_.pose) || !result_.x.allFinite()) return;  // keep the last good pose
    pose_ = result_.pose;
    x_ = result_.x;
    converged_ = result_.converged;
    if (latentPath_.empty() || (latentPath_.back() - x_).norm() > 1e-6) latentPath_.push_back(x_);
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
    if (capturedPosesOf_ != model_->model) {
        capturedPoses_ = model_->model->clipPoseMatrices();
        capturedPosesOf_ = model_->model;
    }
    // Every source clip is searched; the readout names the clip the nearest frame belongs to.
    const NearestFrame nearest = nearestFrame(layout_->extract(pose_), capturedPoses_);
    readout_.nearestClip = nearest.clip >= 0 ? model_->model->clipName(nearest.clip) : model_->model->clip.name;
    readout_.nearest = {nearest.frame, nearest.rmsDeg};
    readout_.comShiftCm = comShiftFromStart();
}

std::optional<double> DragSession::comShiftFromStart() const {
    const std::optional<Eigen::Vector3d> com = centreOfMass(*skeleton_, pose_);
    if (!com || !startCom_) return std::nullopt;
    return horizontalDistanceCm(*com, *startCom_);
}

void DragSession::solvePlain() {
    PlainIkJob job;
    job.skeleton = skeleton_;
    job.start = pose_;
    job.constraints = constraints();
    job.maxIterations = kPlainIterations;
    if (!job.validate().empty()) return;
    job.solve();
    if (!allFinite(job.pose)) return;
    pose_ = job.pose;
    converged_ = true;
    readout_.valid = true;
    readout_.learned = false;
    readout_.constraints = job.results;
    readout_.reached = job.reached;
    readout_.sigma2 = readout_.lik = 0.0;
    readout_.iterations = job.iterations;
    readout_.diagnostic = "plain IK (no model): " + job.diagnostic;
    readout_.comShiftCm = comShiftFromStart();
}

void DragSession::setCompare(CompareMode mode, gp::ModelVersionPtr compareModel, int frame) {
    compare_ = mode;
    compareModel_ = std::move(compareModel);
    compareFrame_ = frame;
    comparePose_.reset();
    if (active_ && !latent_) solveCompare();
}

void DragSession::solveCompare() {
    comparePose_.reset();
    if (!active_ || latent_ || compare_ == CompareMode::kNone) return;
    if (compare_ == CompareMode::kPlainIk) {
        PlainIkJob job;
        job.skeleton = skeleton_;
        job.start = startPose_;
        job.constraints = constraints();
        if (!job.validate().empty()) return;
        job.solve();
        if (allFinite(job.pose)) comparePose_ = job.pose;
        return;
    }
    if (!compareModel_) return;
    if (compareModel_->model->clip.skeleton.jointCount() != skeleton_->jointCount()) return;
    if (!compareSolver_ || compareSolver_->version() != compareModel_)
        compareSolver_ = std::make_unique<ConstrainedIkSolver>(compareModel_);
    ConstrainedIkRequest req;
    req.start = startPose_;
    req.startX =
        latentStartForFrame(*compareModel_, std::min(compareFrame_, compareModel_->model->clip.frameCount() - 1));
    req.constraints = constraints();
    req.maxIterations = kPlainIterations;
    if (!compareSolver_->validate(req).empty()) return;
    const ConstrainedIkResult r = compareSolver_->solve(req);
    if (allFinite(r.pose)) comparePose_ = r.pose;
}

void DragSession::beginLatent(const Skeleton& skeleton, gp::ModelVersionPtr model, Eigen::VectorXd x,
                              const Pose& pose) {
    skeleton_ = &skeleton;
    layout_.emplace(skeleton);
    model_ = std::move(model);
    active_ = false;
    latent_ = true;
    x_ = std::move(x);
    pose_ = pose;
    comparePose_.reset();
    latentPath_.clear();
    latentPath_.push_back(x_);
}

bool DragSession::latentTo(const Eigen::VectorXd& x, const Pose& base) {
    if (!latent_ || !model_ || !x.allFinite() || x.size() != x_.size()) return false;
    Eigen::VectorXd mean;
    double variance = 0.0;
    model_->posterior->predict(x, mean, variance);
    Pose p = base;
    layout_->apply(model_->model->fullPose(mean).data(), p);
    if (!allFinite(p)) return false;
    x_ = x;
    pose_ = p;
    latentPath_.push_back(x);
    return true;
}

}  // namespace mgp
