#include "ik/plain_ik.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace mgp {

std::string PlainIkJob::validate() const {
    if (!skeleton) return "expected a skeleton, found none";
    if (static_cast<int>(start.anglesDeg.size()) != skeleton->jointCount())
        return "expected a start pose for this skeleton, found one with " + std::to_string(start.anglesDeg.size()) +
               " joints";
    if (const int P = PoseLayout(*skeleton).size(); !frozenDofs.empty() && static_cast<int>(frozenDofs.size()) != P)
        return "expected " + std::to_string(P) + " frozen-DOF flags, found " + std::to_string(frozenDofs.size());
    if (const int P = PoseLayout(*skeleton).size(); !dofCost.empty()) {
        if (static_cast<int>(dofCost.size()) != P)
            return "expected " + std::to_string(P) + " DOF costs, found " + std::to_string(dofCost.size());
        for (double c : dofCost)
            if (!(c > 0.0) || !std::isfinite(c))
                return "expected positive finite DOF costs, found " + std::to_string(c);
    }
    for (const JointHold& h : jointHolds) {
        if (h.joint < 0 || h.joint >= skeleton->jointCount())
            return "expected a held joint 0.." + std::to_string(skeleton->jointCount() - 1) + ", found " +
                   std::to_string(h.joint);
        if (!h.targetCm.allFinite()) return "expected a finite joint hold, found NaN or Inf";
    }
    return validateConstraints(*skeleton, constraints);
}

void PlainIkJob::solve() {
    pose = start;
    results.clear();
    iterations = 0;
    reached = false;
    if (const std::string problem = validate(); !problem.empty()) {
        diagnostic = problem;
        return;
    }
    const Skeleton& sk = *skeleton;
    const PoseLayout layout(sk);
    std::vector<int> active;
    const int P = layout.size();
    for (int i = 0; i < P; ++i)
        if (layout.joint(i) >= 0 && (frozenDofs.empty() || !frozenDofs[i])) active.push_back(i);
    const int mc = static_cast<int>(constraints.size());
    const int m = mc + static_cast<int>(jointHolds.size());  // rows: the constraints, then the joint holds
    const int angles = static_cast<int>(active.size());
    const int n = angles + (freeRootTranslation ? 3 : 0);  // the root translation's columns come last
    FkState fk;
    Eigen::Matrix<double, 3, Eigen::Dynamic> jac(3, P);
    Eigen::MatrixXd J(3 * m, n);
    Eigen::VectorXd err(3 * m), y(P), trial(P);
    // Column scale 1/√m_k: the minimal-norm step in the scaled variables is the least-Σ m_k Δy_k² step.
    Eigen::VectorXd scale = Eigen::VectorXd::Ones(n);
    if (!dofCost.empty())
        for (int k = 0; k < angles; ++k) scale[k] = 1.0 / std::sqrt(dofCost[static_cast<std::size_t>(active[k])]);

    auto evaluate = [&](const Pose& p, Eigen::VectorXd& e) {
        forwardKinematics(sk, p, fk);
        for (int c = 0; c < mc; ++c)
            e.segment<3>(3 * c) = constraints[c].targetCm - effectorCm(sk, fk, constraints[c].effector);
        for (int h = 0; h < m - mc; ++h)
            e.segment<3>(3 * (mc + h)) = jointHolds[h].targetCm - fk.jointCm[jointHolds[h].joint];
        return e.squaredNorm();
    };
    double cost = evaluate(pose, err);
    double lambda = initialDamping;
    int stalls = 0;
    diagnostic = "iteration limit";
    for (iterations = 0; iterations < maxIterations; ++iterations) {
        bool done = true;
        for (int c = 0; c < m; ++c) done = done && err.segment<3>(3 * c).norm() < toleranceCm;
        if (done) {
            diagnostic = "converged";
            break;
        }
        forwardKinematics(sk, pose, fk);
        for (int c = 0; c < m; ++c) {
            if (c < mc) {
                effectorJacobian(sk, layout, fk, pose, constraints[c].effector, jac);
            } else {
                const int held = jointHolds[c - mc].joint;
                pointJacobian(sk, layout, fk, pose, held, fk.jointCm[held], jac);
            }
            for (int k = 0; k < angles; ++k) J.block<3, 1>(3 * c, k) = scale[k] * jac.col(active[k]);
            // ∂p/∂(root translation) = I for every point of the body.
            if (freeRootTranslation) J.block<3, 3>(3 * c, angles).setIdentity();
        }
        layout.extract(pose, y.data());
        // Adaptive damping: shrink λ after a step that lowers the error, grow it after one that
        // does not; stop when even heavy damping no longer helps (the residual stopped falling).
        bool improved = false;
        for (int attempt = 0; attempt < 12 && !improved; ++attempt) {
            const Eigen::MatrixXd A = J * J.transpose() + lambda * lambda * Eigen::MatrixXd::Identity(3 * m, 3 * m);
            const Eigen::VectorXd step = scale.cwiseProduct(J.transpose() * A.ldlt().solve(err));
            trial = y;
            for (int k = 0; k < angles; ++k) trial[active[k]] += step[k];
            Pose candidate = pose;
            layout.apply(trial.data(), candidate);
            if (freeRootTranslation) candidate.rootCm += step.tail<3>();
            Eigen::VectorXd e2(3 * m);
            const double c2 = evaluate(candidate, e2);
            if (std::isfinite(c2) && c2 < cost) {
                pose = std::move(candidate);
                err = e2;
                improved = cost - c2 > 1e-12 * std::max(1.0, cost);
                cost = c2;
                lambda = std::max(lambda * 0.5, 1e-6);
                if (!improved) break;
            } else {
                lambda *= 4.0;
            }
        }
        if (!improved && ++stalls >= 3) {
            diagnostic = "residual stopped falling";
            break;
        }
        if (improved) stalls = 0;
    }
    evaluate(pose, err);
    reached = true;
    for (int h = mc; h < m; ++h) reached = reached && err.segment<3>(3 * h).norm() <= kReachedToleranceCm;
    for (int c = 0; c < mc; ++c) {
        IkConstraintResult r;
        r.effector = constraints[c].effector;
        r.pin = constraints[c].pin;
        r.residualCm = err.segment<3>(3 * c).norm();
        r.reached = r.residualCm <= kReachedToleranceCm;
        reached = reached && r.reached;
        results.push_back(r);
    }
}

