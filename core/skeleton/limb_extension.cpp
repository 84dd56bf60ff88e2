#include "skeleton/limb_extension.h"

namespace mgp {

std::optional<double> limbExtension(const Skeleton& skeleton, const FkState& fk, Effector e) {
    const char* upper = nullptr;
    const char* lower = nullptr;
    switch (e) {
        case Effector::kLHand: upper = "lhumerus", lower = "lradius"; break;
        case Effector::kRHand: upper = "rhumerus", lower = "rradius"; break;
        case Effector::kLFoot: upper = "lfemur", lower = "ltibia"; break;
        case Effector::kRFoot: upper = "rfemur", lower = "rtibia"; break;
        default: return std::nullopt;
    }
    const int a = skeleton.findBone(upper), b = skeleton.findBone(lower);
    if (a < 0 || b < 0) return std::nullopt;
    const Eigen::Vector3d root = fk.jointCm[a], middle = fk.jointCm[b], end = boneEndCm(skeleton, fk, b);
    const double path = (middle - root).norm() + (end - middle).norm();
    if (!(path > 0.0)) return std::nullopt;
    return (end - root).norm() / path;
}

}  // namespace mgp
