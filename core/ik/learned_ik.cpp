#include "ik/learned_ik.h"

#include <LBFGS.h>

#include <cmath>
#include <limits>

#include "gp/scg.h"

namespace mgp {

LearnedIkSolver::LearnedIkSolver(gp::ModelVersionPtr version)
    : version_(std::move(version)), layout_(version_->model->clip.skeleton) {
    const gp::GpModel& m = *version_->model;
    d_ = m.latentDim();
    D_ = m.D();
    full_.resize(layout_.size());
    gradFull_.resize(layout_.size());
    x_.resize(d_);
    y_.resize(D_);
    gx_.resize(d_);
    gy_.resize(D_);
    jac_.resize(3, layout_.size());
    bestZ_.resize(d_ + D_);
    scale_ = Eigen::VectorXd::Ones(d_ + D_);
    for (Eigen::VectorXd* v : {&zScaled_, &gScaled_, &z_, &u_, &gTmp_, &zProbe_}) v->resize(d_ + D_);
    gx_.setZero();
    gy_.setZero();
    lbfgsParam_.m = 8;
    lbfgsParam_.epsilon = 1e-12;
    lbfgsParam_.epsilon_rel = 1e-12;
    lbfgsParam_.linesearch = LBFGSpp::LBFGS_LINESEARCH_BACKTRACKING_STRONG_WOLFE;
    lbfgsParam_.max_linesearch = 40;
    lbfgsParam_.past = 5;
    lbfgsParam_.delta = 1e-7;
    lbfgs_ = std::make_unique<LBFGSpp::LBFGSSolver<double, CountingLineSearch>>(lbfgsParam_);
}

const char* learnedIkStopName(LearnedIkStop stop) {
    switch (stop) {
        case LearnedIkStop::kInvalidRequest: return "invalid request";
        case LearnedIkStop::kConverged: return "converged";
        case LearnedIkStop::kStalled: return "stalled";
        case LearnedIkStop::kIterationCap: return "iteration cap";
        case LearnedIkStop::kLineSearchFailed: return "line search";
    }
    return "?";
}

const char* learnedIkStopKey(LearnedIkStop stop) {
    switch (stop) {
        case LearnedIkStop::kInvalidRequest: return "invalid_request";
        case LearnedIkStop::kConverged: return "converged";
        case LearnedIkStop::kStalled: return "stalled";
        case LearnedIkStop::kIterationCap: return "iteration_cap";
        case LearnedIkStop::kLineSearchFailed: return "line_search_failed";
    }
    return "?";
}

void LearnedIkSolver::computeScaling(const Eigen::VectorXd& z0) {
    const gp::GpModel& m = *version_->model;
    const LearnedIkRequest& r = *request_;
    objective(z0, gTmp_);  // leaves FK and σ² of z0 in the workspace
    // y: λ·2·Σ_e ‖J_e,k‖² + (1 − λ)·w_k² / σ²(x0). gradFull_ is reused as the column-norm sum.
    const double s2 = pointWs_.variance;
    gradFull_.setZero();
    for (const IkConstraint& c : r.constraints) {
        effectorJacobian(m.clip.skeleton, layout_, fk_, pose_, c.effector, jac_);
        gradFull_.noalias() += jac_.colwise().squaredNorm().transpose();
    }
    for (int k = 0; k < D_; ++k) {
        const double h = 2.0 * r.lambda * gradFull_[m.keptColumns[k]] + (1.0 - r.lambda) * m.w[k] * m.w[k] / s2;
        scale_[d_ + k] = 1.0 / std::sqrt(std::max(h, 1e-12));
    }
    // x: central differences of the gradient (2d extra evaluations).
    for (int i = 0; i < d_; ++i) {
        const double h = 1e-4;
        zProbe_ = z0;
        zProbe_[i] += h;
        objective(zProbe_, gTmp_);
        const double gPlus = gTmp_[i];
        zProbe_[i] -= 2.0 * h;
        objective(zProbe_, gTmp_);
        const double curvature = std::abs(gPlus - gTmp_[i]) / (2.0 * h);
        scale_[i] = 1.0 / std::sqrt(std::max(curvature, 1e-6));
    }
    if (!scale_.allFinite()) scale_.setOnes();
}

std::string LearnedIkSolver::validate(const LearnedIkRequest& r) const {
    const Skeleton& sk = version_->model->clip.skeleton;
    if (static_cast<int>(r.start.anglesDeg.size()) != sk.jointCount())
        return "expected a start pose of the model's skeleton, found one with " +
               std::to_string(r.start.anglesDeg.size()) + " joints";
    if (r.startX.size() != d_)
        return "expected a " + std::to_string(d_) + "-D latent start, found " + std::to_string(r.startX.size());
    if (!r.startX.allFinite()) return "expected a finite latent start, found NaN or Inf";
    if (!r.start.rootCm.allFinite()) return "expected a finite root translation, found NaN or Inf";
    for (const auto& a : r.start.anglesDeg)
        if (!a.allFinite()) return "expected a finite start pose, found NaN or Inf";
    if (!(r.lambda > 0.0 && r.lambda < 1.0)) return "expected 0 < λ < 1, found " + std::to_string(r.lambda);
    if (r.maxIterations < 1) return "expected at least 1 iteration, found " + std::to_string(r.maxIterations);
    return validateConstraints(sk, r.constraints);
}

void LearnedIkSolver::bind(const LearnedIkRequest& request) {
    request_ = &request;
    pose_ = request.start;
    layout_.extract(request.start, full_.data());
    const gp::GpModel& m = *version_->model;
    for (std::size_t k = 0; k < m.constantColumns.size(); ++k) full_[m.constantColumns[k]] = m.constantValues[k];
    bestF_ = std::numeric_limits<double>::infinity();
    evaluations_ = 0;
}

double LearnedIkSolver::objective(const Eigen::VectorXd& z, Eigen::VectorXd& grad) {
    const gp::GpModel& m = *version_->model;
    const LearnedIkRequest& r = *request_;
    ++evaluations_;
    x_ = z.head(d_);
    y_ = z.tail(D_);
    const double lik = version_->posterior->evaluate(x_, y_, pointWs_, &gx_, &gy_);
    for (int k = 0; k < D_; ++k) full_[m.keptColumns[k]] = y_[k];
    layout_.apply(full_.data(), pose_);
    forwardKinematics(m.clip.skeleton, pose_, fk_);
    double constraintCost = 0.0;
    gradFull_.setZero();
    for (const IkConstraint& c : r.constraints) {
        const Eigen::Vector3d res = effectorCm(m.clip.skeleton, fk_, c.effector) - c.targetCm;
        constraintCost += res.squaredNorm();
        effectorJacobian(m.clip.skeleton, layout_, fk_, pose_, c.effector, jac_);
        gradFull_.noalias() += 2.0 * jac_.transpose() * res;
    }
    const double F = (1.0 - r.lambda) * lik + r.lambda * constraintCost;
    grad.resize(d_ + D_);
    grad.head(d_) = (1.0 - r.lambda) * gx_;
    for (int k = 0; k < D_; ++k) grad[d_ + k] = (1.0 - r.lambda) * gy_[k] + r.lambda * gradFull_[m.keptColumns[k]];
    if (!std::isfinite(F) || !grad.allFinite()) {
        grad.setZero();
        return std::numeric_limits<double>::infinity();  // the line search backs off
    }
    if (F < bestF_) {
        bestF_ = F;
        bestZ_ = z;
    }
    return F;
}

void LearnedIkSolver::solve(const LearnedIkRequest& request, LearnedIkResult& result) {
    result.constraints.clear();
    result.reached = result.converged = false;
    result.iterations = result.evaluations = 0;
    result.pose = request.start;
    result.x = request.startX;
    result.stop = LearnedIkStop::kInvalidRequest;
    if (const std::string problem = validate(request); !problem.empty()) {
        result.diagnostic = problem;
        result.objective = result.lik = result.sigma2 = std::numeric_limits<double>::quiet_NaN();
        return;
    }
    bind(request);
    const gp::GpModel& m = *version_->model;
    z_.head(d_) = request.startX;
    for (int k = 0; k < D_; ++k) z_[d_ + k] = full_[m.keptColumns[k]];
    // The solver reads these through its reference at minimize() time.
    lbfgsParam_.past = std::max(1, request.stallWindow);
    lbfgsParam_.delta = std::max(0.0, request.stallRelative);
    lbfgsParam_.max_iterations = request.maxIterations;
    if (request.precondition)
        computeScaling(z_);
    else
        scale_.setOnes();
    // L-BFGS runs on u = S⁻¹ z. The functor carries the line-search counter CountingLineSearch
    // increments.
    int lineSearches = 0;
    struct Objective {
        LearnedIkSolver* self;
        int* lineSearches;
        double operator()(const Eigen::VectorXd& u, Eigen::VectorXd& g) {
            self->zScaled_ = self->scale_.cwiseProduct(u);
            const double F = self->objective(self->zScaled_, self->gScaled_);
            g = self->scale_.cwiseProduct(self->gScaled_);
            return F;
        }
    } f{this, &lineSearches};
    u_ = z_.cwiseQuotient(scale_);
    double fz = 0.0;
    try {
        result.iterations = lbfgs_->minimize(f, u_, fz);
        result.stop =
            result.iterations >= request.maxIterations ? LearnedIkStop::kIterationCap : LearnedIkStop::kStalled;
        result.diagnostic = learnedIkStopName(result.stop);
    } catch (const std::exception& e) {
        result.stop = LearnedIkStop::kLineSearchFailed;
        result.diagnostic = std::string("line search: ") + e.what();
        // The failed line search's iteration did not complete.
        result.iterations = std::max(0, lineSearches - 1);
    }
    result.evaluations = evaluations_;
    // Residuals with stableNorm: a target ~1e200 cm away must give a finite (huge) residual, not
    // Inf from squaring.
    auto fillConstraints = [&](bool& tight) {
        result.reached = true;
        tight = true;
        for (const IkConstraint& c : request.constraints) {
            IkConstraintResult cr;
            cr.effector = c.effector;
            cr.pin = c.pin;
            cr.residualCm = (effectorCm(m.clip.skeleton, fk_, c.effector) - c.targetCm).stableNorm();
            cr.reached = cr.residualCm <= kReachedToleranceCm;
            result.reached = result.reached && cr.reached;
            tight = tight && cr.residualCm < request.convergedResidualCm;
            result.constraints.push_back(cr);
        }
    };
    if (!std::isfinite(bestF_)) {  // nothing finite was ever seen (F overflowed): keep the start
        result.diagnostic += "; no finite objective";
        result.objective = std::numeric_limits<double>::quiet_NaN();
        // Still report the start's residuals (not reached) and prior terms: before, the
        // constraint list came back empty and `pose` printed no target at all.
        const Eigen::VectorXd y0 = z_.tail(D_);
        result.y = y0;
        result.lik = version_->posterior->evaluate(request.startX, y0, pointWs_, nullptr, nullptr);
        result.sigma2 = pointWs_.variance;
        forwardKinematics(m.clip.skeleton, request.start, fk_);
        bool tight = false;
        fillConstraints(tight);
        return;
    }
    // Re-evaluate at the best point so every output matches it exactly.
    zProbe_ = bestZ_;
    result.objective = objective(zProbe_, gTmp_);
    result.x = zProbe_.head(d_);
    result.y = zProbe_.tail(D_);
    result.pose = pose_;
    result.sigma2 = pointWs_.variance;
    result.lik = version_->posterior->evaluate(x_, y_, pointWs_, nullptr, nullptr);
    bool tight = true;
    fillConstraints(tight);
    result.converged = tight && result.stop == LearnedIkStop::kStalled;
    if (result.converged) {
        result.stop = LearnedIkStop::kConverged;
        result.diagnostic = learnedIkStopName(result.stop);
    }
}

LearnedIkResult LearnedIkSolver::solve(const LearnedIkRequest& request) {
    LearnedIkResult r;
    solve(request, r);
    return r;
}

Eigen::VectorXd latentStartForFrame(const gp::ModelVersion& version, int frame) {
    const gp::GpModel& m = *version.model;
    // `frame` is a frame of the primary clip: only its rows count (another clip's frame numbers
    // say nothing about it). A multi-clip model has at least one row of every clip.
    const int nearest = m.primaryRowNearest(frame);
    if (m.rowClip(nearest) == 0 && m.trainingFrames[static_cast<std::size_t>(nearest)] == frame)
        return m.X.row(nearest).transpose();
    const PoseLayout layout(m.clip.skeleton);
    const Eigen::VectorXd y = m.keptPose(layout.extract(m.clip.frames[frame]));
    const gp::ValueAndGradient fg = [&](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
        return version.posterior->evaluate(x, y, &g, nullptr);
    };
    gp::ScgOptions options;
    options.maxIterations = 200;
    return gp::scgMinimize(fg, m.X.row(nearest).transpose(), options).x;
}

}  // namespace mgp
