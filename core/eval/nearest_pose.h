#pragma once
// How close a pose is to real ones, in joint angles (docs/maths.md §14, Table 2's learned-vs-plain
// comparison): the RMS over the 44 non-root DOFs of the §2.3 pose (indices 3..46), each
// difference wrapped to ±180°, to the nearest of a set of candidate poses.
#include <Eigen/Core>

namespace mgp {

// a wrapped to [−180, 180] (degrees).
double wrap180(double a);

// pose: 47 DOFs (degrees); candidates: one pose per row. +∞ when there are no candidates.
double nearestPoseRmsDeg(const Eigen::VectorXd& pose, const Eigen::MatrixXd& candidates);

}  // namespace mgp
