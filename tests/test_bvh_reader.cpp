// BVH: the three cgspeed conventions, ACCAD's Swagger, cross-format checks against the AMC.
#include "io/asf_reader.h"
#include "io/bvh_reader.h"
#include "io/clip_loader.h"
#include "skeleton/forward_kinematics.h"
#include "skip.h"
#include "test_support.h"

using namespace mgp;

namespace {

struct Expect {
    const char* file;
    const char* convention;
    int frames;
    bool rest;
    int modelBones;
    std::size_t unmapped;
};

void checkConventions(const std::vector<Expect>& cases, bool shipped) {
    for (const Expect& e : cases) {
        const std::string file = e.file;
        CAPTURE(file);
        const std::string relative = std::string("bvh/") + e.file + ".bvh";
        const auto path = shipped ? std::optional<std::string>(test::mocap(relative)) : test::sharedMocap(relative);
        REQUIRE_MESSAGE(path, "the full CMU set lacks " << relative);
        const Clip clip = loadClip(*path);
        CHECK(clip.convention == e.convention);
        CHECK(clip.frameCount() == e.frames);
        CHECK(clip.restFrame == e.rest);
        CHECK(clip.fps == 120.0);
        CHECK(kModelBones - static_cast<int>(missingModelBones(clip.skeleton).size()) == e.modelBones);
        CHECK(clip.unmappedJoints.size() == e.unmapped);
        for (int k = 0; k < kEffectorCount; ++k) CHECK(clip.skeleton.hasEffector(static_cast<Effector>(k)));
        // Standing height in cm whatever the file's units (MotionBuilder/3dsMax use ASF units).
        FkState fk;
        forwardKinematics(clip.skeleton, clip.frames[clip.restFrame ? 1 : 0], fk);
        const double head = effectorCm(clip.skeleton, fk, Effector::kHead).y();
        CHECK(head > 120.0);
        CHECK(head < 200.0);
    }
}

}  // namespace

TEST_CASE("conventions, rest frames, units and unmapped joints of the shipped BVH files (one per cgspeed release)") {
    checkConventions({{"02_03", "cgspeed-daz", 174, true, 20, 22},
                      {"49_04", "cgspeed-motionbuilder", 252, true, 22, 0},
                      {"131_01", "cgspeed-3dsmax", 994, false, 22, 0}},
                     true);
}

TEST_CASE("conventions of the other BVH files of the full CMU set, and ACCAD's Swagger") {
    if (test::sharedMocapDir().empty()) MGP_SKIP("the full CMU set (../shared/mocap) is absent here");
    checkConventions({{"10_01", "cgspeed-daz", 802, true, 20, 22},
                      {"131_02", "cgspeed-3dsmax", 1247, false, 22, 0},
                      {"131_03", "cgspeed-3dsmax", 1102, false, 22, 0},
                      {"Swagger", "asf-names", 581, false, 17, 0}},
                     false);
}

TEST_CASE("per-joint channel orders are kept (Daz Z X Y, 3dsMax legs Z Y X, arms Z X Y)") {
    const Clip daz = loadClip(test::mocap("bvh/02_03.bvh"));
    CHECK(daz.skeleton.joints[daz.skeleton.findJoint("rThigh")].order == RotationOrder{kAxisZ, kAxisX, kAxisY});
    CHECK(daz.skeleton.joints[0].order == RotationOrder{kAxisZ, kAxisY, kAxisX});
    const Clip max = loadClip(test::mocap("bvh/131_01.bvh"));
    CHECK(max.skeleton.joints[max.skeleton.findJoint("LeftKnee")].order == RotationOrder{kAxisZ, kAxisY, kAxisX});
    CHECK(max.skeleton.joints[max.skeleton.findJoint("LeftElbow")].order == RotationOrder{kAxisZ, kAxisX, kAxisY});
}

