// limbExtension (core/skeleton/limb_extension.h): a hand-built leg with known answers, then the
// shipped 35_01 skeleton.
#include <cmath>

#include "io/clip_loader.h"
#include "skeleton/limb_extension.h"
#include "test_support.h"

using namespace mgp;

namespace {

// root → lfemur (40 cm down) → ltibia (30 cm down, bending about x).
Skeleton leg() {
    Skeleton sk;
    Joint root;
    root.name = root.bone = "root";
    Joint femur;
    femur.name = femur.bone = "lfemur";
    femur.parent = 0;
    femur.tailCm = Eigen::Vector3d(0, -40, 0);
    Joint tibia;
    tibia.name = tibia.bone = "ltibia";
    tibia.parent = 1;
    tibia.offsetCm = femur.tailCm;
    tibia.tailCm = Eigen::Vector3d(0, -30, 0);
    tibia.dof = {true, false, false};
    sk.joints = {root, femur, tibia};
    return sk;
}

// FK of `sk` in its rest pose (every angle 0), the test leg's knee (joint 2, x) bent by kneeDeg.
FkState fkAtRest(const Skeleton& sk, double kneeDeg = 0.0) {
    Pose pose;
    pose.anglesDeg.assign(sk.jointCount(), Eigen::Vector3d::Zero());
    if (kneeDeg != 0.0) pose.anglesDeg[2].x() = kneeDeg;
    FkState fk;
    forwardKinematics(sk, pose, fk);
    return fk;
}

double extensionWithKnee(const Skeleton& sk, double kneeDeg) {
    const std::optional<double> e = limbExtension(sk, fkAtRest(sk, kneeDeg), Effector::kLFoot);
    REQUIRE(e.has_value());
    return *e;
}

}  // namespace

TEST_CASE("limb extension: the law of cosines on a 40 + 30 cm leg") {
    const Skeleton sk = leg();
    CHECK(extensionWithKnee(sk, 0.0) == doctest::Approx(1.0).epsilon(1e-15));
    // |hip − ankle| = √(40² + 30² + 2·40·30·cos θ) for a knee bent by θ.
    CHECK(extensionWithKnee(sk, 60.0) == doctest::Approx(std::sqrt(3700.0) / 70.0).epsilon(1e-14));
    CHECK(extensionWithKnee(sk, 90.0) == doctest::Approx(50.0 / 70.0).epsilon(1e-14));
    CHECK(extensionWithKnee(sk, -90.0) == doctest::Approx(50.0 / 70.0).epsilon(1e-14));
    CHECK(extensionWithKnee(sk, 180.0) == doctest::Approx(10.0 / 70.0).epsilon(1e-13));
}

TEST_CASE("limb extension: no value for the head or a limb without its bone roles") {
    const Skeleton sk = leg();
    const FkState fk = fkAtRest(sk);
    CHECK_FALSE(limbExtension(sk, fk, Effector::kHead).has_value());
    CHECK_FALSE(limbExtension(sk, fk, Effector::kRFoot).has_value());  // no rfemur / rtibia
    CHECK_FALSE(limbExtension(sk, fk, Effector::kLHand).has_value());
}

TEST_CASE("limb extension of 35_01: straight limbs at rest, bent knees and elbows in the walk") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    FkState fk = fkAtRest(clip.skeleton);
    for (Effector e : {Effector::kLHand, Effector::kRHand, Effector::kLFoot, Effector::kRFoot}) {
        CAPTURE(effectorName(e));
        const std::optional<double> atRest = limbExtension(clip.skeleton, fk, e);
        REQUIRE(atRest.has_value());
        CHECK(*atRest == doctest::Approx(1.0).epsilon(1e-12));
    }
    forwardKinematics(clip.skeleton, clip.frames[30], fk);
    for (Effector e : {Effector::kLHand, Effector::kRHand, Effector::kLFoot, Effector::kRFoot}) {
        CAPTURE(effectorName(e));
        const double walking = *limbExtension(clip.skeleton, fk, e);
        CHECK(walking > 0.5);
        CHECK(walking < 1.0);
    }
}
