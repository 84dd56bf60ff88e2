// Whole-body centre of mass (core/skeleton/centre_of_mass.h): de Leva's table, how it moves with the
// body, and where it sits on a captured frame.
#include <doctest/doctest.h>

#include "io/clip_loader.h"
#include "skeleton/centre_of_mass.h"
#include "test_support.h"

using namespace mgp;

TEST_CASE("centre of mass: de Leva's male segment masses sum to the whole body") {
    int count = 0;
    const BodySegment* segments = bodySegments(&count);
    REQUIRE(count == 16);
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
        sum += segments[i].massFraction;
        CHECK(segments[i].comRatio > 0.0);
        CHECK(segments[i].comRatio < 1.0);
    }
    CHECK(sum == doctest::Approx(1.0).epsilon(1e-12));
}

TEST_CASE(
    "centre of mass: moves with the root, sits at about 55 % of the height on a standing frame, none without legs") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Skeleton& sk = clip.skeleton;
    const Pose& pose = clip.frames[0];
    const std::optional<Eigen::Vector3d> com = centreOfMass(sk, pose);
    REQUIRE(com);
    Pose moved = pose;
    moved.rootCm += Eigen::Vector3d(10, -3, 7);
    const std::optional<Eigen::Vector3d> comMoved = centreOfMass(sk, moved);
    REQUIRE(comMoved);
    CHECK((*comMoved - *com - Eigen::Vector3d(10, -3, 7)).norm() < 1e-9);
    CHECK(*horizontalComShiftCm(sk, moved, pose) == doctest::Approx(std::sqrt(149.0)).epsilon(1e-9));
    // Anthropometry puts a standing adult's centre of mass at 54–56 % of stature; between the
    // feet and the top of the head of the first frame (standing, ankles as the feet's points) it
    // lies at 50–60 % of that span.
    FkState fk;
    forwardKinematics(sk, pose, fk);
    int head = -1;
    for (int j = 0; j < sk.jointCount(); ++j)
        if (sk.joints[j].bone == "head") head = j;
    REQUIRE(head >= 0);
    const double top = boneEndCm(sk, fk, head).y();
    const double feet = std::min(effectorCm(sk, fk, Effector::kLFoot).y(), effectorCm(sk, fk, Effector::kRFoot).y());
    const double ratio = (com->y() - feet) / (top - feet);
    MESSAGE("centre of mass at " << 100.0 * ratio << " % of the ankle-to-head-top span");
    CHECK(ratio > 0.50);
    CHECK(ratio < 0.60);
    // Horizontally between the feet, within a foot's length.
    CHECK(std::abs(com->x() -
                   0.5 * (effectorCm(sk, fk, Effector::kLFoot).x() + effectorCm(sk, fk, Effector::kRFoot).x())) < 25.0);
    Skeleton noLegs = sk;
    for (Joint& j : noLegs.joints)
        if (j.bone == "lfemur") j.bone = "lthigh_renamed";
    CHECK_FALSE(centreOfMass(noLegs, pose));
}
