// docs/maths.md §2: FK anchors on 35_01 and the analytic Jacobian.
#include <random>

#include "io/clip_loader.h"
#include "skeleton/forward_kinematics.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("FK anchors of 35_01 (docs/maths.md §2.3)") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    FkState fk;
    forwardKinematics(clip.skeleton, clip.frames[0], fk);
    CHECK(std::abs(fk.jointCm[0].y() - 101.0) <= 0.1);
    CHECK(std::abs(effectorCm(clip.skeleton, fk, Effector::kHead).y() - 164.2) <= 0.1);
    CHECK(std::abs(effectorCm(clip.skeleton, fk, Effector::kRFoot).y() - 3.4) <= 0.1);
    CHECK(std::abs(effectorCm(clip.skeleton, fk, Effector::kLFoot).y() - 8.9) <= 0.1);
    CHECK(std::abs(effectorCm(clip.skeleton, fk, Effector::kLHand).y() - 83.7) <= 0.1);
    // The ASF bone `lhand` end, with the captured hand DOFs, is 81.7 cm.
    CHECK(std::abs(boneEndCm(clip.skeleton, fk, clip.skeleton.findBone("lhand")).y() - 81.7) <= 0.1);

    forwardKinematics(clip.skeleton, clip.frames[100], fk);
    CHECK(std::abs(fk.jointCm[0].y() - 101.5) <= 0.1);
    CHECK(std::abs(effectorCm(clip.skeleton, fk, Effector::kHead).y() - 164.7) <= 0.1);
}

TEST_CASE("rest pose height of subject 35 is 158.4 cm") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    Pose rest;
    rest.anglesDeg.assign(clip.skeleton.jointCount(), Eigen::Vector3d::Zero());
    FkState fk;
    forwardKinematics(clip.skeleton, rest, fk);
    const Skeleton& sk = clip.skeleton;
    const double lowest =
        std::min(boneEndCm(sk, fk, sk.findBone("lfoot")).y(), boneEndCm(sk, fk, sk.findBone("ltoes")).y());
    CHECK(std::abs(effectorCm(sk, fk, Effector::kHead).y() - lowest - 158.4) <= 0.1);
}

namespace {
// Central-difference check of the 3×P effector Jacobian on random frames (h = 1e-5°).
void checkJacobian(const Clip& clip, int samples, unsigned seed) {
    const Skeleton& sk = clip.skeleton;
    const PoseLayout layout(sk);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> pick(0, clip.frameCount() - 1);
    FkState fk, fkp, fkm;
    Eigen::Matrix<double, 3, Eigen::Dynamic> jac(3, layout.size());
    double worst = 0.0;
    for (int s = 0; s < samples; ++s) {
        const Pose pose = clip.frames[pick(rng)];
        forwardKinematics(sk, pose, fk);
        for (int e = 0; e < kEffectorCount; ++e) {
            const auto eff = static_cast<Effector>(e);
            if (!sk.hasEffector(eff)) continue;
            effectorJacobian(sk, layout, fk, pose, eff, jac);
            for (int i = 0; i < layout.size(); ++i) {
                const int j = layout.joint(i);
                if (j < 0) {
                    CHECK(jac.col(i).isZero(0.0));
                    continue;
                }
                const double h = 1e-5;
                Pose p = pose, m = pose;
                p.anglesDeg[j][layout.axis(i)] += h;
                m.anglesDeg[j][layout.axis(i)] -= h;
                forwardKinematics(sk, p, fkp);
                forwardKinematics(sk, m, fkm);
                const Eigen::Vector3d numeric = (effectorCm(sk, fkp, eff) - effectorCm(sk, fkm, eff)) / (2 * h);
                worst = std::max(worst, (numeric - jac.col(i)).cwiseAbs().maxCoeff());
                if (!sk.isAncestorOrSelf(j, sk.effectorSite(eff).joint)) CHECK(jac.col(i).isZero(0.0));
            }
        }
    }
    MESSAGE(clip.name << ": max |analytic - numeric| = " << worst << " cm/deg");
    CHECK(worst < 1e-6);
}
}  // namespace

TEST_CASE("effector Jacobian matches central differences") {
    SUBCASE("ASF/AMC 35_01 (axis frames C_b, Z·Y·X)") {
        checkJacobian(loadClip(test::mocap("asf_amc/35_01.amc")), 6, 1);
    }
    SUBCASE("kick 10_02") { checkJacobian(loadClip(test::mocap("asf_amc/10_02.amc")), 4, 2); }
    SUBCASE("Daz BVH (Z·X·Y channels)") { checkJacobian(loadClip(test::mocap("bvh/02_03.bvh")), 3, 3); }
    SUBCASE("3dsMax BVH (mixed orders)") { checkJacobian(loadClip(test::mocap("bvh/131_01.bvh")), 3, 4); }
}

TEST_CASE("root translation moves every effector one-for-one") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    Clip moved = clip;
    moved.frames[5].rootCm += Eigen::Vector3d(10, -3, 7);
    for (int e = 0; e < kEffectorCount; ++e) {
        const auto eff = static_cast<Effector>(e);
        const Eigen::Vector3d d =
            effectorCm(moved.skeleton, moved.frames[5], eff) - effectorCm(clip.skeleton, clip.frames[5], eff);
        CHECK((d - Eigen::Vector3d(10, -3, 7)).norm() < 1e-9);
    }
}

TEST_CASE("a joint origin's Jacobian (pointJacobian) matches central differences, its own DOFs' columns 0") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Skeleton& sk = clip.skeleton;
    const PoseLayout layout(sk);
    const Pose& pose = clip.frames[120];
    FkState fk, fkp, fkm;
    forwardKinematics(sk, pose, fk);
    Eigen::Matrix<double, 3, Eigen::Dynamic> jac(3, layout.size());
    for (const char* bone : {"lfoot", "rtibia", "rhand", "head"}) {
        CAPTURE(bone);
        const int held = sk.findBone(bone);
        REQUIRE(held >= 0);
        pointJacobian(sk, layout, fk, pose, held, fk.jointCm[held], jac);
        double worst = 0.0;
        for (int i = 0; i < layout.size(); ++i) {
            const int j = layout.joint(i);
            if (j < 0) continue;
            Pose p = pose, m = pose;
            p.anglesDeg[j][layout.axis(i)] += 1e-5;
            m.anglesDeg[j][layout.axis(i)] -= 1e-5;
            forwardKinematics(sk, p, fkp);
            forwardKinematics(sk, m, fkm);
            worst =
                std::max(worst, ((fkp.jointCm[held] - fkm.jointCm[held]) / 2e-5 - jac.col(i)).cwiseAbs().maxCoeff());
            if (j == held) CHECK(jac.col(i).norm() == 0.0);  // turning a joint leaves its origin where it is
        }
        CHECK(worst < 1e-5);
    }
}
