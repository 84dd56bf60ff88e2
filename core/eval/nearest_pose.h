#pragma once
// How close a pose is to real ones, in joint angles (docs/maths.md §14, Table 2's learned-vs-plain
// comparison): the RMS over the 44 non-root DOFs of the §2.3 pose (indices 3..46), each
// difference wrapped to ±180°, to the nearest of a set of candidate poses.
#include <Eigen/Core>

#include <limits>

namespace mgp {

// Which candidate row is nearest and how far (degrees, RMS over the non-root DOFs).
struct NearestPose {
    int row = -1;  // -1 when there are no candidates
    double rmsDeg = std::numeric_limits<double>::infinity();
};

// pose: 47 DOFs (degrees); candidates: one pose per row (the first row wins a tie).
NearestPose nearestPose(const Eigen::VectorXd& pose, const Eigen::MatrixXd& candidates);
// Its distance alone: +∞ when there are no candidates.
double nearestPoseRmsDeg(const Eigen::VectorXd& pose, const Eigen::MatrixXd& candidates);

}  // namespace mgp
