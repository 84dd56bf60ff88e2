#include "skeleton/clip_match.h"

#include <cmath>
#include <cstdio>

#include "skeleton/rotation.h"

namespace mgp {

namespace {
constexpr double kTolerance = 1e-6;  // degrees and cm

bool differs(std::string* out, const std::string& what) {
    if (out) *out = what;
    return false;
}
}  // namespace

bool sameCapture(const Clip& a, const Clip& b, std::string* difference) {
    const auto& ja = a.skeleton.joints;
    const auto& jb = b.skeleton.joints;
    if (ja.size() != jb.size())
        return differs(difference, std::to_string(ja.size()) + " joints against " + std::to_string(jb.size()));
    for (std::size_t j = 0; j < ja.size(); ++j)
        if (ja[j].name != jb[j].name)
            return differs(difference, "joint " + std::to_string(j + 1) + " is " + ja[j].name + " against " + jb[j].name);
    if (a.frameCount() != b.frameCount())
        return differs(difference,
                       std::to_string(a.frameCount()) + " frames against " + std::to_string(b.frameCount()));
    const PoseLayout layout(a.skeleton);
    Eigen::VectorXd ya(kPoseDofs), yb(kPoseDofs);
    char text[160];
    for (int f = 0; f < a.frameCount(); ++f) {
        const Pose& pa = a.frames[f];
        const Pose& pb = b.frames[f];
        const double rootGap = (pa.rootCm - pb.rootCm).norm();
        if (!(rootGap <= kTolerance)) {
            std::snprintf(text, sizeof text, "frame %d, root position: %.3g cm apart", f + 1, rootGap);
            return differs(difference, text);
        }
        layout.extract(pa, ya.data());
        layout.extract(pb, yb.data());
        for (int d = 0; d < kPoseDofs; ++d) {
            const double gap = std::abs(wrap180(ya[d] - yb[d]));
            if (!(gap <= kTolerance)) {
                std::snprintf(text, sizeof text, "frame %d, %s r%c: %.3g° apart", f + 1, poseDofTable()[d].bone,
                              "xyz"[poseDofTable()[d].axis], gap);
                return differs(difference, text);
            }
        }
    }
    return true;
}

}  // namespace mgp
