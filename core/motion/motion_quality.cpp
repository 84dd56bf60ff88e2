#include "motion/motion_quality.h"

#include <algorithm>
#include <cmath>

#include "skeleton/forward_kinematics.h"
#include "skeleton/rotation.h"

namespace mgp {

double percentile(std::vector<double> values, double q) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    // Nearest rank: the smallest value with at least q·n values at or below it.
    const double rank = std::ceil(std::clamp(q, 0.0, 1.0) * values.size());
    const std::size_t i = static_cast<std::size_t>(std::max(1.0, rank)) - 1;
    return values[std::min(i, values.size() - 1)];
}

SecondDifferenceStats secondDifferences(const std::vector<Pose>& frames, const Skeleton& skeleton, int first,
                                        int last) {
    const PoseLayout layout(skeleton);
    SecondDifferenceStats s;
    const int n = static_cast<int>(frames.size());
    for (int c = std::max(first, 1); c <= std::min(last, n - 2); ++c) {
        const Eigen::VectorXd a = layout.extract(frames[c - 1]), b = layout.extract(frames[c]),
                              d = layout.extract(frames[c + 1]);
        double worst = 0.0;
        for (int k = 0; k < layout.size(); ++k) {
            if (layout.joint(k) < 0) continue;
            worst = std::max(worst, std::abs(wrap180(d[k] - b[k]) - wrap180(b[k] - a[k])));
        }
        s.perFrameDeg.push_back(worst);
        if (worst > s.maxDeg || s.maxFrame < 0) {
            s.maxDeg = worst;
            s.maxFrame = c;
        }
    }
    s.p95Deg = percentile(s.perFrameDeg, 0.95);
    return s;
}

double largestAngleChangeDeg(const Pose& a, const Pose& b, const Skeleton& skeleton) {
    const PoseLayout layout(skeleton);
    const Eigen::VectorXd ya = layout.extract(a), yb = layout.extract(b);
    double worst = 0.0;
    for (int k = 0; k < layout.size(); ++k)
        if (layout.joint(k) >= 0) worst = std::max(worst, std::abs(wrap180(ya[k] - yb[k])));
    return worst;
}

double horizontalTravelCm(const std::vector<Eigen::Vector3d>& p, int first, int last) {
    first = std::max(first, 0);
    last = std::min(last, static_cast<int>(p.size()) - 1);
    double worst = 0.0;
    for (int i = first; i <= last; ++i)
        for (int j = i + 1; j <= last; ++j)
            worst = std::max(worst, std::hypot(p[i].x() - p[j].x(), p[i].z() - p[j].z()));
    return worst;
}

SpanQuality measureSpan(const Clip& captured, const std::vector<Pose>& edited, int first, int last, Effector effector,
                        const std::vector<Eigen::Vector3d>& pathCm, const std::vector<int>& keyFrames,
                        const std::vector<ContactInterval>& contacts) {
    const Skeleton& sk = captured.skeleton;
    SpanQuality q;
    q.first = first;
    q.last = last;
    q.edited = secondDifferences(edited, sk, first, last);
    q.captured = secondDifferences(captured.frames, sk, first, last);
    FkState fk;
    for (int t = first + 1; t < last; ++t) {
        const double change = largestAngleChangeDeg(edited[t], captured.frames[t], sk);
        if (change > q.worstPoseChangeDeg || q.worstPoseChangeFrame < 0) {
            q.worstPoseChangeDeg = change;
            q.worstPoseChangeFrame = t;
        }
        const std::size_t i = static_cast<std::size_t>(t - first);
        if (i >= pathCm.size()) continue;
        forwardKinematics(sk, edited[t], fk);
        const double err = (effectorCm(sk, fk, effector) - pathCm[i]).norm();
        q.worstPathErrorCm = std::max(q.worstPathErrorCm, err);
        if (std::find(keyFrames.begin(), keyFrames.end(), t) != keyFrames.end())
            q.worstKeyErrorCm = std::max(q.worstKeyErrorCm, err);
    }
    for (const ContactInterval& c : contacts) {
        std::vector<Eigen::Vector3d> e, k;
        for (int t = 0; t < captured.frameCount(); ++t) {
            const bool inside = t >= c.first && t <= c.last;
            e.push_back(inside ? effectorCm(sk, edited[t], c.foot) : Eigen::Vector3d::Zero());
            k.push_back(inside ? effectorCm(sk, captured.frames[t], c.foot) : Eigen::Vector3d::Zero());
        }
        q.contacts.push_back(
            {c.foot, c.first, c.last, horizontalTravelCm(e, c.first, c.last), horizontalTravelCm(k, c.first, c.last)});
    }
    return q;
}

}  // namespace mgp
