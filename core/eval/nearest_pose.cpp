#include "eval/nearest_pose.h"

#include <cmath>
#include <limits>

#include "skeleton/pose_layout.h"
#include "skeleton/rotation.h"

namespace mgp {

NearestPose nearestPose(const Eigen::VectorXd& pose, const Eigen::MatrixXd& candidates) {
    NearestPose best;
    for (Eigen::Index i = 0; i < candidates.rows(); ++i) {
        double sum = 0.0;
        for (int k = 3; k < kPoseDofs; ++k) sum += std::pow(wrap180(pose[k] - candidates(i, k)), 2);
        const double rms = std::sqrt(sum / (kPoseDofs - 3));
        if (rms < best.rmsDeg) best = {static_cast<int>(i), rms};
    }
    return best;
}

double nearestPoseRmsDeg(const Eigen::VectorXd& pose, const Eigen::MatrixXd& candidates) {
    return nearestPose(pose, candidates).rmsDeg;
}

}  // namespace mgp
