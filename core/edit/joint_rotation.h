#pragma once
// Rotate joint: set one joint's DOFs directly, in degrees, as one undo step; optionally the rest
// of the pose follows the learned prior (docs/maths-ik.md §7).
//
//   plain          only that joint's animated angles change (its subtree turns with it), unless
//                  that moves what the frame holds (rotationHolds: pins, planted feet, and placed
//                  effectors that are not below the joint):
//                  then the hips and the legs bring those back (settleOnHolds, ik/plain_ik.h);
//   follow prior   those angles are held at the user's values and the rest of the pose (latent
//                  point and free DOFs) is re-solved to the most likely pose under the model,
//                  min over (x, free y) of L_IK, with the pinned effectors and the feet in ground
//                  contact held where they are on the frame (ConstrainedIkSolver with held DOFs),
//                  warm-started at the latent point that best explains the rotated pose; a hold
//                  that solve (which keeps the root translation) leaves off is settled the same way.
#include <Eigen/Core>
#include <optional>
#include <string>

#include "edit/editor_document.h"
#include "ik/constrained_ik.h"
#include "ik/plain_ik.h"

namespace mgp {

struct JointRotation {
    int joint = -1;
    Eigen::Vector3d anglesDeg = Eigen::Vector3d::Zero();  // (x, y, z); axes the joint lacks are ignored
    bool followPrior = false;
};

struct JointRotationResult {
    std::string error;  // "" when `pose` is the rotated pose
    Pose pose;
    bool learned = false;     // the prior re-solved the rest of the pose
    bool settled = false;     // settleOnHolds moved the legs and the root to keep the holds
    int holdCount = 0;        // what the frame holds (rotationHolds)
    double holdMissCm = 0.0;  // the farthest of them from its place in `pose`
    ConstrainedIkResult ik;   // the solve, when learned
};

// `pose` with joint's animated angles set to anglesDeg (the others untouched).
Pose rotateJoint(const Skeleton& skeleton, const Pose& pose, int joint, const Eigen::Vector3d& anglesDeg);
// The angles of `joint` that turn its frame (and its subtree) by `degrees` about the world axis
// `axisWorld`, right-handed, the rest of the pose as it is: a rotate gizmo's view ring. Of the two
// Euler triples of the turned rotation, the nearest to the joint's angles. Only for a joint that
// animates all three axes (a turn about an arbitrary axis needs them); nullopt otherwise.
std::optional<Eigen::Vector3d> anglesTurnedAboutWorldAxis(const Skeleton& skeleton, const Pose& pose, int joint,
                                                          const Eigen::Vector3d& axisWorld, double degrees);
// The held DOFs of a rotation: one per axis the joint animates.
std::vector<HeldDof> heldDofsOf(const Skeleton& skeleton, int joint, const Eigen::Vector3d& anglesDeg);
// What a rotation of `joint` with the prior holds on the current frame, at the current positions:
// the document's pins, its held effectors except those below `joint` (they move with it), and its
// feet in contact (not released), each effector once.
std::vector<IkConstraint> rotationHolds(const EditorDocument& doc, int joint);
// The rest of what the frame keeps in place: the held effectors below `joint`, which move with it.
std::vector<Effector> rotationMovers(const EditorDocument& doc, int joint);

// The rotated current pose (nothing changes in the document). With followPrior and no model,
// the error says so.
JointRotationResult solveJointRotation(EditorDocument& doc, const JointRotation& rotation, int maxIterations = 200);
// Solves and applies it as one undo step "rotate JOINT on frame N"; "" or why not.
std::string applyJointRotation(EditorDocument& doc, const JointRotation& rotation, JointRotationResult* out = nullptr);
// The undo label of a rotation of `jointName` on 0-based `frame`.
std::string jointRotationLabel(const std::string& jointName, int frame);

}  // namespace mgp
