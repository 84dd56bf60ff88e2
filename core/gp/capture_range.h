#pragma once
// What the captured frames of a model's source clips span, measured without the model: each
// joint angle's range and the body shape of every frame. An edited pose is "like the capture"
// when its angles stay within the ranges (plus a margin) and the rest of its body (the moved
// limbs left out) is near some captured frame's. The adaptive update admits only such poses
// (eval/admission.h, docs/maths-ik.md §5), so what the model learns from never depends on
// what it learned before: the reference is the capture, which no update changes.
//
//  - ranges: q_k ∈ [min_k − m_k, max_k + m_k] over every captured frame, m_k = max(5°, 0.1·(max_k
//    − min_k)) (the editing-range protocol's margin, docs/maths.md §14); the root's rotation is
//    not judged (the heading is free). The moved limbs' angles are judged too, with the same
//    margin: on 2 040 moves the verdicts (balance aside) agreed with the naturalness tests on
//    91 %, 89 % with a 10° margin on the moved limbs, 82 % with 20° and 65 % with those angles
//    not judged (docs/maths-ik.md §5). So a hand dragged where the capture never put it is "unlike the
//    captured data" once its elbow or shoulder leaves the captured range (a walk's elbow moves
//    little: a 4 cm hand raise on 35_01 can do it); more clips widen the ranges;
//  - nearest frame: d(y) = min over captured frames of the mean distance (cm) of the joints, root
//    at the origin, heading removed; the moved effectors' limbs (the end joint, the two joints
//    above it and everything below it) are left out, since the animator put them there. The
//    limit is the 99th percentile of the same distance from each captured frame to the frames
//    outside its own ±kHeldOutWindowFrames (how far the capture's own natural moments are from
//    each other).
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "gp/model.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/skeleton.h"

namespace mgp::gp {

constexpr double kCaptureRangeMarginDeg = 5.0;
constexpr double kCaptureRangeMarginFraction = 0.1;
constexpr double kCaptureNearestPercentile = 99.0;
// The limit's percentile uses at most this many captured frames as queries (evenly spaced), so
// that a long multi-clip model is measured in a fraction of a second.
constexpr int kCaptureLimitQueries = 800;

struct CaptureRange {
    Eigen::VectorXd qMin, qMax;        // per pose-vector DOF, degrees (unwrapped as the model's clips)
    std::vector<bool> judged;          // false for the root's rotation and DOFs the skeleton lacks
    Eigen::MatrixXd shapes;            // frames × 3J: joints relative to the root, heading removed (cm)
    std::vector<int> clipOf, frameOf;  // each shape's source clip and frame (0-based)
    double nearestLimitCm = 0.0;       // the percentile above
    double nearestMedianCm = 0.0;
    int frames() const { return static_cast<int>(shapes.rows()); }
};

// From every frame of every source clip of `model` (not its training rows: an adaptive update
// adds rows, never captured frames).
std::shared_ptr<const CaptureRange> computeCaptureRange(const GpModel& model);

struct CaptureLikeness {
    double nearestCm = 0.0;  // d(y)
    int nearestClip = -1, nearestFrame = -1;
    bool nearest = false;     // nearestCm ≤ the limit
    int rangeViolations = 0;  // DOFs outside their range
    int worstDof = -1;        // the DOF furthest outside its range (−1: none)
    double worstExcessDeg = 0.0;
    bool ranges = false;  // no DOF outside its range
    bool like() const { return nearest && ranges; }
};

// The angles of q outside [qMin − m, qMax + m], m = max(5°, 0.1·(qMax − qMin)) per DOF: how many and
// the worst. `judged` (optional) skips DOFs marked false; `wholeTurns` compares each angle a whole
// turn apart where that is nearer (a solved pose need not be unwrapped like the capture).
struct RangeCheck {
    int violations = 0;
    int worstDof = -1;
    double worstExcessDeg = 0.0;
};
RangeCheck checkRanges(const Eigen::VectorXd& q, const Eigen::VectorXd& qMin, const Eigen::VectorXd& qMax,
                       const std::vector<bool>* judged, bool wholeTurns);

// Body shape of a pose (root-relative joints, heading removed), the rows of CaptureRange::shapes;
// the second form from the pose's forward kinematics, already run.
Eigen::VectorXd captureShape(const Skeleton& skeleton, const Pose& pose);
Eigen::VectorXd captureShape(const Skeleton& skeleton, const FkState& fk);
// The joints d(y) leaves out for these moved effectors (true = left out), per skeleton joint.
std::vector<bool> movedLimbJoints(const Skeleton& skeleton, const std::vector<Effector>& moved);

// Judges `pose` (of the model's skeleton) against the capture; `moved`: the effectors the edit
// put somewhere (targets, not pins).
CaptureLikeness judgeAgainstCapture(const CaptureRange& range, const Skeleton& skeleton, const Pose& pose,
                                    const std::vector<Effector>& moved);

}  // namespace mgp::gp
