#include "ik/locality.h"

#include <algorithm>

#include "skeleton/pose_layout.h"

namespace mgp {

std::vector<double> localityWeights(const Skeleton& sk, const std::vector<Effector>& effectors) {
    const PoseLayout layout(sk);
    // hops[j]: joints from j down to the nearest target's end joint, when j is on its chain.
    std::vector<int> hops(sk.jointCount(), -1);
    for (Effector e : effectors) {
        int j = sk.effectorSite(e).joint;
        for (int h = 0; j >= 0; ++h, j = sk.joints[j].parent)
            if (hops[j] < 0 || h < hops[j]) hops[j] = h;
    }
    std::vector<double> w(layout.size(), 1.0);
    for (int dof = 0; dof < layout.size(); ++dof) {
        const int j = layout.joint(dof);
        if (j <= 0 || hops[j] < 0) continue;  // the root's rotation and joints off every chain
        w[dof] = std::clamp(double(hops[j] - kLocalityFreeHops) / kLocalityRampHops, 0.0, 1.0);
    }
    return w;
}

std::vector<double> localityDofCost(const Skeleton& skeleton, const std::vector<Effector>& effectors, double cost) {
    std::vector<double> m = localityWeights(skeleton, effectors);
    for (double& w : m) w = 1.0 + cost * w;
    return m;
}

}  // namespace mgp
