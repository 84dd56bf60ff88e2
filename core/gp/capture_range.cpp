#include "gp/capture_range.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gp/training_range.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"

namespace mgp::gp {

namespace {

// Mean distance over the joints not left out between two shapes (3J each).
double shapeDistance(const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::VectorXd>& b,
                     const std::vector<bool>& leftOut) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t j = 0; j < leftOut.size(); ++j) {
        if (leftOut[j]) continue;
        sum += (a.segment<3>(3 * j) - b.segment<3>(3 * j)).norm();
        ++count;
    }
    return count > 0 ? sum / count : 0.0;
}

// The nearest captured frame to `shape`, skipping clip `skipClip`'s frames within ±window of
// `skipFrame` (skipClip < 0: none skipped).
std::pair<double, int> nearestShape(const CaptureRange& range, const Eigen::VectorXd& shape,
                                    const std::vector<bool>& leftOut, int skipClip, int skipFrame, int window) {
    double best = std::numeric_limits<double>::infinity();
    int at = -1;
    for (int i = 0; i < range.frames(); ++i) {
        if (range.clipOf[i] == skipClip && std::abs(range.frameOf[i] - skipFrame) <= window) continue;
        const double d = shapeDistance(shape, range.shapes.row(i).transpose(), leftOut);
        if (d < best) {
            best = d;
            at = i;
        }
    }
    return {best, at};
}

// The angle a + 360k nearest to [lo, hi] (the clips are unwrapped; a solved pose may not be).
double nearestTurn(double a, double lo, double hi) {
    const double mid = 0.5 * (lo + hi);
    return a - 360.0 * std::round((a - mid) / 360.0);
}

}  // namespace

Eigen::VectorXd captureShape(const Skeleton& skeleton, const Pose& pose) {
    FkState fk;
    forwardKinematics(skeleton, pose, fk);
    return captureShape(skeleton, fk);
}

Eigen::VectorXd captureShape(const Skeleton& skeleton, const FkState& fk) {
    const Eigen::Matrix3d unturn = headingRemoval(fk);
    Eigen::VectorXd out(3 * skeleton.jointCount());
    for (int j = 0; j < skeleton.jointCount(); ++j) out.segment<3>(3 * j) = unturn * (fk.jointCm[j] - fk.jointCm[0]);
    return out;
}

std::vector<bool> movedLimbJoints(const Skeleton& skeleton, const std::vector<Effector>& moved) {
    const int n = skeleton.jointCount();
    std::vector<bool> out(n, false);
    for (Effector e : moved) {
        const int end = skeleton.effectorSite(e).joint;
        if (end < 0) continue;
        // The end joint and the two above it (the limb the locality term also leaves free).
        for (int j = end, h = 0; j > 0 && h <= 2; j = skeleton.joints[j].parent, ++h) out[j] = true;
        // Everything below the end joint (fingers, toes): parents precede children.
        std::vector<bool> below(n, false);
        below[end] = true;
        for (int j = end + 1; j < n; ++j) {
            const int parent = skeleton.joints[j].parent;
            below[j] = parent >= 0 && below[parent];
            if (below[j]) out[j] = true;
        }
    }
    return out;
}

std::shared_ptr<const CaptureRange> computeCaptureRange(const GpModel& model) {
    auto range = std::make_shared<CaptureRange>();
    const Skeleton& skeleton = model.clip.skeleton;
    const PoseLayout layout(skeleton);
    int total = 0;
    for (int c = 0; c < model.clipCount(); ++c) total += model.clipAt(c).frameCount();
    range->shapes.resize(total, 3 * skeleton.jointCount());
    range->qMin = Eigen::VectorXd::Constant(layout.size(), std::numeric_limits<double>::infinity());
    range->qMax = Eigen::VectorXd::Constant(layout.size(), -std::numeric_limits<double>::infinity());
    int row = 0;
    for (int c = 0; c < model.clipCount(); ++c) {
        const Clip& clip = model.clipAt(c);
        for (int t = 0; t < clip.frameCount(); ++t, ++row) {
            range->shapes.row(row) = captureShape(clip.skeleton, clip.frames[t]).transpose();
            range->clipOf.push_back(c);
            range->frameOf.push_back(t);
            const Eigen::VectorXd q = layout.extract(clip.frames[t]);
            range->qMin = range->qMin.cwiseMin(q);
            range->qMax = range->qMax.cwiseMax(q);
        }
    }
    range->judged.resize(layout.size());
    for (int k = 0; k < layout.size(); ++k) range->judged[k] = layout.joint(k) > 0;
    const std::vector<bool> none(skeleton.jointCount(), false);
    const int step = std::max(1, (total + kCaptureLimitQueries - 1) / kCaptureLimitQueries);
    std::vector<double> d;
    for (int i = 0; i < total; i += step)
        d.push_back(nearestShape(*range, range->shapes.row(i).transpose(), none, range->clipOf[i], range->frameOf[i],
                                 kHeldOutWindowFrames)
                        .first);
    // A clip shorter than the window has no frame outside it: those queries see nothing.
    d.erase(std::remove_if(d.begin(), d.end(), [](double v) { return !std::isfinite(v); }), d.end());
    range->nearestLimitCm = percentileOf(d, kCaptureNearestPercentile);
    range->nearestMedianCm = percentileOf(d, 50.0);
    return range;
}

RangeCheck checkRanges(const Eigen::VectorXd& q, const Eigen::VectorXd& qMin, const Eigen::VectorXd& qMax,
                       const std::vector<bool>* judged, bool wholeTurns) {
    RangeCheck out;
    for (Eigen::Index k = 0; k < std::min(q.size(), qMin.size()); ++k) {
        if (judged && !(*judged)[static_cast<std::size_t>(k)]) continue;
        const double margin = std::max(kCaptureRangeMarginDeg, kCaptureRangeMarginFraction * (qMax[k] - qMin[k]));
        const double a = wholeTurns ? nearestTurn(q[k], qMin[k], qMax[k]) : q[k];
        const double excess = std::max(qMin[k] - margin - a, a - qMax[k] - margin);
        if (excess <= 0.0) continue;
        ++out.violations;
        if (excess > out.worstExcessDeg) {
            out.worstExcessDeg = excess;
            out.worstDof = static_cast<int>(k);
        }
    }
    return out;
}

CaptureLikeness judgeAgainstCapture(const CaptureRange& range, const Skeleton& skeleton, const Pose& pose,
                                    const std::vector<Effector>& moved) {
    CaptureLikeness out;
    const PoseLayout layout(skeleton);
    const Eigen::VectorXd q = layout.extract(pose);
    const std::vector<bool> leftOut = movedLimbJoints(skeleton, moved);
    const RangeCheck check = checkRanges(q, range.qMin, range.qMax, &range.judged, true);
    out.rangeViolations = check.violations;
    out.worstDof = check.worstDof;
    out.worstExcessDeg = check.worstExcessDeg;
    out.ranges = check.violations == 0;
    const auto [dist, at] = nearestShape(range, captureShape(skeleton, pose), leftOut, -1, 0, 0);
    out.nearestCm = dist;
    if (at >= 0) {
        out.nearestClip = range.clipOf[at];
        out.nearestFrame = range.frameOf[at];
    }
    out.nearest = std::isfinite(dist) && dist <= range.nearestLimitCm;
    return out;
}

}  // namespace mgp::gp
