// The additive pose layer of whole-pose changes (core/motion/pose_layer.h): its blend weight and
// the layered frames, by hand.
#include <doctest/doctest.h>

#include <Eigen/Geometry>

#include "io/clip_loader.h"
#include "motion/pose_layer.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_mirror.h"
#include "skeleton/rotation.h"
#include "test_support.h"

using namespace mgp;

TEST_CASE("pose layer: the Hermite blend weight is 1 at the frame and 0 with zero slope at the ends") {
    CHECK(poseLayerWeight(10, 10, 4) == 1.0);
    CHECK(poseLayerWeight(12, 10, 4) == doctest::Approx(0.5));      // d = 1/2: (1/4)(2) = 1/2
    CHECK(poseLayerWeight(11, 10, 4) == doctest::Approx(0.84375));  // d = 1/4: (9/16)(3/2)
    CHECK(poseLayerWeight(7, 10, 4) == doctest::Approx(0.15625));   // d = 3/4: (1/16)(5/2)
    CHECK(poseLayerWeight(14, 10, 4) == 0.0);
    CHECK(poseLayerWeight(20, 10, 4) == 0.0);
    CHECK(poseLayerWeight(10, 10, 0) == 1.0);
    CHECK(poseLayerWeight(11, 10, 0) == 0.0);
    // Zero slope at both ends: w(t0 ± r ∓ ε) − w(t0 ± r) is O(ε²), as is 1 − w(t0 ± ε).
    const int r = 1000;
    CHECK(poseLayerWeight(999, 0, r) < 1e-5);
    CHECK(1.0 - poseLayerWeight(1, 0, r) < 1e-5);
}

namespace {

// Two joints, one axis each: their changes add by components.
Skeleton hingeSkeleton() {
    Skeleton sk;
    sk.joints.resize(2);
    sk.joints[0].dof = {true, false, false};
    sk.joints[1].parent = 0;
    sk.joints[1].dof = {false, true, false};
    return sk;
}

}  // namespace

TEST_CASE("pose layer: frames t0 ± r get w times the change, angles the short way round") {
    const Skeleton sk = hingeSkeleton();
    Pose from, to;
    from.rootCm = {0, 90, 0};
    to.rootCm = {10, 90, 0};
    from.anglesDeg = {{179, 0, 0}, {0, 10, 0}};
    to.anglesDeg = {{-179, 0, 0}, {0, 30, 0}};  // +2° across ±180, +20°
    std::vector<Pose> frames(7, from);
    addPoseLayer(sk, frames, 3, 2, from, to);
    CHECK(frames[0].rootCm.x() == 0.0);  // outside (w = 0 at t0 ± r)
    CHECK(frames[1].rootCm.x() == 0.0);
    CHECK(frames[2].rootCm.x() == doctest::Approx(5.0));
    CHECK(frames[2].anglesDeg[0].x() == doctest::Approx(180.0));  // 179 + ½·2
    CHECK(frames[2].anglesDeg[1].y() == doctest::Approx(20.0));
    CHECK(frames[3].rootCm.x() == doctest::Approx(10.0));
    CHECK(frames[3].anglesDeg[0].x() == doctest::Approx(181.0));  // the same rotation as −179
    CHECK(frames[4].anglesDeg[1].y() == doctest::Approx(20.0));
    CHECK(frames[6].anglesDeg[1].y() == 10.0);
    // Clamped to the clip: a change on frame 0 reaches frame 1 only.
    std::vector<Pose> start(3, from);
    addPoseLayer(sk, start, 0, 2, from, to);
    CHECK(start[0].anglesDeg[1].y() == doctest::Approx(30.0));
    CHECK(start[1].anglesDeg[1].y() == doctest::Approx(20.0));
    CHECK(start[2].anglesDeg[1].y() == 10.0);
    // A side shorter than r blends over the frames it has: frame 1's change is 0 on frame 0 and
    // ½ on frame 2 (r = 2 on that side), where the clip's end and the spread's span end.
    std::vector<Pose> near(5, from);
    addPoseLayer(sk, near, 1, 2, from, to);
    CHECK(near[0].anglesDeg[1].y() == 10.0);
    CHECK(near[1].anglesDeg[1].y() == doctest::Approx(30.0));
    CHECK(near[2].anglesDeg[1].y() == doctest::Approx(20.0));
    CHECK(near[3].anglesDeg[1].y() == 10.0);
    std::vector<Pose> nearEnd(5, from);
    addPoseLayer(sk, nearEnd, 3, 3, from, to);  // one frame after it: w = 0 on the last frame
    CHECK(nearEnd[4].anglesDeg[1].y() == 10.0);
    CHECK(nearEnd[0].anglesDeg[1].y() == 10.0);
    CHECK(nearEnd[1].anglesDeg[1].y() == doctest::Approx(10.0 + 20.0 * 0.259259259).epsilon(1e-6));  // d = 2/3
}

