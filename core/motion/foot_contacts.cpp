#include "motion/foot_contacts.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "skeleton/forward_kinematics.h"

namespace mgp {
namespace {

bool finitePositive(double v) { return std::isfinite(v) && v > 0.0; }

void validateThresholds(const ContactThresholds& t, const char* point) {
    if (!finitePositive(t.enterHeightCm) || !finitePositive(t.enterSpeedCmPerFrame))
        throw std::invalid_argument(std::string("contact rule (") + point + "): expected positive enter thresholds");
    if (!(t.exitHeightCm >= t.enterHeightCm) || !(t.exitSpeedCmPerFrame >= t.enterSpeedCmPerFrame))
        throw std::invalid_argument(std::string("contact rule (") + point +
                                    "): expected exit thresholds at least the enter thresholds, found a tighter exit "
                                    "(no hysteresis)");
}

void validateRule(const ContactRule& rule, double fps) {
    validateThresholds(rule.toe, "toe");
    validateThresholds(rule.heel, "heel");
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

// Ranges at most `gap` frames apart become one (`ranges` sorted by first frame).
std::vector<FrameRange> mergeRanges(std::vector<FrameRange> ranges, int gap) {
    std::sort(ranges.begin(), ranges.end(), [](const FrameRange& a, const FrameRange& b) { return a.first < b.first; });
    std::vector<FrameRange> merged;
    for (const FrameRange& r : ranges) {
        if (!merged.empty() && r.first - merged.back().last - 1 <= gap)
            merged.back().last = std::max(merged.back().last, r.last);
        else
            merged.push_back(r);
    }
    return merged;
}

// The frames one point is down: low and slow, with hysteresis; jitters merged, short phases dropped.
std::vector<FrameRange> pointPhases(const std::vector<Eigen::Vector3d>& point, double groundCm, double speedScale,
                                    const ContactThresholds& th, const ContactRule& rule) {
    const int n = static_cast<int>(point.size());
    bool down = false;
    int start = 0;
    std::vector<FrameRange> raw;
    for (int t = 0; t < n; ++t) {
        const double height = point[t].y() - groundCm;
        const double speed = speedAt(point, t);
        if (!down) {
            if (height <= th.enterHeightCm && speed <= th.enterSpeedCmPerFrame * speedScale) {
                down = true;
                start = t;
            }
        } else if (height > th.exitHeightCm || speed > th.exitSpeedCmPerFrame * speedScale) {
            down = false;
            raw.push_back({start, t - 1});
        }
    }
    if (down) raw.push_back({start, n - 1});
    std::vector<FrameRange> out;
    for (const FrameRange& r : mergeRanges(std::move(raw), rule.mergeGapFrames))
        if (r.last - r.first + 1 >= rule.minFrames) out.push_back(r);
    return out;
}

// The span of the phases inside `stance` (empty when none is).
FrameRange phaseWithin(const std::vector<FrameRange>& phases, const FrameRange& stance) {
    FrameRange out{stance.last + 1, stance.first - 1};
    for (const FrameRange& p : phases)
        if (p.first >= stance.first && p.last <= stance.last) {
            out.first = std::min(out.first, p.first);
            out.last = std::max(out.last, p.last);
        }
    return out.empty() ? FrameRange{} : out;
}

// A foot's stances: the union of its heel and toe phases.
void detectFoot(Effector foot, const FootTrack& track, const ContactSet& set, double speedScale,
                const ContactRule& rule, std::vector<FootContact>& out) {
    const std::vector<FrameRange> toe = pointPhases(track.toeCm, set.groundCm, speedScale, rule.toe, rule);
    const std::vector<FrameRange> heel = pointPhases(track.heelCm, set.heelGroundCm, speedScale, rule.heel, rule);
    std::vector<FrameRange> both(toe);
    both.insert(both.end(), heel.begin(), heel.end());
    for (const FrameRange& stance : mergeRanges(std::move(both), rule.mergeGapFrames)) {
        FootContact c;
        c.foot = foot;
        c.first = stance.first;
        c.last = stance.last;
        c.heel = phaseWithin(heel, stance);
        c.toe = phaseWithin(toe, stance);
        out.push_back(c);
    }
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

ContactSet detectFootContacts(const FootTrack& left, const FootTrack& right, double fps, const ContactRule& rule) {
    validateRule(rule, fps);
    for (const FootTrack* track : {&left, &right})
        if (!track->heelCm.empty() && track->heelCm.size() != track->toeCm.size())
            throw std::invalid_argument("foot contacts: expected a heel track as long as its toe track (" +
                                        std::to_string(track->toeCm.size()) + " frames), found " +
                                        std::to_string(track->heelCm.size()));
    ContactSet set;
    if (left.toeCm.empty() && right.toeCm.empty()) return set;
    // Each point's ground: the lower foot's percentile, so that a foot that never lands (held up
    // through the clip) is not declared planted at its own lowest height.
    auto groundOf = [&](const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
        double ground = INFINITY;
        if (!a.empty()) ground = std::min(ground, heightQuantile(a, rule.groundPercentile));
        if (!b.empty()) ground = std::min(ground, heightQuantile(b, rule.groundPercentile));
        return std::isfinite(ground) ? ground : 0.0;
    };
    set.groundCm = groundOf(left.toeCm, right.toeCm);
    set.heelGroundCm = groundOf(left.heelCm, right.heelCm);
    double lowest = INFINITY;
    for (const auto* foot : {&left.toeCm, &right.toeCm})
        for (const Eigen::Vector3d& p : *foot) lowest = std::min(lowest, p.y());
    set.floorCm = lowest;
    const double speedScale = 120.0 / fps;
    detectFoot(Effector::kLFoot, left, set, speedScale, rule, set.contacts);
    detectFoot(Effector::kRFoot, right, set, speedScale, rule, set.contacts);
    return set;
}

ContactSet detectFootContacts(const std::vector<Eigen::Vector3d>& leftFootCm,
                              const std::vector<Eigen::Vector3d>& rightFootCm, double fps, const ContactRule& rule) {
    return detectFootContacts(FootTrack{leftFootCm, {}}, FootTrack{rightFootCm, {}}, fps, rule);
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

FootTrack footTrack(const Clip& clip, Effector foot) {
    FootTrack track;
    if (!clip.skeleton.hasEffector(foot)) return track;
    // The heel is the start of the foot bone, found by its ASF role; else the effector's own joint
    // (the foot effector is the end of the foot bone) or, at the start of the toes, its parent.
    const EffectorSite& site = clip.skeleton.effectorSite(foot);
    int heelJoint = clip.skeleton.findBone(foot == Effector::kLFoot ? "lfoot" : "rfoot");
    if (heelJoint < 0) heelJoint = site.localCm.isZero() ? clip.skeleton.joints[site.joint].parent : site.joint;
    track.toeCm.reserve(clip.frames.size());
    if (heelJoint >= 0) track.heelCm.reserve(clip.frames.size());
    FkState fk;
    for (const Pose& pose : clip.frames) {
        forwardKinematics(clip.skeleton, pose, fk);
        track.toeCm.push_back(effectorCm(clip.skeleton, fk, foot));
        if (heelJoint >= 0) track.heelCm.push_back(fk.jointCm[static_cast<std::size_t>(heelJoint)]);  // none: toe only
    }
    return track;
}

ContactSet detectFootContacts(const Clip& clip, const ContactRule& rule) {
    FootTrack left = footTrack(clip, Effector::kLFoot), right = footTrack(clip, Effector::kRFoot);
    // A converter's rest frame (a T-pose, often off the capture's ground) is no evidence of where
    // the floor is: it stands where the first captured frame does, so it sets neither the floor nor
    // the ground and shares that frame's contacts.
    if (clip.firstMotionFrame() == 1)
        for (FootTrack* t : {&left, &right})
            for (std::vector<Eigen::Vector3d>* points : {&t->toeCm, &t->heelCm})
                if (points->size() > 1) (*points)[0] = (*points)[1];
    return detectFootContacts(left, right, clip.fps, rule);
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
