#include "motion/pose_layer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace mgp {
namespace {

// a − b in degrees, the short way round: in (−180, 180].
double angleDeltaDeg(double a, double b) {
    double d = std::remainder(a - b, 360.0);
    if (d <= -180.0) d += 360.0;
    return d;
}

}  // namespace

double poseLayerWeight(int t, int t0, int radius) {
    if (t == t0) return 1.0;
    if (radius < 1 || std::abs(t - t0) >= radius) return 0.0;
    const double d = static_cast<double>(std::abs(t - t0)) / radius;
    return (1.0 - d) * (1.0 - d) * (1.0 + 2.0 * d);
}

void addPoseLayer(std::vector<Pose>& frames, int t0, int radius, const Pose& from, const Pose& to) {
    const Eigen::Vector3d rootDelta = to.rootCm - from.rootCm;
    std::vector<Eigen::Vector3d> angleDelta(to.anglesDeg.size());
    for (std::size_t j = 0; j < angleDelta.size(); ++j)
        for (int a = 0; a < 3; ++a) angleDelta[j][a] = angleDeltaDeg(to.anglesDeg[j][a], from.anglesDeg[j][a]);
    const int n = static_cast<int>(frames.size());
    for (int t = std::max(0, t0 - radius); t <= std::min(n - 1, t0 + radius); ++t) {
        const double w = poseLayerWeight(t, t0, radius);
        Pose& p = frames[static_cast<std::size_t>(t)];
        p.rootCm += w * rootDelta;
        for (std::size_t j = 0; j < angleDelta.size() && j < p.anglesDeg.size(); ++j)
            p.anglesDeg[j] += w * angleDelta[j];
    }
}

}  // namespace mgp