TEST_CASE("pose layer: a three-axis joint turns by D^w before its own rotation, so a fast turn keeps its speed") {
    Skeleton sk;
    sk.joints.resize(1);
    sk.joints[0].dof = {true, true, true};
    const RotationOrder order = sk.joints[0].order;
    Pose to;
    to.anglesDeg = {{40, 60, -30}};
    // Frames turning 6° per frame in x and z under the layer, near gimbal lock (y = 80° in z-y-x):
    // the two turns almost cancel, |ω|² = 6² + 6² − 2·6·6·sin y, about 1.04° per frame.
    const int n = 401, t0 = 200;
    std::vector<Pose> frames(n);
    for (int t = 0; t < n; ++t) frames[t].anglesDeg = {Eigen::Vector3d(10 + 6.0 * (t - t0), 80, 5 + 6.0 * (t - t0))};
    const std::vector<Pose> under = frames;
    const Eigen::Matrix3d D =
        eulerMatrix(to.anglesDeg[0], order) * eulerMatrix(under[t0].anglesDeg[0], order).transpose();
    const Eigen::AngleAxisd dAxis(D);
    addPoseLayer(sk, frames, t0, 200, under[t0], to);
    for (int t = 0; t < n; t += 7) {
        const double w = poseLayerWeight(t, t0, 200);
        const Eigen::Matrix3d expected = Eigen::AngleAxisd(w * dAxis.angle(), dAxis.axis()).toRotationMatrix() *
                                         eulerMatrix(under[t].anglesDeg[0], order);
        CHECK((eulerMatrix(frames[t].anglesDeg[0], order) - expected).norm() < 1e-9);
    }
    CHECK((eulerMatrix(frames[t0].anglesDeg[0], order) - eulerMatrix(to.anglesDeg[0], order)).norm() < 1e-9);
    // Next to t0 the weight is flat (1 − w ≤ 3·10⁻⁴): the layered joint turns as fast as the one under it.
    auto turnDeg = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
        return Eigen::AngleAxisd(eulerMatrix(b, order) * eulerMatrix(a, order).transpose()).angle() * kRadToDeg;
    };
    const double speed = turnDeg(under[t0].anglesDeg[0], under[t0 + 1].anglesDeg[0]);
    CHECK(speed == doctest::Approx(std::sqrt(72.0 * (1.0 - std::sin(80.0 * kDegToRad)))).epsilon(1e-3));
    for (int t = t0 - 3; t < t0 + 3; ++t)
        CHECK(turnDeg(frames[t].anglesDeg[0], frames[t + 1].anglesDeg[0]) == doctest::Approx(speed).epsilon(0.01));
    // Adding the Euler components instead would not keep it: the same channel steps at y = 60° turn
    // the joint about 3.1° per frame.
    const Eigen::Vector3d added = to.anglesDeg[0], addedNext = to.anglesDeg[0] + Eigen::Vector3d(6, 0, 6);
    CHECK(turnDeg(added, addedNext) > 2.0 * speed);
}