double worstHoldMissCm(const Skeleton& sk, const Pose& pose, const std::vector<IkConstraint>& holds) {
    double worst = 0.0;
    for (const IkConstraint& c : holds) worst = std::max(worst, (effectorCm(sk, pose, c.effector) - c.targetCm).norm());
    return worst;
}

std::optional<Pose> settleOnHolds(const Skeleton& sk, const Pose& pose, int keptJoint,
                                  const std::vector<IkConstraint>& holds, const Pose* soleReference, int maxIterations,
                                  bool moveRoot, const std::vector<Effector>* soleFeet) {
    if (holds.empty()) return std::nullopt;
    // A held foot keeps its sole: its ankle stays where the reference has it, so the ball alone
    // does not pivot the foot onto its toe (or the heel into the floor).
    std::vector<JointHold> soles;
    if (soleReference) {
        FkState ref;
        forwardKinematics(sk, *soleReference, ref);
        for (const IkConstraint& c : holds)
            if ((c.effector == Effector::kLFoot || c.effector == Effector::kRFoot) &&
                (!soleFeet || std::find(soleFeet->begin(), soleFeet->end(), c.effector) != soleFeet->end()))
                // Not a foot whose own ankle or toes were turned: its sole is what changed.
                if (const int ankle = sk.effectorSite(c.effector).joint;
                    ankle >= 0 && !(keptJoint >= 0 && sk.isAncestorOrSelf(ankle, keptJoint)))
                    soles.push_back({ankle, ref.jointCm[ankle]});
    }
    // How far the holds and the soles are from their places.
    auto worstMiss = [&](const Pose& p) {
        double worst = worstHoldMissCm(sk, p, holds);
        if (!soles.empty()) {
            FkState fk;
            forwardKinematics(sk, p, fk);
            for (const JointHold& h : soles) worst = std::max(worst, (fk.jointCm[h.joint] - h.targetCm).norm());
        }
        return worst;
    };
    const double missBefore = worstMiss(pose);
    if (missBefore <= kSettledHoldCm) return std::nullopt;
    const PoseLayout layout(sk);
    std::vector<bool> frozen(static_cast<std::size_t>(layout.size()), false);
    for (int dof = 0; dof < layout.size(); ++dof)
        frozen[static_cast<std::size_t>(dof)] = dof < 3 || (keptJoint >= 0 && layout.joint(dof) == keptJoint);
    auto settle = [&](const std::vector<JointHold>& jointHolds) {
        PlainIkJob job;
        job.skeleton = &sk;
        job.start = pose;
        job.freeRootTranslation = moveRoot;
        job.frozenDofs = frozen;
        for (IkConstraint c : holds) {
            c.pin = true;
            job.constraints.push_back(c);
        }
        job.jointHolds = jointHolds;
        job.toleranceCm = 0.1 * kSettledHoldCm;
        job.maxIterations = maxIterations;
        job.solve();
        return job.pose;
    };
    // A settle is kept only if it brings the worst miss closer and leaves no hold farther from its
    // place than it was: a sole the legs cannot reach must not pull a planted ball off the floor.
    auto holdsNoWorse = [&](const Pose& p) {
        for (const IkConstraint& c : holds) {
            const double before = (effectorCm(sk, pose, c.effector) - c.targetCm).norm();
            if ((effectorCm(sk, p, c.effector) - c.targetCm).norm() > std::max(before, kSettledHoldCm)) return false;
        }
        return true;
    };
    const Pose withSoles = settle(soles);
    if (allFinite(withSoles) && worstMiss(withSoles) < missBefore && holdsNoWorse(withSoles)) return withSoles;
    // The soles cost a hold: the holds alone, if they were missed.
    const double holdsBefore = worstHoldMissCm(sk, pose, holds);
    if (soles.empty() || holdsBefore <= kSettledHoldCm) return std::nullopt;
    const Pose alone = settle({});
    if (!allFinite(alone) || !(worstHoldMissCm(sk, alone, holds) < holdsBefore) || !holdsNoWorse(alone))
        return std::nullopt;
    return alone;
}

}  // namespace mgp
