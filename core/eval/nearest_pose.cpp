#include "eval/nearest_pose.h"

#include <cmath>
#include <limits>

#include "skeleton/rotation.h"

namespace mgp {

NearestPose nearestPose(const Eigen::VectorXd& pose, const Eigen::MatrixXd& candidates) {
    NearestPose best;
    for (Eigen::Index i = 0; i < candidates.rows(); ++i) {
        double sum = 0.0;
        for (Eigen::Index k = 3; k < pose.size(); ++k) sum += std::pow(wrap180(pose[k] - candidates(i, k)), 2);
        const double rms = std::sqrt(sum / static_cast<double>(pose.size() - 3));
        if (rms < best.rmsDeg) best = {static_cast<int>(i), rms};
    }
    return best;
}

NearestFrame nearestFrame(const Eigen::VectorXd& pose, const std::vector<Eigen::MatrixXd>& clipPoses) {
    NearestFrame best;
    for (std::size_t c = 0; c < clipPoses.size(); ++c) {
        const NearestPose n = nearestPose(pose, clipPoses[c]);
        if (n.row >= 0 && n.rmsDeg < best.rmsDeg) best = {static_cast<int>(c), n.row, n.rmsDeg};
    }
    return best;
}

double nearestPoseRmsDeg(const Eigen::VectorXd& pose, const Eigen::MatrixXd& candidates) {
    return nearestPose(pose, candidates).rmsDeg;
}

}  // namespace mgp
