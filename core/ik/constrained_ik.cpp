#include "ik/constrained_ik.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "skeleton/centre_of_mass.h"
#include "skeleton/limb_extension.h"

namespace mgp {

namespace {
constexpr double kMaxDamping = 1e12;
constexpr double kConvergedDamping = 1e-2;  // above this the decrement is not a Newton decrement
constexpr int kProjections = 5;             // second-order corrections onto the pins per trial
constexpr double kNewtonDamping = 1e-3;     // at or below, after an accepted step: full Newton model
constexpr double kFirstShift = 1e-8;        // first τ of an indefinite model, relative to max |H_ii|
constexpr double kMaxStepDeg = 20.0;        // longest change of one angle in one step
// A trial may leave the pins by at most this much (cm; 1/50 of the reached tolerance) when the
// corrections of a long step have not brought them back yet; the next KKT step restores them.
constexpr double kPinSlackCm = 1e-3;
// A solve still running after this many trial steps is crawling (a drag event needs at most 5 at
// its p99): from then on the shift is sized to 4× the smallest that factorises, and the
// latent step bound becomes a trust radius that grows after good steps it cut (docs/maths-ik.md §3).
// Solves that stop earlier take exactly the steps they took without these rules.
constexpr int kCrawlIterations = 20;
constexpr double kMinAngleRadiusDeg = 0.5;       // a crawling solve's angle trust radius: its floor
constexpr double kAccurateGain = 0.1;            // |gain − 1| at most this: the model predicted the step
constexpr double kGoodGain = 0.75;               // gain above this: a good step (trust radii may grow)
constexpr double kAccurateDamping = 0.1;         // a crawling solve's μ factor after such a step
constexpr int kShiftBisections = 4;              // the smallest factorising shift to within 10^(1/16)
constexpr double kShiftMargin = 4.0;             // a crawling solve's shift: this times that smallest
constexpr double kMaxLatentRadius = 16.0;        // the latent trust radius, in half length scales
constexpr double kMinLatentRadius = 1.0 / 16.0;  // its floor once it cut a rejected step (same unit)
constexpr int kDirectTrials = 5;                 // trials before the latent refinement starts
constexpr int kLatentRefinements = 3;            // Newton steps in x per trial point (variable projection)
constexpr int kRefineBacktracks = 5;             // halvings of one such step before it is given up
// Past the interactive budget (a drag event's and `pose --iterations 50`'s cap), a solve whose exact
// target is still out of tolerance is in the large-residual regime, where Gauss–Newton converges
// only linearly: from then on its model is the full Newton one (docs/maths-ik.md §3).
constexpr int kLargeResidualIterations = 50;
// A crawling solve enters that regime earlier, once a step is rejected while such a target sits at
// the end of a limb this close to straight (limbExtension): at a straight knee or elbow the limb's
// Jacobian loses rank, and the Gauss–Newton model cannot see that the effector is at the end of
// its reach; the constraint curvature it omits can (docs/maths-ik.md §3).
constexpr double kStraightLimbExtension = 0.99;
// A trial rejected only for leaving the pins is retried this much shorter, at most and at least.
constexpr double kMaxRetryShortening = 0.5;
constexpr double kMinRetryShortening = 0.1;

// Every entry finite: the same test as Eigen's allFinite(), which compares x − x with itself entry
// by entry and cost 2.7 % of a drag's time on the n×n Hessian checked after every accepted step.
template <class Derived>
bool allFinite(const Eigen::DenseBase<Derived>& m) {
    return (m.derived().array().abs() <= std::numeric_limits<double>::max()).all();
}
}  // namespace

const char* ikStopName(IkStop stop) {
    switch (stop) {
        case IkStop::kConverged: return "converged";
        case IkStop::kIterationCap: return "iteration_cap";
        case IkStop::kStalled: return "stalled";
        case IkStop::kInvalidRequest: return "invalid_request";
        case IkStop::kNonFinite: return "non_finite";
    }
    return "unknown";
}

double targetWeight(double strength) {
    if (strength >= kStrengthExact) return kExactTargetWeight;
    return std::min(kExactTargetWeight, 2.0 * strength / (1.0 - strength));
}

ConstrainedIkSolver::ConstrainedIkSolver(gp::ModelVersionPtr version)
    : version_(std::move(version)), layout_(version_->model->clip.skeleton), bodyMass_(version_->model->clip.skeleton) {
    const gp::GpModel& m = *version_->model;
    d_ = m.latentDim();
    D_ = m.D();
    n_ = d_ + D_;
    latentStepBound_ = 0.5 / std::sqrt(m.kernel().gamma());  // half the RBF length scale
    yOfDof_.assign(layout_.size(), -1);
    for (int k = 0; k < D_; ++k) yOfDof_[m.keptColumns[k]] = k;
    for (int a = 0; a < 3; ++a) rootY_[a] = yOfDof_[a];  // DOFs 0-2 are the root rotation
    full_.resize(layout_.size());
    x_.resize(d_);
    y_.resize(D_);
    gx_.resize(d_);
    gy_.resize(D_);
    gyTmp_.resize(D_);
    for (Eigen::VectorXd* v : {&xR_, &gR_, &sR_, &xRt_, &gRt_}) v->resize(d_);
    HR_.resize(d_, d_);
    jac_.resize(3, layout_.size());
    gaussNewtonRow_.resize(layout_.size());
    for (Eigen::VectorXd* v : {&g_, &z_, &zTrial_, &zSoc_, &delta_, &deltaT_, &tmp_, &rhs_}) v->resize(n_);
    for (Eigen::MatrixXd* m : {&H_, &C_, &Hm_, &Hd_}) m->resize(n_, n_);
    hc_.resize(layout_.size(), layout_.size());
    const Skeleton& sk = m.clip.skeleton;
    for (int e = 0; e < kEffectorCount; ++e) {
        const int end = sk.effectorSite(static_cast<Effector>(e)).joint;
        if (end < 0) continue;
        for (int dof = 0; dof < layout_.size(); ++dof)
            if (layout_.joint(dof) >= 0 && sk.isAncestorOrSelf(layout_.joint(dof), end) && yOfDof_[dof] >= 0)
                chainDofs_[e].push_back(dof);
    }
}

std::string ConstrainedIkSolver::validate(const ConstrainedIkRequest& r) const {
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
    if (r.maxIterations < 1) return "expected at least 1 iteration, found " + std::to_string(r.maxIterations);
    if (!(r.rootStiffness >= 0.0) || !std::isfinite(r.rootStiffness))
        return "expected a root stiffness ≥ 0, found " + std::to_string(r.rootStiffness);
    if (r.rootReferenceDeg && !r.rootReferenceDeg->allFinite())
        return "expected a finite root reference, found NaN or Inf";
    if (!(r.locality >= 0.0) || !std::isfinite(r.locality))
        return "expected a locality ≥ 0, found " + std::to_string(r.locality);
    if (r.localityReference) {
        if (r.localityReference->anglesDeg.size() != r.start.anglesDeg.size())
            return "expected a locality reference of the model's skeleton, found one with " +
                   std::to_string(r.localityReference->anglesDeg.size()) + " joints";
        for (const auto& a : r.localityReference->anglesDeg)
            if (!a.allFinite()) return "expected a finite locality reference, found NaN or Inf";
    }
    if (r.floorCm && !std::isfinite(*r.floorCm))
        return "expected a finite floor height, found " + std::to_string(*r.floorCm);
    if (!(r.balanceWeight >= 0.0) || !std::isfinite(r.balanceWeight))
        return "expected a balance weight ≥ 0, found " + std::to_string(r.balanceWeight);
    if (r.balance) {
        if (r.balance->hull.empty()) return "expected a balance region with at least one point, found none";
        for (const Eigen::Vector2d& p : r.balance->hull)
            if (!p.allFinite()) return "expected a finite balance region, found NaN or Inf";
        if (!(r.balance->growCm >= 0.0) || !std::isfinite(r.balance->growCm))
            return "expected a balance region grown by ≥ 0 cm, found " + std::to_string(r.balance->growCm);
        if (!r.balance->convexCounterClockwise())
            return "expected a balance region's hull convex and counter-clockwise, found one that is not";
    }
    for (std::size_t i = 0; i < r.held.size(); ++i) {
        const HeldDof& h = r.held[i];
        if (h.joint < 0 || h.joint >= sk.jointCount() || h.axis < 0 || h.axis > 2)
            return "expected a held DOF of a joint 0.." + std::to_string(sk.jointCount() - 1) +
                   " and an axis 0..2, found joint " + std::to_string(h.joint) + " axis " + std::to_string(h.axis);
        if (!std::isfinite(h.valueDeg)) return "expected a finite held angle, found NaN or Inf";
        for (std::size_t k = 0; k < i; ++k)
            if (r.held[k].joint == h.joint && r.held[k].axis == h.axis)
                return "expected each held DOF once, found joint " + std::to_string(h.joint) + " axis " +
                       std::to_string(h.axis) + " twice";
    }
    return validateConstraints(sk, r.constraints);
}

void ConstrainedIkSolver::bind(const ConstrainedIkRequest& request) {
    request_ = &request;
    posed_ = valued_ = false;
    pose_ = request.start;
    for (const HeldDof& h : request.held) pose_.anglesDeg[h.joint][h.axis] = h.valueDeg;
    layout_.extract(pose_, full_.data());
    const gp::GpModel& m = *version_->model;
    for (std::size_t k = 0; k < m.constantColumns.size(); ++k) full_[m.constantColumns[k]] = m.constantValues[k];
    // Held DOFs keep their values even on a constant column (the prior never sees those).
    heldY_.clear();
    for (const HeldDof& h : request.held)
        for (int dof = 0; dof < layout_.size(); ++dof)
            if (layout_.joint(dof) == h.joint && layout_.axis(dof) == h.axis) {
                full_[dof] = h.valueDeg;
                if (yOfDof_[dof] >= 0) heldY_.push_back(yOfDof_[dof]);
            }
    rootRef_ = request.rootReferenceDeg ? *request.rootReferenceDeg : Eigen::Vector3d(full_[0], full_[1], full_[2]);
    localityW_.setZero(D_);
    localityRef_.setZero(D_);
    if (request.locality > 0.0) {
        std::vector<Effector> targeted;
        for (const IkConstraint& c : request.constraints)
            if (!c.pin) targeted.push_back(c.effector);
        const std::vector<double> w = localityWeights(m.clip.skeleton, targeted);
        Eigen::VectorXd ref(layout_.size());
        layout_.extract(request.localityReference ? *request.localityReference : request.start, ref.data());
        for (int dof = 0; dof < layout_.size(); ++dof)
            if (const int k = yOfDof_[dof]; k >= 0) {
                localityW_[k] = request.locality * w[dof];
                localityRef_[k] = ref[dof];
            }
        for (int k : heldY_) localityW_[k] = 0.0;  // not unknowns
    }
    floorGuarded_.clear();
    if (request.floorCm)
        for (Effector e : {Effector::kLHand, Effector::kRHand, Effector::kLFoot, Effector::kRFoot}) {
            const bool constrained = std::any_of(request.constraints.begin(), request.constraints.end(),
                                                 [e](const IkConstraint& c) { return c.effector == e; });
            if (!constrained && m.clip.skeleton.effectorSite(e).joint >= 0) floorGuarded_.push_back(e);
        }
    pins_.clear();
    targets_.clear();
    exactTargets_.clear();
    for (std::size_t i = 0; i < request.constraints.size(); ++i)
        (request.constraints[i].pin ? pins_ : targets_).push_back(static_cast<int>(i));
    const int p = 3 * static_cast<int>(pins_.size());
    // Exact targets follow the pins in the second-order correction's rows.
    correctionRow_.assign(targets_.size(), -1);
    for (std::size_t k = 0; k < targets_.size(); ++k)
        if (request.constraints[targets_[k]].strength >= kStrengthExact) {
            correctionRow_[k] = p + 3 * static_cast<int>(exactTargets_.size());
            exactTargets_.push_back(targets_[k]);
        }
    const int q = p + 3 * static_cast<int>(exactTargets_.size());
    Aall_.resize(q, n_);
    eHat_.resize(q);
    eAt_.resize(q);
    rAll_.resize(q);
    HinvAll_.resize(n_, q);
    Sall_.resize(q, q);
    A_.resize(p, n_);
    c_.resize(p);
    cTrial_.resize(p);
    nu_.resize(p);
    nuT_.resize(p);
    HinvAt_.resize(n_, p);
    S_.resize(p, p);
}

Eigen::VectorXd ConstrainedIkSolver::startPoint(const ConstrainedIkRequest& request) {
    bind(request);
    Eigen::VectorXd z(n_);
    z.head(d_) = request.startX;
    const gp::GpModel& m = *version_->model;
    for (int k = 0; k < D_; ++k) z[d_ + k] = full_[m.keptColumns[k]];
    return z;
}

void ConstrainedIkSolver::setPose(const Eigen::VectorXd& y) {
    if (posed_ && y == yPosed_) return;
    yPosed_ = y;
    posed_ = true;
    const gp::GpModel& m = *version_->model;
    for (int k = 0; k < D_; ++k) full_[m.keptColumns[k]] = y[k];
    layout_.apply(full_.data(), pose_);
    forwardKinematics(m.clip.skeleton, pose_, fk_);
}

double ConstrainedIkSolver::correctionResidual(const Eigen::VectorXd& z, Eigen::VectorXd& r) {
    setPose(z.tail(D_));
    const Skeleton& sk = version_->model->clip.skeleton;
    const auto p = static_cast<Eigen::Index>(3 * pins_.size());
    for (std::size_t i = 0; i < pins_.size(); ++i) {
        const IkConstraint& pc = request_->constraints[pins_[i]];
        r.segment<3>(3 * static_cast<Eigen::Index>(i)) = effectorCm(sk, fk_, pc.effector) - pc.targetCm;
    }
    for (std::size_t i = 0; i < exactTargets_.size(); ++i) {
        const IkConstraint& tc = request_->constraints[exactTargets_[i]];
        const auto row = p + 3 * static_cast<Eigen::Index>(i);
        r.segment<3>(row) = effectorCm(sk, fk_, tc.effector) - tc.targetCm - eHat_.segment<3>(row);
    }
    return p > 0 ? r.head(p).cwiseAbs().maxCoeff() : 0.0;
}

double ConstrainedIkSolver::evaluate(const Eigen::VectorXd& z, bool derivatives) {
    x_ = z.head(d_);
    y_ = z.tail(D_);
    if (!(valued_ && z == zValued_)) {
        ++evaluations_;
        lik_ = version_->posterior->evaluate(x_, y_, ws_, nullptr, nullptr);
        sigma2_ = ws_.variance;
        zValued_ = z;
        valued_ = true;
    }
    if (derivatives) version_->posterior->gradients(x_, ws_, &gx_, &gy_);
    double F = lik_;
    if (derivatives) priorDerivatives();
    setPose(y_);
    // F's terms are added in this order (targets, root, locality, floor, balance): the sum is bit-exact.
    addTargetTerms(F, derivatives);
    addRootAndLocalityTerms(F, derivatives);
    addFloorTerms(F, derivatives);
    addBalanceTerm(F, derivatives);
    if (derivatives) pinDerivatives();
    return F;
}

void ConstrainedIkSolver::priorDerivatives() {
    const gp::GpModel& m = *version_->model;
    const double s2 = sigma2_;
    g_.head(d_) = gx_;
    g_.tail(D_) = gy_;
    H_.setZero();
    C_.setZero();
    // y–y: ∂²/∂y² of ‖W(y − f)‖²/(2σ²) = W²/σ².
    for (int k = 0; k < D_; ++k) H_(d_ + k, d_ + k) = m.w[k] * m.w[k] / s2;
    // x–y: ∂(W r/σ²)/∂x = −W² J_f/σ² − (W r) (∂σ²/∂x)ᵀ/σ⁴.
    version_->posterior->meanVarianceJacobians(x_, ws_, Jf_, dS2_);
    for (int k = 0; k < D_; ++k) {
        const double wk2 = m.w[k] * m.w[k];
        const double wr = m.w[k] * ws_.r[k];
        for (int i = 0; i < d_; ++i) {
            const double h = -wk2 * Jf_(k, i) / s2 - wr * dS2_[i] / (s2 * s2);
            H_(d_ + k, i) = h;
            H_(i, d_ + k) = h;
        }
    }
    // x–x: exact, from the kernel's second derivatives (y fixed).
    version_->posterior->latentHessian(x_, ws_, Jf_, dS2_, Hxx_);
    H_.topLeftCorner(d_, d_) = Hxx_;
}

void ConstrainedIkSolver::addTargetTerms(double& F, bool derivatives) {
    const Skeleton& sk = version_->model->clip.skeleton;
    // Targets (penalties).
    for (std::size_t k = 0; k < targets_.size(); ++k) {
        const IkConstraint& c = request_->constraints[targets_[k]];
        const double kappa = targetWeight(c.strength);
        const Eigen::Vector3d e = effectorCm(sk, fk_, c.effector) - c.targetCm;
        F += 0.5 * kappa * e.squaredNorm();
        if (!derivatives) continue;
        if (curvature_) addConstraintCurvature(c.effector, kappa * e);
        effectorJacobian(sk, layout_, fk_, pose_, c.effector, jac_);
        if (correctionRow_[k] >= 0) {
            scatterJacobian(Aall_, correctionRow_[k]);
            eAt_.segment<3>(correctionRow_[k]) = e;  // the residual at z; ê adds the step's linear change
        }
        for (int a = 0; a < layout_.size(); ++a) {
            const int ka = yOfDof_[a];
            if (ka < 0 || jac_.col(a).isZero(0.0)) continue;
            g_[d_ + ka] += kappa * jac_.col(a).dot(e);
            for (int b = 0; b <= a; ++b) {
                const int kb = yOfDof_[b];
                if (kb < 0) continue;
                const double h = kappa * jac_.col(a).dot(jac_.col(b));
                H_(d_ + ka, d_ + kb) += h;
                if (kb != ka) H_(d_ + kb, d_ + ka) += h;
            }
        }
    }
}

void ConstrainedIkSolver::addRootAndLocalityTerms(double& F, bool derivatives) {
    const ConstrainedIkRequest& r = *request_;
    for (int a = 0; a < 3; ++a) {
        const int k = rootY_[a];
        if (k < 0) continue;
        const double dev = y_[k] - rootRef_[a];
        F += 0.5 * r.rootStiffness * dev * dev;
        if (derivatives) {
            g_[d_ + k] += r.rootStiffness * dev;
            H_(d_ + k, d_ + k) += r.rootStiffness;
        }
    }
    // Locality: ½ Σ_k ℓw_k (y_k − y_ref,k)², exact (diagonal).
    for (int k = 0; k < D_; ++k) {
        if (localityW_[k] == 0.0) continue;
        const double dev = y_[k] - localityRef_[k];
        F += 0.5 * localityW_[k] * dev * dev;
        if (derivatives) {
            g_[d_ + k] += localityW_[k] * dev;
            H_(d_ + k, d_ + k) += localityW_[k];
        }
    }
}

void ConstrainedIkSolver::addFloorTerms(double& F, bool derivatives) {
    const Skeleton& sk = version_->model->clip.skeleton;
    // Floor: ½ κ_exact min(0, p_y − floor)² on each free hand and foot (Gauss–Newton on the
    // Jacobian's vertical row). Its gradient is continuous at the floor; its curvature steps there.
    for (Effector e : floorGuarded_) {
        const double below = effectorCm(sk, fk_, e).y() - *request_->floorCm;
        if (below >= 0.0) continue;
        F += 0.5 * kExactTargetWeight * below * below;
        if (!derivatives) continue;
        effectorJacobian(sk, layout_, fk_, pose_, e, jac_);
        gaussNewtonRow_ = jac_.row(1);
        addGaussNewtonRow(kExactTargetWeight, below);
    }
}

void ConstrainedIkSolver::addGaussNewtonRow(double weight, double residual) {
    for (int a = 0; a < layout_.size(); ++a) {
        const int ka = yOfDof_[a];
        const double ra = gaussNewtonRow_[a];
        if (ka < 0 || ra == 0.0) continue;
        g_[d_ + ka] += weight * residual * ra;
        for (int b = 0; b <= a; ++b) {
            const int kb = yOfDof_[b];
            if (kb < 0) continue;
            const double h = weight * ra * gaussNewtonRow_[b];
            H_(d_ + ka, d_ + kb) += h;
            if (kb != ka) H_(d_ + kb, d_ + ka) += h;
        }
    }
}

void ConstrainedIkSolver::addBalanceTerm(double& F, bool derivatives) {
    if (!request_->balance) return;
    const Skeleton& sk = version_->model->clip.skeleton;
    const std::optional<Eigen::Vector3d> com = centreOfMass(sk, bodyMass_, fk_);
    if (!com) return;
    Eigen::Vector2d n;
    double k = 0.0;
    const double d = request_->balance->outsideCm(Eigen::Vector2d(com->x(), com->z()), &n, &k);
    if (!(d > 0.0) || !std::isfinite(d)) return;
    const double kappa = request_->balanceWeight;
    F += 0.5 * kappa * d * d;
    if (!derivatives) return;
    // ∂d/∂y = nᵀ ∂c_xz/∂y (n: the unit direction d grows in); Gauss–Newton curvature κ (∂d)ᵀ∂d in H,
    // and in the Newton regime the rest of ∇²(½κd²) in C: κd (Σ n·∂²c + J_cᵀ k (I − nnᵀ) J_c).
    centreOfMassJacobian(sk, bodyMass_, layout_, fk_, pose_, jac_);
    if (curvature_) {
        centreOfMassHessianContracted(sk, bodyMass_, layout_, fk_, pose_,
                                      kappa * d * Eigen::Vector3d(n.x(), 0.0, n.y()), hc_);
        const Eigen::Vector2d t(-n.y(), n.x());  // I − nnᵀ = t tᵀ in the plane
        for (int a = 0; a < layout_.size(); ++a) {
            const int ka = yOfDof_[a];
            if (ka < 0) continue;
            const double ta = t.x() * jac_(0, a) + t.y() * jac_(2, a);
            for (int b = 0; b < layout_.size(); ++b) {
                const int kb = yOfDof_[b];
                if (kb < 0) continue;
                const double tb = t.x() * jac_(0, b) + t.y() * jac_(2, b);
                C_(d_ + ka, d_ + kb) += hc_(a, b) + kappa * d * k * ta * tb;
            }
        }
    }
    gaussNewtonRow_ = n.x() * jac_.row(0) + n.y() * jac_.row(2);  // ∂d/∂y
    addGaussNewtonRow(kappa, d);
}

void ConstrainedIkSolver::pinDerivatives() {
    const Skeleton& sk = version_->model->clip.skeleton;
    const ConstrainedIkRequest& r = *request_;
    // Pins (constraints).
    for (std::size_t i = 0; i < pins_.size(); ++i) {
        const IkConstraint& pc = r.constraints[pins_[i]];
        const auto row = 3 * static_cast<Eigen::Index>(i);
        c_.segment<3>(row) = effectorCm(sk, fk_, pc.effector) - pc.targetCm;
        effectorJacobian(sk, layout_, fk_, pose_, pc.effector, jac_);
        scatterJacobian(A_, row);
    }
    freezeHeld(false);
    Aall_.topRows(A_.rows()) = A_;
    eAt_.head(c_.size()).setZero();  // pins are corrected back onto c = 0
    if (curvature_ && !pins_.empty()) {
        // Least-squares multipliers at z, ν = −(A Aᵀ)⁻¹ A g: the pins' share of the curvature.
        S_.noalias() = A_ * A_.transpose();
        S_.diagonal().array() += 1e-12 * std::max(1.0, S_.diagonal().maxCoeff());
        sLdlt_.compute(S_);
        nu_ = -sLdlt_.solve(A_ * g_);
        for (std::size_t i = 0; i < pins_.size(); ++i)
            addConstraintCurvature(r.constraints[pins_[i]].effector, nu_.segment<3>(3 * static_cast<Eigen::Index>(i)));
    }
    if (curvature_) freezeHeld(true);
}

ConstrainedIkSolver::ExactTargetReach ConstrainedIkSolver::exactTargetReach(double reachedToleranceCm) const {
    const Skeleton& sk = version_->model->clip.skeleton;
    ExactTargetReach reach;
    for (int t : exactTargets_) {
        const IkConstraint& c = request_->constraints[t];
        if (!((effectorCm(sk, fk_, c.effector) - c.targetCm).norm() > reachedToleranceCm)) continue;
        reach.outside = true;
        const std::optional<double> extension = limbExtension(sk, fk_, c.effector);
        if (extension && *extension >= kStraightLimbExtension) reach.outsideAtStraightLimb = true;
    }
    return reach;
}

void ConstrainedIkSolver::refineLatent(Eigen::VectorXd& z) {
    const gp::ActiveSetPosterior& post = *version_->posterior;
    y_ = z.tail(D_);
    xR_ = z.head(d_);
    double L = post.evaluate(xR_, y_, wsRefine_, &gR_, &gyTmp_);
    ++evaluations_;
    // The x–x Hessian is the joint model's at the current point (already computed): a trial's y
    // differs from it by one step, and the backtracking below only accepts what lowers L_IK
    // (docs/maths-ik.md §3).
    HR_ = Hm_.topLeftCorner(d_, d_);
    HR_ = (0.5 * (HR_ + HR_.transpose())).eval();
    // |λ|: a direction of negative curvature is followed downhill, not uphill.
    eigR_.compute(HR_);
    const double largest = std::max(1.0, eigR_.eigenvalues().cwiseAbs().maxCoeff());
    for (int step = 0; step < kLatentRefinements; ++step) {
        sR_ = eigR_.eigenvectors().transpose() * gR_;
        for (int i = 0; i < d_; ++i) sR_[i] /= std::max(std::abs(eigR_.eigenvalues()[i]), 1e-6 * largest);
        sR_ = -(eigR_.eigenvectors() * sR_).eval();
        const double length = sR_.norm();
        if (length > latentStepBound_) sR_ *= latentStepBound_ / length;
        if (sR_.norm() < 1e-6 * latentStepBound_) break;  // x is already optimal for this pose
        bool lowered = false;
        for (int b = 0; b < kRefineBacktracks && !lowered; ++b, sR_ *= 0.5) {
            xRt_ = xR_ + sR_;
            const double Lt = post.evaluate(xRt_, y_, wsRefine_, &gRt_, &gyTmp_);
            ++evaluations_;
            if (Lt < L) {
                xR_ = xRt_;
                gR_ = gRt_;
                L = Lt;
                lowered = true;
            }
        }
        if (!lowered) break;
    }
    z.head(d_) = xR_;
}

void ConstrainedIkSolver::freezeHeld(bool curvature) {
    for (int k : heldY_) {
        const Eigen::Index i = d_ + k;
        if (curvature) {
            C_.row(i).setZero();
            C_.col(i).setZero();
            continue;
        }
        g_[i] = 0.0;
        H_.row(i).setZero();
        H_.col(i).setZero();
        H_(i, i) = 1.0;  // δ_i = −g_i / 1 = 0, decoupled from every other unknown
        if (A_.rows() > 0) A_.col(i).setZero();
        if (Aall_.rows() > 0) Aall_.col(i).setZero();
    }
}

void ConstrainedIkSolver::scatterJacobian(Eigen::MatrixXd& into, Eigen::Index row) const {
    into.middleRows<3>(row).setZero();
    for (int a = 0; a < layout_.size(); ++a)
        if (yOfDof_[a] >= 0) into.block<3, 1>(row, d_ + yOfDof_[a]) = jac_.col(a);
}

void ConstrainedIkSolver::addConstraintCurvature(Effector e, const Eigen::Vector3d& lambda) {
    effectorHessianContracted(version_->model->clip.skeleton, layout_, fk_, pose_, e, lambda, hc_);
    const std::vector<int>& chain = chainDofs_[static_cast<int>(e)];
    for (int a : chain)
        for (int b : chain) C_(d_ + yOfDof_[a], d_ + yOfDof_[b]) += hc_(a, b);
}

double ConstrainedIkSolver::objective(const ConstrainedIkRequest& request, const Eigen::VectorXd& z,
                                      Eigen::VectorXd* gradient) {
    bind(request);
    curvature_ = true;
    const double F = evaluate(z, gradient != nullptr);
    if (gradient) *gradient = g_;
    return F;
}

void ConstrainedIkSolver::fillResult(const ConstrainedIkRequest& request, ConstrainedIkResult& result) {
    // Re-evaluate at z_ so every output belongs to it.
    result.objective = evaluate(z_, false);
    result.x = z_.head(d_);
    result.y = z_.tail(D_);
    result.pose = pose_;
    result.sigma2 = sigma2_;
    result.lik = lik_;
    scoreConstraints(request, result);
}

void ConstrainedIkSolver::scoreConstraints(const ConstrainedIkRequest& request, ConstrainedIkResult& result) const {
    result.constraints.clear();
    result.reached = true;
    const Skeleton& sk = version_->model->clip.skeleton;
    for (const IkConstraint& c : request.constraints) {
        IkConstraintResult cr;
        cr.effector = c.effector;
        cr.pin = c.pin;
        cr.strength = c.pin ? kStrengthExact : c.strength;
        // stableNorm: a target ~1e200 cm away gives a huge finite residual, not Inf.
        cr.residualCm = (effectorCm(sk, fk_, c.effector) - c.targetCm).stableNorm();
        cr.reached = cr.residualCm <= request.reachedToleranceCm;
        result.reached = result.reached && cr.reached;
        result.constraints.push_back(cr);
    }
}

void ConstrainedIkSolver::solve(const ConstrainedIkRequest& request, ConstrainedIkResult& result) {
    const auto belowFloor = [&request](const IkConstraint& c) {
        return request.floorCm && !c.pin && c.effector != Effector::kHead && c.targetCm.y() < *request.floorCm;
    };
    if (!std::any_of(request.constraints.begin(), request.constraints.end(), belowFloor) ||
        !validate(request).empty()) {
        solveOnFloor(request, result);
        return;
    }
    // Targets below the floor: solve for the floor, report against what was asked.
    ConstrainedIkRequest raised = request;
    for (IkConstraint& c : raised.constraints)
        if (belowFloor(c)) c.targetCm.y() = *request.floorCm;
    solveOnFloor(raised, result);
    scoreConstraints(request, result);
    for (std::size_t i = 0; i < request.constraints.size(); ++i)
        result.constraints[i].belowFloor = belowFloor(request.constraints[i]);
}

void ConstrainedIkSolver::solveOnFloor(const ConstrainedIkRequest& request, ConstrainedIkResult& result) {
    result.iterations = result.evaluations = 0;
    result.converged = false;
    result.decrement = std::numeric_limits<double>::quiet_NaN();
    evaluations_ = 0;
    if (const std::string problem = validate(request); !problem.empty()) {
        rejectRequest(request, problem, result);
        return;
    }
    z_ = startPoint(request);
    curvature_ = false;
    Iteration s;
    s.F = evaluate(z_, true);
    if (!std::isfinite(s.F) || !allFinite(g_) || !allFinite(H_)) {
        result.stop = IkStop::kNonFinite;
        result.diagnostic = "expected a finite objective at the start, found NaN or Inf";
        fillResult(request, result);
        result.evaluations = evaluations_;
        return;
    }
    s.latentRadius = latentStepBound_;
    s.angleRadius = kMaxStepDeg;
    while (true) {
        Step step;
        step.crawling = s.it >= kCrawlIterations;
        step.shortenedRetry = std::isfinite(s.retryAngleCap);
        if (!buildModel(s, step)) {
            s.lastAccepted = false;  // the Newton model is indefinite: this step is Gauss–Newton's
            continue;
        }
        if (!shiftIndefiniteModel(step)) {
            s.stop = IkStop::kStalled;
            break;
        }
        kktStep(step);
        result.decrement = step.decrement;
        if (stationary(s, step)) {
            s.stop = IkStop::kConverged;
            break;
        }
        if (s.it >= request.maxIterations) break;
        ++s.it;
        boundStep(s, step);
        const double trialPinNorm = correctTrial();
        const Trial trial = scoreTrial(s, step, trialPinNorm);
        if (!step.newton && std::isfinite(trial.Ft)) s.gaussNewtonOverpredicted = trial.gain < kGoodGain;
        planRetry(s, step, trial);
        if (step.crawling) updateTrustRadii(s, step, trial);
        if (trial.accepted ? !acceptTrial(s, step, trial) : !rejectTrial(s, step)) break;
    }
    result.stop = s.stop;
    result.converged = s.stop == IkStop::kConverged;
    result.iterations = s.it;
    fillResult(request, result);
    result.evaluations = evaluations_;
    result.diagnostic = ikStopName(s.stop);
}

void ConstrainedIkSolver::rejectRequest(const ConstrainedIkRequest& request, const std::string& problem,
                                        ConstrainedIkResult& result) const {
    result.stop = IkStop::kInvalidRequest;
    result.diagnostic = problem;
    result.pose = request.start;
    result.x = request.startX;
    result.y.resize(0);
    result.constraints.clear();
    result.reached = false;
    result.objective = result.lik = result.sigma2 = std::numeric_limits<double>::quiet_NaN();
}

bool ConstrainedIkSolver::buildModel(const Iteration& s, Step& step) {
    // Hessian model: Gauss–Newton for the constraints, plus their curvature (the full
    // Lagrangian Hessian) once the iteration is in its Newton regime; see the header.
    step.newton = s.lastAccepted && curvature_;
    Hm_ = H_;
    if (step.newton) Hm_ += C_;
    // Damped model (a Newton model that cannot be factorised falls back to Gauss–Newton or
    // takes a shift; see below).
    Hd_ = Hm_;
    // ρAᵀA leaves the KKT step unchanged (it only shifts ν by −ρc) but makes the factorised
    // matrix positive definite wherever the Hessian is on the pins' tangent space, which is
    // all a constrained minimum has (docs/maths-ik.md §3).
    if (c_.size() > 0) Hd_.noalias() += kExactTargetWeight * A_.transpose() * A_;
    const double floor = 1e-9 * std::max(1.0, H_.diagonal().cwiseAbs().maxCoeff());
    for (int i = 0; i < n_; ++i) Hd_(i, i) += s.mu * std::max(std::abs(H_(i, i)), floor);
    llt_.compute(Hd_);
    // An indefinite Newton model falls back to Gauss–Newton for this step, except in the
    // large-residual regime, where Gauss–Newton is what crawls, and in a crawling solve whose
    // last Gauss–Newton trial had a gain ratio below 0.75 (it promised more decrease than it
    // gave: the curvature that model omits is what limits the steps): both take the shift below.
    step.keepIndefiniteNewton = step.newton && !s.largeResidual && step.crawling && s.gaussNewtonOverpredicted;
    return !(llt_.info() != Eigen::Success && step.newton && !s.largeResidual && !step.keepIndefiniteNewton);
}

bool ConstrainedIkSolver::shiftIndefiniteModel(Step& step) {
    // An indefinite model (the prior's x–x block is not convex everywhere) gets a shift τI
    // for this step only; raising μ instead would slow every later step (docs/maths-ik.md §3).
    // A crawling solve shifts only the latent block: the indefiniteness is the prior's x–x
    // block, the y block (W²/σ² + κJᵀJ + ρAᵀA) is positive definite without the constraints'
    // curvature, so τ on x alone always factorises a Gauss–Newton model, and it no longer
    // throttles the y DOFs whose prior curvature W²/σ² is far below τ; the latent
    // refinement moves x after y. A model it cannot factorise gets τI (docs/maths-ik.md §3).
    // A Newton model kept because Gauss–Newton overpredicted is indefinite through the
    // constraints' curvature on y: its shift is τI from the start (docs/maths-ik.md §3 step 6).
    double shift = 0.0;
    bool latentOnly = step.crawling && !step.keepIndefiniteNewton;
    while (llt_.info() != Eigen::Success) {
        const double next =
            shift > 0.0 ? 10.0 * shift : kFirstShift * std::max(1.0, H_.diagonal().cwiseAbs().maxCoeff());
        addShift(next - shift, latentOnly);
        shift = next;
        llt_.compute(Hd_);
        if (shift > kMaxDamping) {
            if (!latentOnly) break;
            addShift(-shift, latentOnly);
            latentOnly = false;
            shift = 0.0;
        }
    }
    // τ grows tenfold per try, so it can end up to 10× larger than needed; τ on every unknown
    // then freezes x and the free DOFs for many steps. A crawling solve brackets the smallest
    // factorising τ (between the last failure and the success) and takes four times that
    // (closer to it, the barely positive model's steps were often rejected).
    const double firstShift = kFirstShift * std::max(1.0, H_.diagonal().cwiseAbs().maxCoeff());
    if (step.crawling && llt_.info() == Eigen::Success && shift > firstShift) shift = bracketShift(shift, latentOnly);
    step.shift = shift;
    return llt_.info() == Eigen::Success;
}

double ConstrainedIkSolver::bracketShift(double shift, bool latentOnly) {
    const double succeeded = shift;
    double lo = shift / 10.0, hi = shift;  // lo failed, hi factorises
    for (int b = 0; b < kShiftBisections; ++b) {
        const double mid = std::sqrt(lo * hi);
        addShift(mid - shift, latentOnly);
        shift = mid;
        llt_.compute(Hd_);
        (llt_.info() == Eigen::Success ? hi : lo) = mid;
    }
    const double use = std::min(kShiftMargin * hi, succeeded);
    addShift(use - shift, latentOnly);
    llt_.compute(Hd_);
    return use;
}

void ConstrainedIkSolver::addShift(double amount, bool latentOnly) {
    if (latentOnly)
        Hd_.diagonal().head(d_).array() += amount;
    else
        Hd_.diagonal().array() += amount;
}

void ConstrainedIkSolver::kktStep(Step& step) {
    const Eigen::Index p = c_.size();
    // KKT step: δ = −Hd⁻¹(g + Aᵀν), (A Hd⁻¹ Aᵀ) ν = c − A Hd⁻¹ g.
    tmp_ = llt_.solve(g_);
    if (p > 0) {
        HinvAt_ = llt_.solve(A_.transpose());
        S_.noalias() = A_ * HinvAt_;
        const double reg = 1e-12 * std::max(1.0, S_.diagonal().maxCoeff());
        S_.diagonal().array() += reg;  // rank-deficient pins (a straight leg) stay solvable
        sLdlt_.compute(S_);
        nu_ = sLdlt_.solve(c_ - A_ * tmp_);
        delta_ = -tmp_ - HinvAt_ * nu_;
    } else {
        delta_ = -tmp_;
    }
    step.pinWorst = p > 0 ? c_.cwiseAbs().maxCoeff() : 0.0;
    // Model decrease of F along δ (the pins' linearisation is met by δ).
    step.modelDecrease = -(g_.dot(delta_) + 0.5 * delta_.dot(Hm_ * delta_));
    // Stationarity: the damped Newton decrement on the pins' tangent space, −gᵀδₜ − ½δₜᵀHdδₜ
    // with Aδₜ = 0 (δ itself also restores the pins, which near a solution can cost more F
    // than is left to gain, so its decrement can be negative at a stationary point).
    double decrement = -(g_.dot(delta_) + 0.5 * delta_.dot(Hd_ * delta_));
    if (p > 0) {
        nuT_ = sLdlt_.solve(-(A_ * tmp_));
        deltaT_ = -tmp_ - HinvAt_ * nuT_;
        decrement = -(g_.dot(deltaT_) + 0.5 * deltaT_.dot(Hd_ * deltaT_));
    }
    step.decrement = decrement;
}

bool ConstrainedIkSolver::stationary(const Iteration& s, const Step& step) const {
    const ConstrainedIkRequest& r = *request_;
    return step.pinWorst <= r.pinToleranceCm && s.mu <= kConvergedDamping && step.shift == 0.0 &&
           std::abs(step.decrement) <= r.stationarityAbsolute + r.stationarityRelative * std::abs(s.F);
}

void ConstrainedIkSolver::boundStep(Iteration& s, Step& step) {
    const Eigen::Index p = c_.size();
    // Step bound: the linearisation of FK and of the prior does not reach further than about
    // half a kernel length scale in x or kMaxStepDeg in any angle; a longer step is shortened
    // (same direction) rather than left to the damping, which would also slow every later step.
    // A crawling solve uses trust radii instead of the fixed bounds (latent and angle), and a
    // shortened retry (below) its caps.
    step.latentBound = std::min(step.crawling ? s.latentRadius : latentStepBound_, s.retryLatentCap);
    const double latentScale = step.latentBound / std::max(1e-300, delta_.head(d_).norm());
    const double angleBound = std::min(step.crawling ? s.angleRadius : kMaxStepDeg, s.retryAngleCap);
    const double angleScale = angleBound / std::max(1e-300, delta_.tail(D_).cwiseAbs().maxCoeff());
    step.scale = std::min({1.0, latentScale, angleScale});
    step.latentCut = latentScale < 1.0 && latentScale <= step.scale;  // the latent bound set the length
    step.angleCut = angleScale < 1.0 && angleScale <= step.scale;
    step.stepDecrease = step.modelDecrease;
    if (step.scale < 1.0) {
        delta_ *= step.scale;
        step.stepDecrease = -(g_.dot(delta_) + 0.5 * delta_.dot(Hm_ * delta_));
    }
    if (p > 0) s.meritNu = std::max(s.meritNu, 2.0 * nu_.cwiseAbs().maxCoeff());
    step.c1 = p > 0 ? c_.lpNorm<1>() : 0.0;
    step.pred = step.stepDecrease + s.meritNu * step.scale * step.c1;
}

double ConstrainedIkSolver::correctTrial() {
    // Trial point with second-order corrections.
    zTrial_ = z_ + delta_;
    const Eigen::Index p = c_.size();
    const Eigen::Index q = Aall_.rows();
    if (q == 0) return 0.0;
    // Second-order correction: back onto the pins, and onto the exact targets' linearised
    // prediction (a penalty of weight κ would otherwise charge the manifold's curvature
    // to every step along it: linear convergence; docs/maths-ik.md §3).
    eHat_ = eAt_;
    eHat_.tail(q - p).noalias() += Aall_.bottomRows(q - p) * delta_;
    HinvAll_ = llt_.solve(Aall_.transpose());
    Sall_.noalias() = Aall_ * HinvAll_;
    Sall_.diagonal().array() += 1e-12 * std::max(1.0, Sall_.diagonal().maxCoeff());
    sAllLdlt_.compute(Sall_);
    const double tolerance = 0.01 * request_->pinToleranceCm;
    double lastWorst = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= kProjections; ++k) {
        const double pinWorstTrial = correctionResidual(zTrial_, rAll_);
        const double worst = rAll_.cwiseAbs().maxCoeff();
        if (!(worst <= lastWorst)) {
            // Diverging (B H⁻¹Bᵀ nearly singular, e.g. a straight arm): keep the last point
            // that was closer; the gain ratio judges it.
            zTrial_ = zSoc_;
            break;
        }
        const double targetWorst = q > p ? rAll_.tail(q - p).cwiseAbs().maxCoeff() : 0.0;
        if (k == kProjections || (pinWorstTrial <= tolerance && targetWorst <= tolerance)) break;
        lastWorst = worst;
        zSoc_ = zTrial_;
        zTrial_.noalias() -= HinvAll_ * sAllLdlt_.solve(rAll_);
    }
    correctionResidual(zTrial_, rAll_);
    cTrial_ = rAll_.head(p);
    return cTrial_.lpNorm<1>();
}

