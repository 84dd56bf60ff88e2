#pragma once
// Euler rotations. Conventions (used everywhere in MotionGP):
//  - right-handed, column vectors, angles in DEGREES at every interface;
//  - a RotationOrder lists axes from the OUTERMOST (leftmost) matrix to the innermost, so the
//    order {Z, Y, X} builds Rz·Ry·Rx, i.e. x is applied first. CMU ASF "dof rx ry rz" and
//    "axis ... XYZ" both mean {Z, Y, X}; a BVH "CHANNELS Zrotation Xrotation Yrotation" means
//    {Z, X, Y}.
#include <Eigen/Core>
#include <array>

namespace mgp {

enum Axis : int { kAxisX = 0, kAxisY = 1, kAxisZ = 2 };

using RotationOrder = std::array<int, 3>;  // outermost first
inline constexpr RotationOrder kOrderZYX{kAxisZ, kAxisY, kAxisX};

constexpr double kDegToRad = 0.017453292519943295769;
constexpr double kRadToDeg = 57.295779513082320877;

Eigen::Matrix3d axisRotation(int axis, double radians);
// anglesDeg holds (x, y, z) angles; the matrix is R_order[0] · R_order[1] · R_order[2].
Eigen::Matrix3d eulerMatrix(const Eigen::Vector3d& anglesDeg, const RotationOrder& order);
// Inverse of eulerMatrix for the order {Z, Y, X} (x first): returns (x, y, z) in degrees,
// y in [-90, 90].
Eigen::Vector3d eulerZYXFromMatrix(const Eigen::Matrix3d& r);
// Inverse of eulerMatrix for any order of three distinct axes: returns (x, y, z) in degrees with
// the middle axis's angle in [-90, 90] (at gimbal lock the innermost angle is 0). The other
// solution of the same matrix is eulerAlternative of this one.
Eigen::Vector3d eulerFromMatrix(const Eigen::Matrix3d& r, const RotationOrder& order);
// The second Euler triple of the same rotation: outer and inner angles + 180°, middle 180° − it.
Eigen::Vector3d eulerAlternative(const Eigen::Vector3d& anglesDeg, const RotationOrder& order);
// `angleDeg` moved by whole turns to within 180° of `referenceDeg`: angle − 360·round((angle − reference)/360).
double wrapNear(double angleDeg, double referenceDeg);
// An angle difference wrapped into [−180, 180]: wrapNear(angleDeg, 0).
inline double wrap180(double angleDeg) { return wrapNear(angleDeg, 0.0); }

}  // namespace mgp
