#include "motion/span_solver.h"

#include <LBFGS.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "ik/ik_types.h"
#include "ik/learned_ik.h"
#include "ik/locality.h"

namespace mgp {

const char* spanStopName(SpanStop s) {
    switch (s) {
        case SpanStop::kConverged: return "converged";
        case SpanStop::kStalled: return "stalled";
        case SpanStop::kIterationCap: return "iteration cap";
        case SpanStop::kLineSearch: return "line search";
        case SpanStop::kCancelled: return "cancelled";
        case SpanStop::kInvalid: return "invalid";
    }
    return "?";
}

SpanSolver::SpanSolver(gp::ModelVersionPtr version, int first, int last, SpanWeights weights, const EditBase* base)
    : version_(std::move(version)), layout_(version_->model->clip.skeleton), w_(weights), first_(first), last_(last) {
    const gp::GpModel& m = *version_->model;
    const std::vector<Pose>& motion = base ? base->frames : m.clip.frames;
    frames_ = static_cast<int>(motion.size());
    if (first < 0 || last >= frames_ || first + 1 >= last)
        throw std::invalid_argument("expected a span first < last − 1 inside the clip's " + std::to_string(frames_) +
                                    " frames, found " + std::to_string(first + 1) + ".." + std::to_string(last + 1));
    if (!(w_.lambda > 0.0 && w_.lambda < 1.0))
        throw std::invalid_argument("expected 0 < λ < 1, found " + std::to_string(w_.lambda));
    if (!(w_.locality >= 0.0) || !std::isfinite(w_.locality))
        throw std::invalid_argument("expected a locality ≥ 0, found " + std::to_string(w_.locality));
    n_ = last - first - 1;
    d_ = m.latentDim();
    D_ = m.D();
    kappa_ = (1.0 - w_.lambda) / w_.lambda;
    full_.resize(layout_.size());
    gradFull_.resize(layout_.size());
    xt_.resize(d_);
    yt_.resize(D_);
    gx_.resize(d_);
    gy_.resize(D_);
    jac_.resize(3, layout_.size());
    for (int k = 0; k < D_; ++k)
        if (m.keptColumns[k] < 3) rootKept_.push_back(k);
    // Captured (or base) x̂, ŷ on frames first−1..last+1 (those inside the clip; others stay empty).
    xCap_.assign(n_ + 4, Eigen::VectorXd());
    yCap_.assign(n_ + 4, Eigen::VectorXd());
    // A base of another length is another clip of the model's skeleton (in-betweening): its
    // frames are not the model clip's, so their latent points must come with it.
    const bool otherClip = frames_ != m.clip.frameCount();
    if (base && !base->x.empty() && static_cast<int>(base->x.size()) != frames_)
        throw std::invalid_argument("expected a base latent point per frame (" + std::to_string(frames_) + "), found " +
                                    std::to_string(base->x.size()));
    innerBase_.clear();
    for (int t = first - 1; t <= last + 1; ++t) {
        if (t < 0 || t >= frames_) continue;
        yCap_[t - first + 1] = m.keptPose(layout_.extract(motion[t]));
        // Only inner frames need x̂ (outer frames have v = 0 by definition).
        if (t > first && t < last) {
            innerBase_.push_back(motion[t]);
            const bool known = base && !base->x.empty() && base->x[t].size() == d_;
            if (!known && otherClip)
                throw std::invalid_argument("expected a latent point for frame " + std::to_string(t + 1) +
                                            " of a base motion that is not the model's clip, found none");
            xCap_[t - first + 1] = known ? base->x[t] : latentStartForFrame(*version_, t);
        }
    }
    resid_.assign(n_, Eigen::VectorXd::Zero(D_));
    z0_.resize(variableCount());
    const int b = d_ + D_;
    for (int i = 0; i < n_; ++i) {
        const int c = i + 2;  // index of inner frame i in the captured arrays
        z0_.segment(i * b, d_) = xCap_[c];
        z0_.segment(i * b + d_, D_) = yCap_[c];
        if (w_.keepResidual) {
            Eigen::VectorXd mean;
            double var = 0.0;
            version_->posterior->predict(xCap_[c], mean, var);
            resid_[i] = yCap_[c] - mean;
        }
    }
    targetsOf_.assign(n_, {});
    stay_ = Eigen::VectorXd::Constant(D_, w_.stay);
    scale_ = Eigen::VectorXd::Ones(variableCount());
    priorGx_.assign(n_, Eigen::VectorXd::Zero(d_));
    priorGy_.assign(n_, Eigen::VectorXd::Zero(D_));
    priorVar_.assign(n_, 1.0);
}

std::string validateEditBase(const gp::GpModel& model, const EditBase& base) {
    const int n = model.clip.frameCount();
    if (static_cast<int>(base.frames.size()) != n)
        return "expected a base motion of " + std::to_string(n) + " frames, found " +
               std::to_string(base.frames.size());
    if (!base.x.empty() && base.x.size() != base.frames.size())
        return "expected a base latent point per frame, found " + std::to_string(base.x.size());
    for (const Pose& p : base.frames)
        if (static_cast<int>(p.anglesDeg.size()) != model.clip.skeleton.jointCount() || !allFinite(p))
            return "expected a finite base motion of the model's skeleton";
    for (const Eigen::VectorXd& x : base.x)
        if (x.size() != 0 && (x.size() != model.latentDim() || !x.allFinite()))
            return "expected base latent points of " + std::to_string(model.latentDim()) + " finite values";
    if (!base.holdFrames.empty() && base.holdFrames.size() != base.frames.size())
        return "expected a hold pose per frame, found " + std::to_string(base.holdFrames.size());
    for (const Pose& p : base.holdFrames)
        if (static_cast<int>(p.anglesDeg.size()) != model.clip.skeleton.jointCount() || !allFinite(p))
            return "expected finite hold poses of the model's skeleton";
    if (!base.placedFrames.empty() && base.placedFrames.size() != base.frames.size())
        return "expected a placement pose per frame, found " + std::to_string(base.placedFrames.size());
    for (const Pose& p : base.placedFrames)
        if (static_cast<int>(p.anglesDeg.size()) != model.clip.skeleton.jointCount() || !allFinite(p))
            return "expected finite placement poses of the model's skeleton";
    return "";
}

std::string SpanSolver::validate(const std::vector<SpanTarget>& targets) const {
    const Skeleton& sk = version_->model->clip.skeleton;
    for (const SpanTarget& t : targets) {
        if (t.frame <= first_ || t.frame >= last_)
            return "expected target frames in " + std::to_string(first_ + 2) + ".." + std::to_string(last_) +
                   ", found " + std::to_string(t.frame + 1);
        if (!t.targetCm.allFinite()) return "expected finite targets, found NaN or Inf";
        if (!sk.hasEffector(t.effector))
            return std::string("expected an effector of this skeleton, found ") + effectorName(t.effector);
    }
    return "";
}

void SpanSolver::setTargets(std::vector<SpanTarget> targets) {
    if (const std::string p = validate(targets); !p.empty()) throw std::invalid_argument(p);
    targets_ = std::move(targets);
    targetsOf_.assign(n_, {});
    for (std::size_t k = 0; k < targets_.size(); ++k)
        targetsOf_[targets_[k].frame - first_ - 1].push_back(static_cast<int>(k));
    targetJac_.assign(targets_.size(), Eigen::MatrixXd::Zero(3, D_));
    std::vector<Effector> edited;
    for (const SpanTarget& t : targets_)
        if (t.kind == SpanTarget::Kind::kPath && std::find(edited.begin(), edited.end(), t.effector) == edited.end())
            edited.push_back(t.effector);
    const gp::GpModel& m = *version_->model;
    const std::vector<double> lw = localityWeights(m.clip.skeleton, edited);
    // κ/2: the constrained IK's ½ℓ‖·‖² beside L_IK, here beside κ·L_IK, so one ℓ means the same.
    for (int k = 0; k < D_; ++k) stay_[k] = w_.stay + 0.5 * kappa_ * w_.locality * lw[m.keptColumns[k]];
    lastZ_.resize(0);
    computeScaling();
}

std::string SpanSolver::holdFrame(int frame, const Pose& pose, const Eigen::VectorXd& x) {
    const gp::GpModel& m = *version_->model;
    if (frame <= first_ || frame >= last_)
        return "expected a held frame in " + std::to_string(first_ + 2) + ".." + std::to_string(last_) + ", found " +
               std::to_string(frame + 1);
    if (static_cast<int>(pose.anglesDeg.size()) != m.clip.skeleton.jointCount())
        return "expected a held pose of the model's skeleton, found one with " + std::to_string(pose.anglesDeg.size()) +
               " joints";
    if (x.size() != d_)
        return "expected a " + std::to_string(d_) + "-D held latent point, found " + std::to_string(x.size());
    if (!x.allFinite() || !allFinite(pose)) return "expected a finite held pose, found NaN or Inf";
    heldInner_ = frame - first_ - 1;
    heldPose_ = pose;
    const int b = d_ + D_;
    z0_.segment(heldInner_ * b, d_) = x;
    z0_.segment(heldInner_ * b + d_, D_) = m.keptPose(layout_.extract(pose));
    lastZ_.resize(0);
    computeScaling();
    return "";
}

std::string SpanSolver::holdEnd(int frame, const Pose& pose) {
    const gp::GpModel& m = *version_->model;
    if (frame != first_ && frame != last_)
        return "expected the span's first or last frame (" + std::to_string(first_ + 1) + " or " +
               std::to_string(last_ + 1) + "), found " + std::to_string(frame + 1);
    if (static_cast<int>(pose.anglesDeg.size()) != m.clip.skeleton.jointCount() || !allFinite(pose))
        return "expected a finite end pose of the model's skeleton";
    (frame == first_ ? uFirst_ : uLast_) = m.keptPose(layout_.extract(pose)) - yCap_[frame - first_ + 1];
    lastZ_.resize(0);
    return "";
}

void SpanSolver::poseOf(int i, const Eigen::VectorXd& z, Pose& pose) {
    if (i == heldInner_) {  // exactly the held pose, also what the layout does not cover
        pose = heldPose_;
        return;
    }
    const gp::GpModel& m = *version_->model;
    pose = innerBase_[static_cast<std::size_t>(i)];  // the root translation and what the layout does not cover
    layout_.extract(pose, full_.data());
    for (std::size_t k = 0; k < m.constantColumns.size(); ++k) full_[m.constantColumns[k]] = m.constantValues[k];
    const auto y = z.segment(i * (d_ + D_) + d_, D_);
    for (int k = 0; k < D_; ++k) full_[m.keptColumns[k]] = y[k];
    layout_.apply(full_.data(), pose);
}

double SpanSolver::objective(const Eigen::VectorXd& z, Eigen::VectorXd& grad) {
    const gp::GpModel& m = *version_->model;
    const Skeleton& sk = m.clip.skeleton;
    const int b = d_ + D_;
    grad.setZero(z.size());
    double F = 0.0;
    for (int i = 0; i < n_; ++i) {
        const int c = i + 2;
        xt_ = z.segment(i * b, d_);
        yt_ = z.segment(i * b + d_, D_) - resid_[i];
        F += kappa_ * version_->posterior->evaluate(xt_, yt_, pointWs_, &gx_, &gy_);
        priorGx_[i] = gx_;
        priorGy_[i] = gy_;
        priorVar_[i] = pointWs_.variance;
        grad.segment(i * b, d_) += kappa_ * gx_;
        grad.segment(i * b + d_, D_) += kappa_ * gy_;
        // Stay near the capture: every DOF a little, the root orientation more.
        const auto u = z.segment(i * b + d_, D_) - yCap_[c];
        F += u.dot(stay_.cwiseProduct(u));
        grad.segment(i * b + d_, D_) += 2.0 * stay_.cwiseProduct(u);
        const auto v = z.segment(i * b, d_) - xCap_[c];
        F += w_.stayLatent * v.squaredNorm();
        grad.segment(i * b, d_) += 2.0 * w_.stayLatent * v;
        for (int k : rootKept_) {
            F += w_.root * u[k] * u[k];
            grad[i * b + d_ + k] += 2.0 * w_.root * u[k];
        }
        if (targetsOf_[i].empty()) continue;
        poseOf(i, z, pose_);
        forwardKinematics(sk, pose_, fk_);
        gradFull_.setZero();
        for (int k : targetsOf_[i]) {
            const SpanTarget& tg = targets_[k];
            const Eigen::Vector3d res = effectorCm(sk, fk_, tg.effector) - tg.targetCm;
            F += w_.target * res.squaredNorm();
            effectorJacobian(sk, layout_, fk_, pose_, tg.effector, jac_);
            gradFull_.noalias() += 2.0 * w_.target * jac_.transpose() * res;
            for (int c = 0; c < D_; ++c) targetJac_[k].col(c) = jac_.col(m.keptColumns[c]);
        }
        for (int k = 0; k < D_; ++k) grad[i * b + d_ + k] += gradFull_[m.keptColumns[k]];
    }
    // Second differences of u and v, centres first..last (those with both neighbours in the clip).
    const int frames = frames_;
    auto uAt = [&](int t, Eigen::VectorXd& out) {  // u at frame t (0 outside the span, but a held end's)
        if (t > first_ && t < last_)
            out = z.segment((t - first_ - 1) * b + d_, D_) - yCap_[t - first_ + 1];
        else if (t == first_ && uFirst_.size() == D_)
            out = uFirst_;
        else if (t == last_ && uLast_.size() == D_)
            out = uLast_;
        else
            out.setZero(D_);
    };
    auto vAt = [&](int t, Eigen::VectorXd& out) {
        if (t > first_ && t < last_)
            out = z.segment((t - first_ - 1) * b, d_) - xCap_[t - first_ + 1];
        else
            out.setZero(d_);
    };
    Eigen::VectorXd a, bb, cc, acc;
    // w‖q(s−1) − 2q(s) + q(s+1)‖² for one block of variables (q = u or v, at `offset` in a frame's
    // block, `size` long) and its gradient on the frames strictly inside the span.
    auto addSecondDifference = [&](int s, const auto& at, double w, int offset, int size) {
        const double ws[3] = {1.0, -2.0, 1.0};
        at(s - 1, a);
        at(s, bb);
        at(s + 1, cc);
        acc = a - 2.0 * bb + cc;
        F += w * acc.squaredNorm();
        for (int j = 0; j < 3; ++j) {
            const int t = s - 1 + j;
            if (t > first_ && t < last_) grad.segment((t - first_ - 1) * b + offset, size) += 2.0 * w * ws[j] * acc;
        }
    };
    for (int s = first_; s <= last_; ++s) {
        if (s - 1 < 0 || s + 1 >= frames) continue;
        addSecondDifference(s, uAt, w_.smoothPose, d_, D_);
        addSecondDifference(s, vAt, w_.smoothLatent, 0, d_);
    }
    if (heldInner_ >= 0) grad.segment(heldInner_ * b, b).setZero();  // constants, not unknowns
    if (!std::isfinite(F) || !grad.allFinite()) {
        grad.setZero();
        lastZ_.resize(0);
        return std::numeric_limits<double>::infinity();
    }
    lastZ_ = z;
    return F;
}

void SpanSolver::computeScaling() {
    // Diagonal curvature at the captured span: y analytically (prior w²/σ², targets' Jacobian
    // column norms, stay/root, the smoothness band's diagonal 6·s_y), x by central differences of
    // the prior's gradient plus 6·s_x.
    const gp::GpModel& m = *version_->model;
    const Skeleton& sk = m.clip.skeleton;
    const int b = d_ + D_;
    Eigen::VectorXd g1(d_), g2(d_), xp(d_);
    for (int i = 0; i < n_; ++i) {
        const int c = i + 2;
        xt_ = z0_.segment(i * b, d_);
        yt_ = z0_.segment(i * b + d_, D_) - resid_[i];
        version_->posterior->evaluate(xt_, yt_, pointWs_, nullptr, nullptr);
        const double s2 = pointWs_.variance;
        gradFull_.setZero();
        if (!targetsOf_[i].empty()) {
            poseOf(i, z0_, pose_);
            forwardKinematics(sk, pose_, fk_);
            for (int k : targetsOf_[i]) {
                effectorJacobian(sk, layout_, fk_, pose_, targets_[k].effector, jac_);
                gradFull_.noalias() += w_.target * jac_.colwise().squaredNorm().transpose();
            }
        }
        for (int k = 0; k < D_; ++k) {
            double h = kappa_ * m.w[k] * m.w[k] / s2 + 2.0 * gradFull_[m.keptColumns[k]] + 2.0 * stay_[k] +
                       12.0 * w_.smoothPose;
            if (m.keptColumns[k] < 3) h += 2.0 * w_.root;
            scale_[i * b + d_ + k] = 1.0 / std::sqrt(h);
        }
        for (int j = 0; j < d_; ++j) {
            const double h = 1e-4;
            xp = xt_;
            xp[j] += h;
            version_->posterior->evaluate(xp, yt_, pointWs_, &g1, nullptr);
            xp[j] -= 2.0 * h;
            version_->posterior->evaluate(xp, yt_, pointWs_, &g2, nullptr);
            const double curv =
                kappa_ * std::abs(g1[j] - g2[j]) / (2.0 * h) + 12.0 * w_.smoothLatent + 2.0 * w_.stayLatent;
            scale_[i * b + j] = 1.0 / std::sqrt(std::max(curv, 1e-9));
        }
        (void)c;
    }
    if (!scale_.allFinite()) scale_.setOnes();
}

SpanResult SpanSolver::solveLbfgs(int maxIterations, double relativeTolerance, const std::atomic<bool>* cancel) {
    SpanResult r;
    LBFGSpp::LBFGSParam<double> param;
    param.m = 10;
    param.epsilon = 1e-10;
    param.epsilon_rel = 1e-10;
    param.past = 3;
    param.delta = relativeTolerance;
    param.max_iterations = maxIterations;
    param.max_linesearch = 40;
    param.linesearch = LBFGSpp::LBFGS_LINESEARCH_BACKTRACKING_STRONG_WOLFE;
    LBFGSpp::LBFGSSolver<double> lbfgs(param);
    Eigen::VectorXd zs(z0_.size()), gs(z0_.size()), best = z0_;
    double bestF = std::numeric_limits<double>::infinity();
    int evaluations = 0;
    struct Cancelled {};
    auto f = [&](const Eigen::VectorXd& u, Eigen::VectorXd& g) {
        if (cancel && cancel->load()) throw Cancelled{};
        zs = scale_.cwiseProduct(u);
        const double F = objective(zs, gs);
        ++evaluations;
        if (F < bestF) {
            bestF = F;
            best = zs;
        }
        g = scale_.cwiseProduct(gs);
        return F;
    };
    Eigen::VectorXd u = z0_.cwiseQuotient(scale_);
    double fx = 0.0;
    try {
        r.iterations = lbfgs.minimize(f, u, fx);
        r.stop = r.iterations >= maxIterations ? SpanStop::kIterationCap : SpanStop::kConverged;
    } catch (const Cancelled&) {
        r.stop = SpanStop::kCancelled;
        r.diagnostic = "cancelled";
    } catch (const std::exception& e) {
        // LBFGS++ gives up when the line search cannot make progress, typically at the noise
        // floor of F; the best point seen is kept.
        r.stop = SpanStop::kLineSearch;
        r.diagnostic = e.what();
        r.iterations = -1;
    }
    r.evaluations = evaluations;
    if (!std::isfinite(bestF)) {
        r.stop = SpanStop::kInvalid;
        r.diagnostic = "no finite objective";
        best = z0_;
    }
    return finish(std::move(r), best);
}

SpanResult SpanSolver::finish(SpanResult r, const Eigen::VectorXd& best) {
    const int b = d_ + D_;
    Eigen::VectorXd gs;
    r.objective = objective(best, gs);
    r.poses.resize(n_);
    r.x.resize(n_);
    r.y.resize(n_);
    r.lik.resize(n_);
    for (int i = 0; i < n_; ++i) {
        poseOf(i, best, r.poses[i]);
        r.x[i] = best.segment(i * b, d_);
        r.y[i] = best.segment(i * b + d_, D_);
        r.lik[i] = version_->posterior->evaluate(r.x[i], Eigen::VectorXd(r.y[i] - resid_[i]), nullptr, nullptr);
    }
    r.targetResidualCm = targetResidualsCm(best);
    return r;
}

void SpanSolver::assemble(const Eigen::VectorXd& z, BlockBandedMatrix& h) {
    const gp::GpModel& m = *version_->model;
    const int b = d_ + D_;
    // The caches must describe z (objective() ran there last).
    if (lastZ_.size() != z.size() || lastZ_ != z) {
        Eigen::VectorXd g;
        objective(z, g);
    }
    h.setZero();
    Eigen::VectorXd gxp(d_), gyp(D_), xp(d_);
    for (int i = 0; i < n_; ++i) {
        Eigen::Ref<Eigen::MatrixXd> hii = h.block(i, i);
        xt_ = z.segment(i * b, d_);
        yt_ = z.segment(i * b + d_, D_) - resid_[i];
        // Prior y–y block, exact: ∂²L_IK/∂y² = W²/σ²(x).
        for (int k = 0; k < D_; ++k) hii(d_ + k, d_ + k) += kappa_ * m.w[k] * m.w[k] / priorVar_[i];
        // Prior x–x and y–x blocks: forward differences of the analytic gradient in x.
        for (int j = 0; j < d_; ++j) {
            const double step = 1e-6 * std::max(1.0, std::abs(xt_[j]));
            xp = xt_;
            xp[j] += step;
            version_->posterior->evaluate(xp, yt_, pointWs_, &gxp, &gyp);
            hii.col(j).head(d_) += kappa_ * (gxp - priorGx_[i]) / step;
            hii.col(j).tail(D_) += kappa_ * (gyp - priorGy_[i]) / step;
        }
        // Symmetrise the x–x block, mirror x–y, and make the prior's block positive semidefinite:
        // its y–y part is positive, so it is PSD iff the Schur complement S = Hxx − Hxy Hyy⁻¹ Hyx
        // is; S's negative eigenvalues (ln σ² is not convex) are raised to a small positive
        // floor. Otherwise Cholesky would need a large damping on every variable.
        Eigen::MatrixXd hxx = hii.topLeftCorner(d_, d_);
        hxx = 0.5 * (hxx + hxx.transpose());
        const Eigen::MatrixXd hyx = hii.bottomLeftCorner(D_, d_);
        const Eigen::VectorXd hyyInv = hii.diagonal().tail(D_).cwiseInverse();
        const Eigen::MatrixXd coupling = hyx.transpose() * hyyInv.asDiagonal() * hyx;
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(hxx - coupling);
        const Eigen::VectorXd lam = eig.eigenvalues().cwiseMax(kappa_ * 1e-3);
        hii.topLeftCorner(d_, d_) = eig.eigenvectors() * lam.asDiagonal() * eig.eigenvectors().transpose() + coupling;
        hii.topRightCorner(d_, D_) = hyx.transpose();
        for (int k = 0; k < D_; ++k) hii(d_ + k, d_ + k) += 2.0 * stay_[k];
        for (int k = 0; k < d_; ++k) hii(k, k) += 2.0 * w_.stayLatent;
        for (int k : rootKept_) hii(d_ + k, d_ + k) += 2.0 * w_.root;
        for (int k : targetsOf_[i])
            hii.bottomRightCorner(D_, D_).noalias() += 2.0 * w_.target * targetJac_[k].transpose() * targetJac_[k];
    }
    // Smoothness: Σ_s ‖Σ_j c_j u_{s−1+j}‖² adds 2·s·c_a·c_b·I to block (a, b).
    const int frames = frames_;
    const double c[3] = {1.0, -2.0, 1.0};
    for (int s = first_; s <= last_; ++s) {
        if (s - 1 < 0 || s + 1 >= frames) continue;
        for (int p = 0; p < 3; ++p)
            for (int q = 0; q <= p; ++q) {
                const int ta = s - 1 + p, tb = s - 1 + q;  // ta ≥ tb
                if (ta <= first_ || ta >= last_ || tb <= first_ || tb >= last_) continue;
                Eigen::Ref<Eigen::MatrixXd> blk = h.block(ta - first_ - 1, tb - first_ - 1);
                for (int k = 0; k < d_; ++k) blk(k, k) += 2.0 * w_.smoothLatent * c[p] * c[q];
                for (int k = 0; k < D_; ++k) blk(d_ + k, d_ + k) += 2.0 * w_.smoothPose * c[p] * c[q];
            }
    }
    if (heldInner_ >= 0) {
        // The held frame's rows and columns: identity on the diagonal, nothing coupling it, so
        // with its zero gradient the factorised step is exactly zero there.
        for (int j = std::max(0, heldInner_ - 2); j <= std::min(n_ - 1, heldInner_ + 2); ++j)
            (j >= heldInner_ ? h.block(j, heldInner_) : h.block(heldInner_, j)).setZero();
        h.block(heldInner_, heldInner_).setIdentity();
    }
}

namespace {
constexpr double kMaxStepDeg = 20.0;
}  // namespace

std::vector<double> SpanSolver::targetResidualsCm(const Eigen::VectorXd& z) {
    const Skeleton& sk = version_->model->clip.skeleton;
    std::vector<double> out(targets_.size());
    int posed = -1;
    for (std::size_t k = 0; k < targets_.size(); ++k) {
        const SpanTarget& t = targets_[k];
        if (t.frame - first_ - 1 != posed) poseOf(posed = t.frame - first_ - 1, z, pose_);
        out[k] = (effectorCm(sk, pose_, t.effector) - t.targetCm).norm();
    }
    return out;
}

bool SpanSolver::targetsStalled(const std::vector<double>& startCm, const std::vector<double>& nowCm, double relative) {
    bool missed = false;
    for (std::size_t k = 0; k < nowCm.size() && k < startCm.size(); ++k) {
        if (!(nowCm[k] > kReachedToleranceCm)) continue;
        const double now = nowCm[k] * nowCm[k], moved = std::abs(startCm[k] * startCm[k] - now);
        if (!(moved < relative * now || std::abs(startCm[k] - nowCm[k]) < kStallStepCm))
            return false;  // still closing in, newly missed, or drifting away: the solve is moving
        missed = true;
    }
    return missed;
}

SpanResult SpanSolver::solveLm(int maxIterations, double relativeTolerance, const std::atomic<bool>* cancel) {
    SpanResult r;
    const int N = variableCount();
    Eigen::VectorXd z = z0_, g(N), zTrial(N), gTrial(N), step(N);
    double F = objective(z, g);
    int evaluations = 1;
    if (!std::isfinite(F)) {
        r.stop = SpanStop::kInvalid;
        r.diagnostic = "no finite objective at the captured span";
        r.evaluations = evaluations;
        return finish(std::move(r), z0_);
    }
    BlockBandedMatrix h(n_, d_ + D_, 2), chol;
    double mu = 1e-6;
    r.stop = SpanStop::kIterationCap;
    int it = 0;
    std::vector<double> windowStart = targetResidualsCm(z);  // the stall test's window
    int windowSteps = 0;
    for (; it < maxIterations; ++it) {
        if (cancel && cancel->load()) {
            r.stop = SpanStop::kCancelled;
            break;
        }
        assemble(z, h);
        bool accepted = false;
        double decrease = 0.0;
        for (int tries = 0; tries < 14 && !accepted; ++tries) {
            if (!chol.factor(h, mu, 1e-9)) {
                mu = std::max(mu * 10.0, 1e-6);
                continue;
            }
            step = chol.solve(g);
            // Trust region in joint space: no DOF turns more than kMaxStepDeg in one iteration.
            double largest = 0.0;
            for (int i = 0; i < n_; ++i)
                largest = std::max(largest, step.segment(i * (d_ + D_) + d_, D_).cwiseAbs().maxCoeff());
            if (largest > kMaxStepDeg) step *= kMaxStepDeg / largest;
            // Backtrack along the step before damping more: far from the solution the FK's
            // rotations make the full Gauss–Newton step overshoot, yet its direction is good.
            for (double alpha = 1.0; alpha > 0.05 && !accepted; alpha *= 0.5) {
                zTrial = z - alpha * step;
                const double Ft = objective(zTrial, gTrial);
                ++evaluations;
                if (std::isfinite(Ft) && Ft < F) {
                    decrease = F - Ft;
                    z.swap(zTrial);
                    g.swap(gTrial);
                    F = Ft;
                    accepted = true;
                    mu = alpha == 1.0 ? std::max(mu / 10.0, 1e-9) : mu;
                }
            }
            if (!accepted) mu = std::max(mu * 10.0, 1e-6);
        }
        if (!accepted) {  // no decrease at any damping: F's noise floor
            r.stop = SpanStop::kConverged;
            r.diagnostic = "no decrease";
            break;
        }
        if (decrease <= relativeTolerance * std::max(1.0, std::abs(F))) {
            r.stop = SpanStop::kConverged;
            ++it;
            break;
        }
        // A target out of reach: F still falls by about 1e-5 of itself per step as the limb
        // straightens, so the rule above can take hundreds of steps to fire while the missed
        // distance no longer changes.
        if (stallRelative_ > 0.0 && ++windowSteps == kStallWindow) {
            std::vector<double> now = targetResidualsCm(z);
            if (targetsStalled(windowStart, now, stallRelative_)) {
                r.stop = SpanStop::kStalled;
                r.diagnostic = "a target out of reach: its distance stalled";
                ++it;
                break;
            }
            windowStart = std::move(now);
            windowSteps = 0;
        }
    }
    r.iterations = it;
    r.evaluations = evaluations;
    return finish(std::move(r), z);
}

SpanResult SpanSolver::solve(int maxIterations, double relativeTolerance, const std::atomic<bool>* cancel,
                             SpanMethod method) {
    return method == SpanMethod::kLbfgs ? solveLbfgs(maxIterations, relativeTolerance, cancel)
                                        : solveLm(maxIterations, relativeTolerance, cancel);
}

}  // namespace mgp
