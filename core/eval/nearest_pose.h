#pragma once
// How close a pose is to real ones, in joint angles (docs/maths.md §14, Table 2's learned-vs-plain
// comparison): the RMS over the non-root DOFs of the pose vector (indices 3..P−1: the 44 of the
// ASF vector, every non-root rotation channel of a BVH one), each difference wrapped to ±180°, to
// the nearest of a set of candidate poses.
#include <Eigen/Core>

#include <limits>
#include <vector>

namespace mgp {

// Which candidate row is nearest and how far (degrees, RMS over the non-root DOFs).
struct NearestPose {
    int row = -1;  // -1 when there are no candidates
    double rmsDeg = std::numeric_limits<double>::infinity();
};

// pose: P ≥ 4 DOFs (degrees); candidates: one pose per row (P columns) (the first row wins a tie).
NearestPose nearestPose(const Eigen::VectorXd& pose, const Eigen::MatrixXd& candidates);
// The nearest captured frame over several clips' pose matrices (clipPoses[c]: one pose vector per
// frame of clip c): which clip, which frame of it, how far. Ties go to the earlier clip, then the
// earlier frame. clip = row = −1 when there are no frames.
struct NearestFrame {
    int clip = -1;
    int frame = -1;
    double rmsDeg = std::numeric_limits<double>::infinity();
};
NearestFrame nearestFrame(const Eigen::VectorXd& pose, const std::vector<Eigen::MatrixXd>& clipPoses);
// Its distance alone: +∞ when there are no candidates.
double nearestPoseRmsDeg(const Eigen::VectorXd& pose, const Eigen::MatrixXd& candidates);

}  // namespace mgp