TEST_CASE("pose layer radius: the falloff, widened to 1.5·S·fps / 90 cm/s for a change whose blend moves a hand S cm") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Skeleton& sk = clip.skeleton;
    const Pose& from = clip.frames[100];
    // A pure root move of 30 cm: every hand and foot moves 30 cm per unit weight.
    Pose to = from;
    to.rootCm.x() += 30.0;
    CHECK(poseLayerSteepestCm(sk, from, to) == doctest::Approx(30.0));
    CHECK(poseLayerRadius(sk, from, to, 20, 120.0) == 60);  // ⌈1.5·30·120/90⌉
    CHECK(poseLayerRadius(sk, from, to, 80, 120.0) == 80);  // never narrower than the falloff
    to.rootCm.x() += 300.0;
    CHECK(poseLayerRadius(sk, from, to, 20, 120.0) == kLayerWidening * 20);  // at most 8 falloffs
    CHECK(poseLayerRadius(sk, from, from, 20, 120.0) == 20);
    CHECK(poseLayerRadius(sk, from, to, 0, 120.0) == 0);  // no spread stays none
    // The whole body turned 170° about the vertical: each hand travels an arc of 170°·R per unit
    // weight, 1.49 times its chord 2R·sin 85°, so the slope seen along the blend exceeds what the
    // end points alone would give.
    const Joint& root = sk.joints[0];
    Pose turned = from;
    turned.anglesDeg[0] = fitJointAngles(
        Eigen::AngleAxisd(170.0 * kDegToRad, Eigen::Vector3d::UnitY()) * eulerMatrix(from.anglesDeg[0], root.order),
        root.order, root.dof, from.anglesDeg[0]);
    double chord = 0.0;
    for (Effector e : {Effector::kLHand, Effector::kRHand, Effector::kLFoot, Effector::kRFoot})
        chord = std::max(chord, (effectorCm(sk, turned, e) - effectorCm(sk, from, e)).norm());
    const double slope = poseLayerSteepestCm(sk, from, turned);
    MESSAGE("turned 170 degrees: steepest slope " << slope << " cm per unit weight, largest chord " << chord << " cm");
    CHECK(slope > 1.3 * chord);
}

TEST_CASE("pose layer excess: the most a hand or foot gains per frame step over the motion under the layer") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Skeleton& sk = clip.skeleton;
    // A still pose under the layer, moved 30 cm by the root: the gain is the blend's own step,
    // 30·max|w(s+1) − w(s)| = 30·1.5/60 = 0.75 cm at radius 60 (up to the step's discreteness).
    const std::vector<Pose> still(241, clip.frames[100]);
    Pose moved = still[120];
    moved.rootCm.x() += 30.0;
    CHECK(poseLayerExcessCm(sk, still, 120, 60, moved) == doctest::Approx(0.75).epsilon(1e-3));
    CHECK(poseLayerExcessCm(sk, still, 120, 120, moved) == doctest::Approx(0.375).epsilon(1e-3));
    // No change, no gain; on the captured walk too.
    CHECK(poseLayerExcessCm(sk, clip.frames, 150, 60, clip.frames[150]) == 0.0);
    // Over the still pose the measured radius is the speed rule's: nothing under the layer turns.
    CHECK(poseLayerRadiusOver(sk, still, 120, moved, 20, 120.0) == poseLayerRadius(sk, still[120], moved, 20, 120.0));
}

TEST_CASE("pose layer radius over the motion: a wide layer over a fast passage is replaced by one that gains less") {
    const Clip clip = loadClip(test::mocap("asf_amc/10_02.amc"));
    const Skeleton& sk = clip.skeleton;
    // Frame 366 of the kick given the pose of frame 186 (its root kept): the speed rule widens the
    // layer to 224 frames, over the kick, where the turned legs sweep faster than captured.
    const int t0 = 365;
    Pose to = clip.frames[185];
    to.rootCm = clip.frames[t0].rootCm;
    const int rule = poseLayerRadius(sk, clip.frames[t0], to, 30, clip.fps);
    const int chosen = poseLayerRadiusOver(sk, clip.frames, t0, to, 30, clip.fps);
    const double ruleGain = poseLayerExcessCm(sk, clip.frames, t0, rule, to);
    const double chosenGain = poseLayerExcessCm(sk, clip.frames, t0, chosen, to);
    MESSAGE("rule radius " << rule << " gains " << ruleGain << " cm; measured radius " << chosen << " gains "
                           << chosenGain << " cm");
    CHECK(rule > 200);
    CHECK(chosen >= 30);
    CHECK(chosen <= kLayerWidening * 30);
    CHECK(chosenGain < ruleGain - 0.5);
    // Wherever the measured radius differs from the rule's, it gains less; where the rule's layer
    // gains no more than 90 cm/s (0.75 cm per step at 120 fps), it is the rule's.
    for (int t = 40; t + 40 < clip.frameCount(); t += 50) {
        const int source = t >= 180 ? t - 180 : t + 180;
        Pose p = clip.frames[source];
        p.rootCm = clip.frames[t].rootCm;
        const int r = poseLayerRadius(sk, clip.frames[t], p, 30, clip.fps);
        const int over = poseLayerRadiusOver(sk, clip.frames, t, p, 30, clip.fps);
        const double gain = poseLayerExcessCm(sk, clip.frames, t, r, p);
        if (gain <= 0.75) CHECK(over == r);
        if (over != r) CHECK(poseLayerExcessCm(sk, clip.frames, t, over, p) < gain - 0.05);
    }
}
