#include "motion/foot_contacts.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "skeleton/forward_kinematics.h"

namespace mgp {
namespace {

void validateRule(const ContactRule& rule, double fps) {
    auto finitePositive = [](double v) { return std::isfinite(v) && v > 0.0; };
    if (!finitePositive(rule.enterHeightCm) || !finitePositive(rule.enterSpeedCmPerFrame))
        throw std::invalid_argument("contact rule: expected positive enter thresholds");
    if (!(rule.exitHeightCm >= rule.enterHeightCm) || !(rule.exitSpeedCmPerFrame >= rule.enterSpeedCmPerFrame))
        throw std::invalid_argument(
            "contact rule: expected exit thresholds at least the enter thresholds, found "
            "a tighter exit (no hysteresis)");
    if (rule.mergeGapFrames < 0)
        throw std::invalid_argument("contact rule: expected mergeGapFrames >= 0, found " +
                                    std::to_string(rule.mergeGapFrames));
    if (rule.minFrames < 1)
        throw std::invalid_argument("contact rule: expected minFrames >= 1, found " + std::to_string(rule.minFrames));
    if (!(rule.groundPercentile >= 0.0 && rule.groundPercentile <= 1.0))
        throw std::invalid_argument("contact rule: expected a ground percentile in [0, 1]");
    if (!finitePositive(fps)) throw std::invalid_argument("contact rule: expected a positive frame rate");
}

// The q-quantile (nearest rank) of a foot's heights.
double heightQuantile(const std::vector<Eigen::Vector3d>& foot, double q) {
    std::vector<double> h(foot.size());
    for (std::size_t i = 0; i < foot.size(); ++i) h[i] = foot[i].y();
    const std::size_t k = std::min(h.size() - 1, static_cast<std::size_t>(std::floor(q * double(h.size() - 1) + 0.5)));
    std::nth_element(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(k), h.end());
    return h[k];
}

double speedAt(const std::vector<Eigen::Vector3d>& foot, int t) {
    const int n = static_cast<int>(foot.size());
    if (n < 2) return 0.0;
    const int a = std::max(0, t - 1), b = std::min(n - 1, t + 1);
    return (foot[b] - foot[a]).norm() / double(b - a);
}

void detectOne(Effector e, const std::vector<Eigen::Vector3d>& foot, double groundCm, double speedScale,
               const ContactRule& rule, std::vector<FootContact>& out) {
    const int n = static_cast<int>(foot.size());
    bool planted = false;
    int start = 0;
    std::vector<FootContact> raw;
    auto close = [&](int last) { raw.push_back({e, start, last, true}); };
    for (int t = 0; t < n; ++t) {
        const double height = foot[t].y() - groundCm;
        const double speed = speedAt(foot, t);
        if (!planted) {
            if (height <= rule.enterHeightCm && speed <= rule.enterSpeedCmPerFrame * speedScale) {
                planted = true;
                start = t;
            }
        } else if (height > rule.exitHeightCm || speed > rule.exitSpeedCmPerFrame * speedScale) {
            planted = false;
            close(t - 1);
        }
    }
    if (planted) close(n - 1);
    std::vector<FootContact> merged;
    for (const FootContact& c : raw) {
        if (!merged.empty() && c.first - merged.back().last - 1 <= rule.mergeGapFrames)
            merged.back().last = c.last;
        else
            merged.push_back(c);
    }
    for (const FootContact& c : merged)
        if (c.length() >= rule.minFrames) out.push_back(c);
}

}  // namespace

const FootContact* ContactSet::at(Effector foot, int frame) const {
    for (const FootContact& c : contacts)
        if (c.foot == foot && c.enabled && c.contains(frame)) return &c;
    return nullptr;
}

FootContact* ContactSet::at(Effector foot, int frame) {
    return const_cast<FootContact*>(static_cast<const ContactSet&>(*this).at(foot, frame));
}

ContactSet detectFootContacts(const std::vector<Eigen::Vector3d>& leftFootCm,
                              const std::vector<Eigen::Vector3d>& rightFootCm, double fps, const ContactRule& rule) {
    validateRule(rule, fps);
    ContactSet set;
    if (leftFootCm.empty() && rightFootCm.empty()) return set;
    double ground = INFINITY;
    if (!leftFootCm.empty()) ground = std::min(ground, heightQuantile(leftFootCm, rule.groundPercentile));
    if (!rightFootCm.empty()) ground = std::min(ground, heightQuantile(rightFootCm, rule.groundPercentile));
    set.groundCm = ground;
    double lowest = INFINITY;
    for (const auto* foot : {&leftFootCm, &rightFootCm})
        for (const Eigen::Vector3d& p : *foot) lowest = std::min(lowest, p.y());
    set.floorCm = lowest;
    const double speedScale = 120.0 / fps;
    detectOne(Effector::kLFoot, leftFootCm, ground, speedScale, rule, set.contacts);
    detectOne(Effector::kRFoot, rightFootCm, ground, speedScale, rule, set.contacts);
    return set;
}

std::vector<Eigen::Vector3d> effectorTrajectory(const Skeleton& skeleton, const std::vector<Pose>& frames,
                                                Effector effector) {
    std::vector<Eigen::Vector3d> out;
    if (!skeleton.hasEffector(effector)) return out;
    out.reserve(frames.size());
    FkState fk;
    for (const Pose& pose : frames) {
        forwardKinematics(skeleton, pose, fk);
        out.push_back(effectorCm(skeleton, fk, effector));
    }
    return out;
}

std::vector<Eigen::Vector3d> effectorTrajectory(const Clip& clip, Effector effector) {
    return effectorTrajectory(clip.skeleton, clip.frames, effector);
}

ContactSet detectFootContacts(const Clip& clip, const ContactRule& rule) {
    return detectFootContacts(effectorTrajectory(clip, Effector::kLFoot), effectorTrajectory(clip, Effector::kRFoot),
                              clip.fps, rule);
}

std::vector<IkConstraint> contactPinsAt(const Clip& clip, const FkState& fk, const ContactSet& contacts, int frame,
                                        const std::vector<IkConstraint>& constraints, const bool* released) {
    std::vector<IkConstraint> out;
    for (Effector foot : {Effector::kLFoot, Effector::kRFoot}) {
        if (!clip.skeleton.hasEffector(foot) || (released && released[static_cast<int>(foot)]) ||
            !contacts.at(foot, frame))
            continue;
        bool constrained = false;
        for (const IkConstraint& c : constraints) constrained |= c.effector == foot;
        if (!constrained) out.push_back({foot, effectorCm(clip.skeleton, fk, foot), true});
    }
    return out;
}

}  // namespace mgp