ConstrainedIkSolver::Trial ConstrainedIkSolver::scoreTrial(const Iteration& s, const Step& step, double trialPinNorm) {
    const ConstrainedIkRequest& r = *request_;
    const Eigen::Index p = c_.size();
    Trial t;
    // From the sixth trial on: a drag event converges within five (its p99), so drags keep
    // their cost and their steps; a long solve gets x re-fitted to each trial pose
    // (docs/maths-ik.md §3).
    if (s.it > kDirectTrials) refineLatent(zTrial_);
    t.Ft = evaluate(zTrial_, false);
    // Both points on the pins (to a tenth of the tolerance): compare F itself, so round-off in
    // c times a large ν cannot mask progress. Otherwise the ℓ1 merit.
    const bool feasible =
        p == 0 || (step.pinWorst <= 0.1 * r.pinToleranceCm && cTrial_.cwiseAbs().maxCoeff() <= 0.1 * r.pinToleranceCm);
    const double actual = feasible ? s.F - t.Ft : (s.F + s.meritNu * step.c1) - (t.Ft + s.meritNu * trialPinNorm);
    const double predicted = feasible ? step.stepDecrease : step.pred;
    t.gain = predicted > 0.0 ? actual / predicted : (actual > 0.0 ? 1.0 : -1.0);
    // Pins never get visibly worse: a trial that leaves them by more than kPinSlackCm, the
    // tolerance or where they are (a projection that could not return, e.g. at a straight leg)
    // is rejected.
    t.pinAllowance = std::max({kPinSlackCm, r.pinToleranceCm, step.pinWorst});
    t.pinsHeld = p == 0 || cTrial_.cwiseAbs().maxCoeff() <= t.pinAllowance;
    t.accepted = std::isfinite(t.Ft) && t.pinsHeld && t.gain > 1e-4;
    t.predictedWell = std::abs(t.gain - 1.0) <= kAccurateGain;  // the model predicted F's change
    return t;
}

