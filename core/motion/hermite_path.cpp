#include "motion/hermite_path.h"

#include <algorithm>
#include <stdexcept>

namespace mgp {

HermitePath::HermitePath(std::vector<HermiteKey> keys, const Eigen::Vector3d& startTangent,
                         const Eigen::Vector3d& endTangent)
    : keys_(std::move(keys)) {
    if (keys_.size() < 2)
        throw std::invalid_argument("expected at least 2 Hermite keys, found " + std::to_string(keys_.size()));
    for (std::size_t i = 1; i < keys_.size(); ++i)
        if (!(keys_[i].frame > keys_[i - 1].frame))
            throw std::invalid_argument("expected strictly increasing key frames, found " +
                                        std::to_string(keys_[i - 1].frame) + " then " + std::to_string(keys_[i].frame));
    const std::size_t n = keys_.size();
    tangents_.resize(n);
    tangents_[0] = startTangent;
    tangents_[n - 1] = endTangent;
    for (std::size_t i = 1; i + 1 < n; ++i)
        tangents_[i] = (keys_[i + 1].positionCm - keys_[i - 1].positionCm) / (keys_[i + 1].frame - keys_[i - 1].frame);
}

int HermitePath::segmentOf(double t) const {
    const auto it =
        std::upper_bound(keys_.begin(), keys_.end(), t, [](double v, const HermiteKey& k) { return v < k.frame; });
    const int i = static_cast<int>(it - keys_.begin()) - 1;
    return std::clamp(i, 0, static_cast<int>(keys_.size()) - 2);
}

Eigen::Vector3d HermitePath::position(double t) const {
    t = std::clamp(t, keys_.front().frame, keys_.back().frame);
    const int i = segmentOf(t);
    const double h = keys_[i + 1].frame - keys_[i].frame;
    const double u = (t - keys_[i].frame) / h;
    const double u2 = u * u, u3 = u2 * u;
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
    return h00 * keys_[i].positionCm + h10 * h * tangents_[i] + h01 * keys_[i + 1].positionCm +
           h11 * h * tangents_[i + 1];
}

Eigen::Vector3d HermitePath::velocity(double t) const {
    t = std::clamp(t, keys_.front().frame, keys_.back().frame);
    const int i = segmentOf(t);
    const double h = keys_[i + 1].frame - keys_[i].frame;
    const double u = (t - keys_[i].frame) / h;
    const double u2 = u * u;
    // d/dt = (1/h) d/du.
    const double d00 = 6 * u2 - 6 * u, d10 = 3 * u2 - 4 * u + 1, d01 = -6 * u2 + 6 * u, d11 = 3 * u2 - 2 * u;
    return (d00 * keys_[i].positionCm + d01 * keys_[i + 1].positionCm) / h + d10 * tangents_[i] +
           d11 * tangents_[i + 1];
}

Eigen::Vector3d capturedVelocity(const std::vector<Eigen::Vector3d>& trajectory, int t) {
    const int last = static_cast<int>(trajectory.size()) - 1;
    if (last < 1) return Eigen::Vector3d::Zero();
    const int a = std::max(0, t - 1), b = std::min(last, t + 1);
    return (trajectory[b] - trajectory[a]) / double(b - a);
}

}  // namespace mgp
