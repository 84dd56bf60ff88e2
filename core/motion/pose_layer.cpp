#include "motion/pose_layer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

#include <Eigen/Geometry>

#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_mirror.h"
#include "skeleton/rotation.h"

namespace mgp {
namespace {

// a − b in degrees, the short way round: in (−180, 180].
double angleDeltaDeg(double a, double b) {
    double d = std::remainder(a - b, 360.0);
    if (d <= -180.0) d += 360.0;
    return d;
}

// The change from → to. A joint that animates all three axes changes by the rotation
// D = E(to)·E(from)ᵀ, applied at weight w as D^w·E(p) (Maya's layer accumulation "by layer"): a
// fast-turning joint under the layer keeps its angular speed, which adding Euler components does
// not (near gimbal lock those components turn the joint faster or slower). A joint with fewer
// axes, and the root translation, change by components (a one-axis hinge composes exactly so).
struct PoseChange {
    const Skeleton& skeleton;
    Eigen::Vector3d root;
    std::vector<Eigen::Vector3d> angles;      // component change (degrees), the short way round
    std::vector<Eigen::AngleAxisd> rotation;  // D of the three-axis joints (identity elsewhere)
    std::vector<bool> byRotation;             // the joint changes by D (three axes, and changed)

    PoseChange(const Skeleton& sk, const Pose& from, const Pose& to)
        : skeleton(sk),
          root(to.rootCm - from.rootCm),
          angles(to.anglesDeg.size()),
          rotation(to.anglesDeg.size(), Eigen::AngleAxisd::Identity()),
          byRotation(to.anglesDeg.size(), false) {
        for (std::size_t j = 0; j < angles.size(); ++j) {
            for (int a = 0; a < 3; ++a) angles[j][a] = angleDeltaDeg(to.anglesDeg[j][a], from.anglesDeg[j][a]);
            if (j >= sk.joints.size()) continue;
            const Joint& jt = sk.joints[j];
            if (!(jt.dof[0] && jt.dof[1] && jt.dof[2]) || to.anglesDeg[j] == from.anglesDeg[j]) continue;
            byRotation[j] = true;
            rotation[j] = Eigen::AngleAxisd(eulerMatrix(to.anglesDeg[j], jt.order) *
                                            eulerMatrix(from.anglesDeg[j], jt.order).transpose());
        }
    }
    void addTo(Pose& p, double w) const {
        p.rootCm += w * root;
        for (std::size_t j = 0; j < angles.size() && j < p.anglesDeg.size(); ++j) {
            if (!byRotation[j]) {
                p.anglesDeg[j] += w * angles[j];
                continue;
            }
            if (w == 0.0) continue;
            const Joint& jt = skeleton.joints[j];
            const Eigen::Matrix3d turned =
                Eigen::AngleAxisd(w * rotation[j].angle(), rotation[j].axis()) * eulerMatrix(p.anglesDeg[j], jt.order);
            // Of the two Euler triples, the one nearest the component blend: at w = 1 on t0 that is
            // `to` itself (up to whole turns), not the other solution of the same rotation.
            p.anglesDeg[j] = fitJointAngles(turned, jt.order, jt.dof, p.anglesDeg[j] + w * angles[j]);
        }
    }
};

// The effectors whose speed bounds a layer: the hands and the feet.
constexpr Effector kLayerEnds[] = {Effector::kLHand, Effector::kRHand, Effector::kLFoot, Effector::kRFoot};

// How much less (cm per frame step) another layer radius must gain than the one found, to replace it.
constexpr double kLayerExcessMarginCm = 0.05;

// Samples of the blend from + wΔ, w = 0, 1/16, …, 1: enough to see a hand swing out and back
// along an Euler blend (a mirrored arm) as well as its end points.
constexpr int kBlendSamples = 16;

}  // namespace

double poseLayerWeight(int t, int t0, int radius) {
    if (t == t0) return 1.0;
    if (radius < 1 || std::abs(t - t0) >= radius) return 0.0;
    const double d = static_cast<double>(std::abs(t - t0)) / radius;
    return (1.0 - d) * (1.0 - d) * (1.0 + 2.0 * d);
}

void addPoseLayer(const Skeleton& skeleton, std::vector<Pose>& frames, int t0, int radius, const Pose& from,
                  const Pose& to) {
    const PoseChange change(skeleton, from, to);
    const int n = static_cast<int>(frames.size());
    // Each side's blend ends by the clip's end, where the spread's span ends too: a side with
    // fewer than `radius` frames blends faster rather than stop short of zero.
    const int before = std::min(radius, t0), after = std::min(radius, n - 1 - t0);
    for (int t = t0 - before; t <= t0 + after; ++t)
        change.addTo(frames[static_cast<std::size_t>(t)], poseLayerWeight(t, t0, t < t0 ? before : after));
}

double poseLayerSteepestCm(const Skeleton& skeleton, const Pose& from, const Pose& to) {
    const PoseChange change(skeleton, from, to);
    const auto& ends = kLayerEnds;
    Eigen::Vector3d previous[4];
    double steepest = 0.0;
    FkState fk;
    for (int i = 0; i <= kBlendSamples; ++i) {
        Pose p = from;
        change.addTo(p, static_cast<double>(i) / kBlendSamples);
        forwardKinematics(skeleton, p, fk);
        for (int e = 0; e < 4; ++e) {
            if (skeleton.effectorSite(ends[e]).joint < 0) continue;
            const Eigen::Vector3d at = effectorCm(skeleton, fk, ends[e]);
            if (i > 0) steepest = std::max(steepest, (at - previous[e]).norm() * kBlendSamples);
            previous[e] = at;
        }
    }
    return steepest;
}

int layerBlendFrames(double distanceCm, double fps) {
    const double needed = 1.5 * distanceCm * fps / kLayerSpeedCmPerSecond;
    if (!(needed > 0.0)) return 0;
    // (The 1e-9 keeps a whole number of frames, computed a rounding error above it, whole.)
    return needed >= 1e6 ? 1000000 : static_cast<int>(std::ceil(needed - 1e-9));
}

int poseLayerRadius(const Skeleton& skeleton, const Pose& from, const Pose& to, int radius, double fps) {
    if (radius < 1 || !(fps > 0.0)) return radius;
    // The blend's slope is at most 1.5/r per frame (at d = ½), so an effector whose blended path
    // has slope S (cm per unit weight) gains at most 1.5·S/r cm per frame.
    return std::clamp(layerBlendFrames(poseLayerSteepestCm(skeleton, from, to), fps), radius, kLayerWidening * radius);
}

namespace {

// The hands' and feet's positions on each frame of `frames` (a row of four per frame; NaN where the
// skeleton has no such effector).
std::vector<std::array<Eigen::Vector3d, 4>> endPositions(const Skeleton& skeleton, const std::vector<Pose>& frames) {
    const auto& ends = kLayerEnds;
    std::vector<std::array<Eigen::Vector3d, 4>> out(frames.size());
    FkState fk;
    for (std::size_t t = 0; t < frames.size(); ++t) {
        forwardKinematics(skeleton, frames[t], fk);
        for (int e = 0; e < 4; ++e)
            out[t][e] = skeleton.effectorSite(ends[e]).joint < 0 ? Eigen::Vector3d::Constant(std::nan(""))
                                                                 : effectorCm(skeleton, fk, ends[e]);
    }
    return out;
}

// poseLayerExcessCm on `window`, frames of the clip around the changed frame window[t0] that reach
// at least radius + 1 frames past it on each side or to the clip's end (so the layer on them is
// the clip's); `under` is endPositions(window).
double layerExcessOnWindow(const Skeleton& skeleton, const std::vector<Pose>& window,
                           const std::vector<std::array<Eigen::Vector3d, 4>>& under, int t0, int radius,
                           const Pose& to) {
    const int n = static_cast<int>(window.size());
    const int first = std::max(0, t0 - radius - 1), last = std::min(n - 1, t0 + radius + 1);
    std::vector<Pose> layered(window.begin() + first, window.begin() + last + 1);
    addPoseLayer(skeleton, layered, t0 - first, radius, window[static_cast<std::size_t>(t0)], to);
    const std::vector<std::array<Eigen::Vector3d, 4>> moved = endPositions(skeleton, layered);
    double worst = 0.0;
    for (int s = 0; s + 1 < static_cast<int>(layered.size()); ++s)
        for (int e = 0; e < 4; ++e) {
            const auto u = static_cast<std::size_t>(first + s);
            const double gain = (moved[s + 1][e] - moved[s][e]).norm() - (under[u + 1][e] - under[u][e]).norm();
            if (gain > worst) worst = gain;  // (NaN, no such effector, compares false)
        }
    return worst;
}

}  // namespace

double poseLayerExcessCm(const Skeleton& skeleton, const std::vector<Pose>& under, int t0, int radius, const Pose& to) {
    if (t0 < 0 || t0 >= static_cast<int>(under.size())) return 0.0;
    return layerExcessOnWindow(skeleton, under, endPositions(skeleton, under), t0, radius, to);
}

int poseLayerRadiusOver(const Skeleton& skeleton, const std::vector<Pose>& under, int t0, const Pose& to, int radius,
                        double fps) {
    const int n = static_cast<int>(under.size());
    const int rule = poseLayerRadius(skeleton, under.at(static_cast<std::size_t>(t0)), to, radius, fps);
    if (radius < 1 || !(fps > 0.0)) return rule;
    // Every candidate's layer lies within the widest one's frames: measure on those only.
    const int widest = kLayerWidening * radius;
    const int first = std::max(0, t0 - widest - 1), last = std::min(n - 1, t0 + widest + 1);
    const std::vector<Pose> window(under.begin() + first, under.begin() + last + 1);
    const std::vector<std::array<Eigen::Vector3d, 4>> ends = endPositions(skeleton, window);
    const int local = t0 - first;
    double best = layerExcessOnWindow(skeleton, window, ends, local, rule, to);
    if (best <= kLayerSpeedCmPerSecond / fps) return rule;
    int chosen = rule;
    for (int r = radius; r <= widest; r += std::max(1, radius / 2)) {
        if (r == rule) continue;
        // A radius replaces the one found only if it gains clearly less (kLayerExcessMarginCm): a
        // layer twice as wide for a tenth of a millimetre would only edit more frames.
        const double excess = layerExcessOnWindow(skeleton, window, ends, local, r, to);
        if (excess < best - kLayerExcessMarginCm) best = excess, chosen = r;
    }
    return chosen;
}

}  // namespace mgp
