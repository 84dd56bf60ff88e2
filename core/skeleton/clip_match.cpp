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
            return differs(difference,
                           "joint " + std::to_string(j + 1) + " is " + ja[j].name + " against " + jb[j].name);
    if (a.frameCount() != b.frameCount())
        return differs(difference,
                       std::to_string(a.frameCount()) + " frames against " + std::to_string(b.frameCount()));
    if (a.skeleton.poseVector != b.skeleton.poseVector)
        return differs(difference, "an ASF pose vector against a BVH channel one");
    const PoseLayout layout(a.skeleton);
    Eigen::VectorXd ya(layout.size()), yb(layout.size());
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
        for (int d = 0; d < layout.size(); ++d) {
            const double gap = std::abs(wrap180(ya[d] - yb[d]));
            if (!(gap <= kTolerance)) {
                std::snprintf(text, sizeof text, "frame %d, %s: %.3g° apart", f + 1,
                              layout.dofName(a.skeleton, d).c_str(), gap);
                return differs(difference, text);
            }
        }
    }
    return true;
}

namespace {
std::string vec3(const Eigen::Vector3d& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.4g, %.4g, %.4g)", v.x(), v.y(), v.z());
    return text;
}

std::string dofText(const std::array<bool, 3>& dof) {
    std::string out;
    for (int k = 0; k < 3; ++k)
        if (dof[static_cast<std::size_t>(k)]) out += std::string(out.empty() ? "" : " ") + "r" + "xyz"[k];
    return out.empty() ? "none" : out;
}
}  // namespace

bool sameSkeleton(const Skeleton& a, const Skeleton& b, std::string* difference) {
    const auto& ja = a.joints;
    const auto& jb = b.joints;
    for (std::size_t j = 0; j < ja.size() && j < jb.size(); ++j) {
        const Joint& x = ja[j];
        const Joint& y = jb[j];
        const std::string where = "joint " + std::to_string(j + 1) + " ";
        if (x.name != y.name) return differs(difference, where + "is " + x.name + " against " + y.name);
        const std::string at = where + x.name + ": ";
        if (x.parent != y.parent) {
            auto parentName = [](const std::vector<Joint>& js, int p) {
                return p < 0 ? std::string("none") : js[p].name;
            };
            return differs(difference,
                           at + "parent " + parentName(ja, x.parent) + " against " + parentName(jb, y.parent));
        }
        if (x.dof != y.dof)
            return differs(difference, at + "DOF channels " + dofText(x.dof) + " against " + dofText(y.dof));
        if (x.order != y.order) return differs(difference, at + "a different rotation order");
        if (!((x.offsetCm - y.offsetCm).cwiseAbs().maxCoeff() <= kSkeletonToleranceCm))
            return differs(difference, at + "offset " + vec3(x.offsetCm) + " cm against " + vec3(y.offsetCm) + " cm");
        if (!((x.tailCm - y.tailCm).cwiseAbs().maxCoeff() <= kSkeletonToleranceCm))
            return differs(difference, at + "bone (direction × length) " + vec3(x.tailCm) + " cm against " +
                                           vec3(y.tailCm) + " cm");
        if (!((x.axis - y.axis).cwiseAbs().maxCoeff() <= kSkeletonAxisTolerance))
            return differs(difference, at + "a different axis frame");
    }
    if (ja.size() != jb.size())
        return differs(difference, std::to_string(ja.size()) + " joints against " + std::to_string(jb.size()));
    if (a.poseVector != b.poseVector) return differs(difference, "an ASF skeleton against a BVH one");
    return true;
}

}  // namespace mgp
