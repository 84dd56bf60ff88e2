#include "eval/nearest_pose.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "skeleton/pose_layout.h"
#include "skeleton/rotation.h"

namespace mgp {

double nearestPoseRmsDeg(const Eigen::VectorXd& pose, const Eigen::MatrixXd& candidates) {
    double best = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 0; i < candidates.rows(); ++i) {
        double sum = 0.0;
        for (int k = 3; k < kPoseDofs; ++k) sum += std::pow(wrap180(pose[k] - candidates(i, k)), 2);
        best = std::min(best, std::sqrt(sum / (kPoseDofs - 3)));
    }
    return best;
}

}  // namespace mgp