TEST_CASE("cross-format: Daz BVH frame k+1 is AMC frame k (02_03 shipped, 10_01 of the full set when present)") {
    std::vector<std::pair<std::string, std::string>> pairs = {
        {test::mocap("asf_amc/02_03.amc"), test::mocap("bvh/02_03.bvh")}};
    if (const auto a = test::sharedMocap("asf_amc/10_01.amc"), b = test::sharedMocap("bvh/10_01.bvh"); a && b)
        pairs.emplace_back(*a, *b);
    else
        MESSAGE("10_01 is not shipped; checking 02_03 only");
    for (const auto& [amcPath, bvhPath] : pairs) {
        const std::string trial = amcPath;
        CAPTURE(trial);
        const Clip amc = loadClip(amcPath);
        const Clip bvh = loadClip(bvhPath);
        REQUIRE(bvh.frameCount() == amc.frameCount() + 1);
        double worstRoot = 0.0;
        for (int k = 0; k < amc.frameCount(); ++k)
            worstRoot = std::max(worstRoot,
                                 (bvh.frames[k + 1].anglesDeg[0] - amc.frames[k].anglesDeg[0]).cwiseAbs().maxCoeff());
        CHECK(worstRoot <= 1e-4);
        // Report, do not assert: the Daz release is retargeted onto a generic figure.
        FkState fa, fb;
        double worst[kEffectorCount + 1] = {};
        for (int k = 0; k < amc.frameCount(); ++k) {
            forwardKinematics(amc.skeleton, amc.frames[k], fa);
            forwardKinematics(bvh.skeleton, bvh.frames[k + 1], fb);
            worst[kEffectorCount] = std::max(worst[kEffectorCount], (fa.jointCm[0] - fb.jointCm[0]).norm());
            for (int e = 0; e < kEffectorCount; ++e) {
                const auto eff = static_cast<Effector>(e);
                worst[e] =
                    std::max(worst[e], (effectorCm(amc.skeleton, fa, eff) - effectorCm(bvh.skeleton, fb, eff)).norm());
            }
        }
        MESSAGE(trial << " AMC vs Daz BVH, max distance (cm): root " << worst[kEffectorCount] << ", head " << worst[4]
                      << ", lhand " << worst[0] << ", rhand " << worst[1] << ", lfoot " << worst[2] << ", rfoot "
                      << worst[3]);
    }
}

TEST_CASE("MotionBuilder BVH offsets equal subject 49's ASF bone vectors") {
    const Clip bvh = loadClip(test::mocap("bvh/49_04.bvh"));
    const Skeleton asf = readAsf(test::mocap("asf_amc/49.asf")).skeleton;
    // LeftUpLeg's offset is the lhipjoint vector; LeftLeg's offset is the lfemur vector.
    const auto& b = bvh.skeleton.joints;
    const auto& a = asf.joints;
    CHECK((b[bvh.skeleton.findJoint("LeftUpLeg")].offsetCm - a[asf.findBone("lhipjoint")].tailCm).norm() < 0.01);
    CHECK((b[bvh.skeleton.findJoint("LeftLeg")].offsetCm - a[asf.findBone("lfemur")].tailCm).norm() < 0.01);
}

TEST_CASE("BVH: mixed CRLF/LF, 'Frames:' with a tab, End Sites, and a minimal file") {
    const std::string text =
        "HIERARCHY\r\nROOT root\n{\r\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation "
        "Xrotation\r\n"
        "  JOINT lfemur\n  {\n    OFFSET 5 -5 0\r\n    CHANNELS 3 Zrotation Xrotation Yrotation\n"
        "    End Site\r\n    {\n      OFFSET 0 -40 0\n    }\n  }\n}\r\nMOTION\nFrames:\t2\r\nFrame Time: 0.0333333\n"
        "1 90 2 0 0 0 0 0 0\r\n1 90 2 0 0 0 10 0 0\n";
    const Clip clip = parseBvh("mini.bvh", text);
    CHECK(clip.frameCount() == 2);
    CHECK(clip.fps == 30.0);
    const int femur = clip.skeleton.findBone("lfemur");
    REQUIRE(femur == 1);
    CHECK(clip.skeleton.joints[femur].tailCm == Eigen::Vector3d(0, -40, 0));
    CHECK(clip.frames[1].rootCm == Eigen::Vector3d(1, 90, 2));
    CHECK(clip.frames[1].anglesDeg[femur].z() == 10.0);
}