void ConstrainedIkSolver::planRetry(Iteration& s, const Step& step, const Trial& t) {
    // A Gauss–Newton trial whose F the model predicted (gain within 1 ± 0.1) but which left the
    // pins was too long for the pins' curvature, not for the model. Its retry is shortened so
    // that the pins' error, second order in the step, fits the allowance (to at most half and
    // at least a tenth of the step); raising μ alone shortened it only after up to seven
    // trials at μ far below the model's curvature (docs/maths-ik.md §3 step 5).
    s.retryAngleCap = s.retryLatentCap = std::numeric_limits<double>::infinity();
    if (std::isfinite(t.Ft) && !t.pinsHeld && !step.newton && t.predictedWell) {
        const double shorten = std::clamp(std::sqrt(t.pinAllowance / cTrial_.cwiseAbs().maxCoeff()),
                                          kMinRetryShortening, kMaxRetryShortening);
        s.retryAngleCap = shorten * delta_.tail(D_).cwiseAbs().maxCoeff();
        s.retryLatentCap = shorten * delta_.head(d_).norm();
    }
}

void ConstrainedIkSolver::updateTrustRadii(Iteration& s, const Step& step, const Trial& t) {
    // Trust radius: doubled after a good step that the latent bound cut (the model
    // predicted it well, so the bound, not the model, limited it), halved on rejection:
    // down to the fixed bound, or below it when it cut the rejected step (a cut step that
    // fails otherwise fails again until Nielsen's ladder has raised μ), except in the
    // large-residual regime, where short latent steps ended farther from out-of-reach
    // targets; a radius already below the bound keeps its value after other rejections
    // (docs/maths-ik.md §3 step 6).
    if (t.accepted && t.gain > kGoodGain && step.latentCut)
        s.latentRadius = std::min(kMaxLatentRadius * latentStepBound_, 2.0 * s.latentRadius);
    else if (!t.accepted)
        s.latentRadius = std::max(step.latentCut && !s.largeResidual ? kMinLatentRadius * latentStepBound_
                                                                     : std::min(s.latentRadius, latentStepBound_),
                                  0.5 * s.latentRadius);
    // Angle trust radius: halved when a step it cut is rejected (a long bounded step that
    // fails keeps failing while μ is still too small to shorten it), doubled back up to
    // kMaxStepDeg after a good step it cut. A full-length step rejected on its merit (finite
    // F, the pins held; not a shortened retry) sets it to half that step's largest angle
    // change (at least kMinAngleRadiusDeg): at μ ≈ 1e-12 the retry is otherwise about the
    // same step until Nielsen's ladder has raised μ to the model's curvature, up to seven
    // trials later (docs/maths-ik.md §3 step 6).
    if (step.angleCut) {
        if (!t.accepted)
            s.angleRadius = std::max(kMinAngleRadiusDeg, 0.5 * s.angleRadius);
        else if (t.gain > kGoodGain)
            s.angleRadius = std::min(kMaxStepDeg, 2.0 * s.angleRadius);
    } else if (!t.accepted && step.scale >= 1.0 && !step.shortenedRetry && std::isfinite(t.Ft) && t.pinsHeld) {
        s.angleRadius = std::max(kMinAngleRadiusDeg, 0.5 * delta_.tail(D_).cwiseAbs().maxCoeff());
    }
}

