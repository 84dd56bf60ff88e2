// The built-in demo walk used when no mocap folder exists.
#include "skeleton/forward_kinematics.h"
#include "skeleton/synthetic_clip.h"
#include "test_support.h"

using namespace mgp;

TEST_CASE("synthetic walk: 22 model bones, human height, feet near the ground, periodic") {
    const Clip clip = makeSyntheticWalk();
    CHECK(clip.frameCount() >= 120);
    CHECK(missingModelBones(clip.skeleton).empty());
    for (int e = 0; e < kEffectorCount; ++e) CHECK(clip.skeleton.hasEffector(static_cast<Effector>(e)));
    FkState fk;
    double minHead = 1e9, maxHead = -1e9, maxLowFoot = -1e9;
    double maxLeftFootHeight = -1e9;
    for (int t = 0; t < clip.frameCount(); ++t) {
        forwardKinematics(clip.skeleton, clip.frames[t], fk);
        const double head = effectorCm(clip.skeleton, fk, Effector::kHead).y();
        const double lf = effectorCm(clip.skeleton, fk, Effector::kLFoot).y();
        const double rf = effectorCm(clip.skeleton, fk, Effector::kRFoot).y();
        minHead = std::min(minHead, head);
        maxHead = std::max(maxHead, head);
        CHECK(std::min(lf, rf) == doctest::Approx(3.0).epsilon(1e-9));  // lower foot 3 cm up
        maxLowFoot = std::max(maxLowFoot, std::min(lf, rf));
        maxLeftFootHeight = std::max(maxLeftFootHeight, lf);
        for (const auto& a : clip.frames[t].anglesDeg) CHECK(a.allFinite());
    }
    MESSAGE("head height " << minHead << ".." << maxHead << " cm; swing foot rises to " << maxLeftFootHeight);
    CHECK(minHead > 150.0);
    CHECK(maxHead < 190.0);
    CHECK(maxLeftFootHeight > 8.0);  // the swing foot leaves the ground
    CHECK(maxLeftFootHeight < 40.0);
    // One cycle is 120 frames: the joint angles repeat exactly.
    for (std::size_t j = 0; j < clip.frames[0].anglesDeg.size(); ++j)
        CHECK((clip.frames[130].anglesDeg[j] - clip.frames[10].anglesDeg[j]).norm() < 1e-9);
    // It moves forward (+z) at walking speed.
    const double speed = (clip.frames[120].rootCm.z() - clip.frames[0].rootCm.z()) / 1.0;
    CHECK(speed > 80.0);
    CHECK(speed < 180.0);
}

TEST_CASE("synthetic walk: legs swing in antiphase") {
    const Clip clip = makeSyntheticWalk();
    const int lf = clip.skeleton.findBone("lfemur"), rf = clip.skeleton.findBone("rfemur");
    double corr = 0.0;
    for (int t = 0; t < 120; ++t) corr += clip.frames[t].anglesDeg[lf].x() * clip.frames[t].anglesDeg[rf].x();
    CHECK(corr < 0.0);
}
