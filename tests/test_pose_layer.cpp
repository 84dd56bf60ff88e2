// The additive pose layer of whole-pose changes (core/motion/pose_layer.h): its blend weight and
// the layered frames, by hand.
#include <doctest/doctest.h>

#include "motion/pose_layer.h"

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

TEST_CASE("pose layer: frames t0 ± r get w times the change, angles the short way round") {
    Pose from, to;
    from.rootCm = {0, 90, 0};
    to.rootCm = {10, 90, 0};
    from.anglesDeg = {{179, 0, 0}, {0, 10, 0}};
    to.anglesDeg = {{-179, 0, 0}, {0, 30, 0}};  // +2° across ±180, +20°
    std::vector<Pose> frames(7, from);
    addPoseLayer(frames, 3, 2, from, to);
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
    addPoseLayer(start, 0, 2, from, to);
    CHECK(start[0].anglesDeg[1].y() == doctest::Approx(30.0));
    CHECK(start[1].anglesDeg[1].y() == doctest::Approx(20.0));
    CHECK(start[2].anglesDeg[1].y() == 10.0);
}
