#include "edit/joint_rotation.h"

#include <Eigen/Geometry>

#include "ik/plain_ik.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/rotation.h"

namespace mgp {

Pose rotateJoint(const Skeleton& skeleton, const Pose& pose, int joint, const Eigen::Vector3d& anglesDeg) {
    Pose out = pose;
    for (int a = 0; a < 3; ++a)
        if (skeleton.joints[joint].dof[a]) out.anglesDeg[joint][a] = anglesDeg[a];
    return out;
}

std::optional<Eigen::Vector3d> anglesTurnedAboutWorldAxis(const Skeleton& skeleton, const Pose& pose, int joint,
                                                          const Eigen::Vector3d& axisWorld, double degrees) {
    if (joint < 0 || joint >= skeleton.jointCount() || axisWorld.norm() < 1e-12) return std::nullopt;
    const Joint& jt = skeleton.joints[joint];
    if (!(jt.dof[0] && jt.dof[1] && jt.dof[2])) return std::nullopt;
    FkState fk;
    forwardKinematics(skeleton, pose, fk);
    // G = P·E·Cᵀ with P the DOF axes' base frame; turning G by R in the world gives E' = Pᵀ·R·P·E.
    const Eigen::Matrix3d& P = fk.parentFrame[joint];
    const Eigen::Matrix3d R = Eigen::AngleAxisd(degrees * kDegToRad, axisWorld.normalized()).toRotationMatrix();
    const Eigen::Matrix3d turned = P.transpose() * R * P * eulerMatrix(pose.anglesDeg[joint], jt.order);
    // Of the two Euler triples of that rotation, the one nearest the joint's angles, each angle
    // within half a turn of its old value (no jump by 360° in the middle of a drag).
    const Eigen::Vector3d& old = pose.anglesDeg[joint];
    auto near = [&](Eigen::Vector3d a) {
        for (int k = 0; k < 3; ++k) a[k] = wrapNear(a[k], old[k]);
        return a;
    };
    const Eigen::Vector3d a = near(eulerFromMatrix(turned, jt.order));
    const Eigen::Vector3d b = near(eulerAlternative(a, jt.order));
    return (a - old).squaredNorm() <= (b - old).squaredNorm() ? a : b;
}

std::vector<HeldDof> heldDofsOf(const Skeleton& skeleton, int joint, const Eigen::Vector3d& anglesDeg) {
    std::vector<HeldDof> held;
    for (int a = 0; a < 3; ++a)
        if (skeleton.joints[joint].dof[a]) held.push_back({joint, a, anglesDeg[a]});
    return held;
}

namespace {

// A held hand or foot below the rotated joint moves with it (holding it would turn the rotation
// into a reach by the rest of the body). Pins and planted feet stay wherever they are.
bool movesWithJoint(const EditorDocument& doc, int joint, Effector e) {
    const Skeleton& sk = doc.clip().skeleton;
    const bool planted = doc.inContact(e) && !doc.contactReleased(e);
    return doc.held(e) && !doc.pinned(e) && !planted && sk.isAncestorOrSelf(joint, sk.effectorSite(e).joint);
}

}  // namespace

std::vector<IkConstraint> rotationHolds(const EditorDocument& doc, int joint) {
    std::vector<IkConstraint> out;
    for (const IkConstraint& c : doc.keptInPlace())
        if (!movesWithJoint(doc, joint, c.effector)) out.push_back(c);
    return out;
}

std::vector<Effector> rotationMovers(const EditorDocument& doc, int joint) {
    std::vector<Effector> out;
    for (const IkConstraint& c : doc.keptInPlace())
        if (movesWithJoint(doc, joint, c.effector)) out.push_back(c.effector);
    return out;
}

JointRotationResult solveJointRotation(EditorDocument& doc, const JointRotation& r, int maxIterations) {
    JointRotationResult out;
    if (!doc.hasClip()) {
        out.error = "no clip: open one first";
        return out;
    }
    const Skeleton& sk = doc.clip().skeleton;
    if (r.joint < 0 || r.joint >= sk.jointCount()) {
        out.error = "expected a joint 0.." + std::to_string(sk.jointCount() - 1) + ", found " + std::to_string(r.joint);
        return out;
    }
    if (!r.anglesDeg.allFinite()) {
        out.error = "expected finite angles, found NaN or Inf";
        return out;
    }
    const Pose& before = doc.currentPose();
    out.pose = rotateJoint(sk, before, r.joint, r.anglesDeg);
    const std::vector<IkConstraint> holds = rotationHolds(doc, r.joint);
    out.holdCount = static_cast<int>(holds.size());
    auto settle = [&] {
        // Only a missed hold is settled (the hips and the legs bring it back, each held foot's
        // ankle with it); a held foot that the prior's solve merely turned about its ball is left
        // as the solve put it.
        if (worstHoldMissCm(sk, out.pose, holds) > kSettledHoldCm)
            if (std::optional<Pose> settled = settleOnHolds(sk, out.pose, r.joint, holds, &before, maxIterations)) {
                out.pose = std::move(*settled);
                out.settled = true;
            }
        out.holdMissCm = worstHoldMissCm(sk, out.pose, holds);
    };
    if (!r.followPrior) {
        settle();
        return out;
    }
    const gp::ModelVersionPtr model = doc.model();
    if (!model) {
        out.error = "follow with the learned prior needs a model: train one or open one first";
        return out;
    }
    // The prior's solve keeps the root translation: where the holds need the hips to move (a knee
    // bent over its planted foot) it starts from the settled pose, whose hips are where they need
    // to be (else it keeps the foot by tipping it onto its toe, the hips where they were).
    settle();
    // Warm start: the latent point that best explains the rotated pose (every DOF held, x alone
    // free), so the solve does not start on the frame's branch of the latent space.
    ConstrainedIkSolver solver(model);
    ConstrainedIkRequest fit;
    fit.start = out.pose;
    fit.startX = doc.currentLatent();
    for (int j = 0; j < sk.jointCount(); ++j)
        for (int a = 0; a < 3; ++a)
            if (sk.joints[j].dof[a]) fit.held.push_back({j, a, out.pose.anglesDeg[j][a]});
    fit.maxIterations = maxIterations;
    const ConstrainedIkResult fitted = solver.solve(fit);
    ConstrainedIkRequest req;
    req.start = out.pose;
    req.startX = fitted.x.allFinite() && fitted.x.size() == fit.startX.size() ? fitted.x : fit.startX;
    req.constraints = holds;
    req.held = heldDofsOf(sk, r.joint, r.anglesDeg);
    req.maxIterations = maxIterations;
    solver.solve(req, out.ik);
    if (out.ik.stop == IkStop::kInvalidRequest || out.ik.stop == IkStop::kNonFinite) {
        out.error = "the learned prior could not solve this rotation: " + out.ik.diagnostic;
        return out;
    }
    out.pose = out.ik.pose;
    out.learned = true;
    settle();  // what the solve left off, if anything
    return out;
}

std::string jointRotationLabel(const std::string& jointName, int frame) {
    return "rotate " + jointName + " on frame " + std::to_string(frame + 1);
}

std::string applyJointRotation(EditorDocument& doc, const JointRotation& r, JointRotationResult* result) {
    JointRotationResult solved = solveJointRotation(doc, r);
    if (!solved.error.empty()) return solved.error;
    // The solve kept the frame's holds (settled, with or without the prior): the spread keeps them
    // on the neighbours, and lets what moved with the joint follow the rotation there too. When the
    // solve could not quite meet a hold (a knee bent too far for its planted foot), the neighbours
    // still keep it: the miss stays on this frame, where the readout reports it, instead of the
    // layer sliding the foot over the whole span (docs/experiments/ik.md, "Paste, mirror and rotate on standing
    // frames").
    const std::string label = jointRotationLabel(doc.clip().skeleton.joints[r.joint].name, doc.frame());
    const std::string err =
        doc.setCurrentPose(solved.pose, label, EditorDocument::PoseHolds::kSolved, rotationMovers(doc, r.joint));
    if (result) *result = std::move(solved);
    return err;
}

}  // namespace mgp