bool ConstrainedIkSolver::acceptTrial(Iteration& s, const Step& step, const Trial& t) {
    z_ = zTrial_;
    // Nielsen's update lowers μ by at most 3× per step; a crawling solve whose model
    // predicted the step (gain within 1 ± 0.1) lowers it 10×, so it regains the Newton
    // regime in a third of the steps after a run of rejections (docs/maths-ik.md §3).
    // A shortened retry that succeeds keeps the μ its rejection raised: it shows that the
    // short step holds the pins, not that the next full-length one will.
    if (!step.shortenedRetry)
        s.mu *= step.crawling && t.predictedWell ? kAccurateDamping
                                                 : std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * t.gain - 1.0, 3));
    s.mu = std::max(s.mu, 1e-12);
    // fk_ is still the trial's (its evaluate() was the last), i.e. the new point's.
    // Only a crawling solve looks (a drag event does no extra FK work); before, both flags are false.
    const ExactTargetReach reach =
        s.it > kCrawlIterations ? exactTargetReach(request_->reachedToleranceCm) : ExactTargetReach{};
    s.straightLimbNewton = s.straightLimbNewton || (s.rejectedSinceAccepted && reach.outsideAtStraightLimb);
    s.largeResidual =
        (s.it >= kLargeResidualIterations && reach.outside) || (s.straightLimbNewton && reach.outsideAtStraightLimb);
    s.rejectedSinceAccepted = false;
    curvature_ = s.mu <= kNewtonDamping || s.largeResidual;  // the next model is a Newton one: it needs C
    s.F = evaluate(z_, true);
    if (!std::isfinite(s.F) || !allFinite(g_) || !allFinite(H_)) {
        s.stop = IkStop::kNonFinite;  // cannot happen for finite z; kept as a guard
        return false;
    }
    s.nuLm = 2.0;
    s.lastAccepted = true;
    return true;
}

bool ConstrainedIkSolver::rejectTrial(Iteration& s, const Step& step) {
    s.lastAccepted = false;
    s.rejectedSinceAccepted = true;
    // The grown radius, not the damping, made the step too long: the halved radius above
    // shortens the retry, and μ stays where the gain ratio put it.
    if (step.crawling && step.latentBound > latentStepBound_ && step.latentCut) return true;
    s.mu *= s.nuLm;
    s.nuLm *= 2.0;
    if (s.mu > kMaxDamping) {
        s.stop = IkStop::kStalled;
        return false;
    }
    return true;
}

ConstrainedIkResult ConstrainedIkSolver::solve(const ConstrainedIkRequest& request) {
    ConstrainedIkResult r;
    solve(request, r);
    return r;
}

}  // namespace mgp
