#pragma once
// Forward kinematics and the analytic effector Jacobian (docs/maths.md §2).
// Units: positions in cm, world Y up; Jacobian columns in cm per DEGREE.
#include <Eigen/Core>
#include <vector>

#include "skeleton/pose_layout.h"
#include "skeleton/skeleton.h"

namespace mgp {

// Per-joint results of one FK pass. Reuse one instance across calls: forwardKinematics only
// resizes it when the joint count changes, so a solver loop allocates nothing.
struct FkState {
    std::vector<Eigen::Vector3d> jointCm;      // joint (bone start) positions
    std::vector<Eigen::Matrix3d> global;       // G_j
    std::vector<Eigen::Matrix3d> parentFrame;  // G_parent · C_j (the DOF axes' base frame)
};

void forwardKinematics(const Skeleton& skeleton, const Pose& pose, FkState& fk);

// The rotation about world Y that takes the root's forward (+z) axis onto +z: applied to
// root-relative points it removes the heading (the yaw ψ = atan2(f_x, f_z) of that axis), so poses
// facing different ways compare as body shapes.
Eigen::Matrix3d headingRemoval(const FkState& fk);
// That yaw ψ itself (radians): headingRemoval is the rotation by −ψ about world Y.
double headingRadians(const FkState& fk);

// End point of joint j's bone (p_j + G_j · tail_j).
Eigen::Vector3d boneEndCm(const Skeleton& skeleton, const FkState& fk, int joint);
Eigen::Vector3d effectorCm(const Skeleton& skeleton, const FkState& fk, Effector e);
// One effector of a pose (runs FK; use the FkState form when you need several).
Eigen::Vector3d effectorCm(const Skeleton& skeleton, const Pose& pose, Effector e);

// World axis of joint j's rotation DOF `axis` (unit vector), given its current angles.
Eigen::Vector3d dofWorldAxis(const Skeleton& skeleton, const FkState& fk, const Pose& pose, int joint, int axis);

// d(effector position)/d(y) for the P pose-vector DOFs, 3×P, cm/deg. Columns of DOFs that are not
// ancestors of the effector (or absent from the skeleton) are exactly 0.
void effectorJacobian(const Skeleton& skeleton, const PoseLayout& layout, const FkState& fk, const Pose& pose,
                      Effector e, Eigen::Ref<Eigen::Matrix<double, 3, Eigen::Dynamic>> jac);
// The same for a point fixed in joint `pointJoint`'s frame, now at world position `pointCm`: column
// i is ω_i × (p − q_i) in cm per degree for the DOFs of the joint and its ancestors (a joint's own
// origin: its own DOFs' columns are 0).
void pointJacobian(const Skeleton& skeleton, const PoseLayout& layout, const FkState& fk, const Pose& pose,
                   int pointJoint, const Eigen::Vector3d& pointCm,
                   Eigen::Ref<Eigen::Matrix<double, 3, Eigen::Dynamic>> jac);

// λ · ∂²(effector position)/∂y² for the P pose-vector DOFs (P×P, cm/deg², symmetric): the
// second-order term a Newton step on ‖FK − c‖² or on a pinned effector's multiplier needs. For
// DOFs a (upstream, or the same DOF) and b on the effector's chain, with world axes ω and b's
// pivot q_b: ∂²p/∂θ_a∂θ_b = (π/180)² ω_a × (ω_b × (p − q_b)). Other entries are exactly 0.
void effectorHessianContracted(const Skeleton& skeleton, const PoseLayout& layout, const FkState& fk, const Pose& pose,
                               Effector e, const Eigen::Vector3d& lambda, Eigen::Ref<Eigen::MatrixXd> out);
// The same for any point `p` fixed in joint `pointJoint`'s frame, ADDED to `out` (a sum over points,
// as the centre of mass needs).
void addPointHessianContracted(const Skeleton& skeleton, const PoseLayout& layout, const FkState& fk, const Pose& pose,
                               int pointJoint, const Eigen::Vector3d& p, const Eigen::Vector3d& lambda,
                               Eigen::Ref<Eigen::MatrixXd> out);

}  // namespace mgp
