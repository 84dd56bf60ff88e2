// BVH export: read → write → read keeps FK within 0.01 cm on every kind of source clip; a BVH
// source keeps its own hierarchy.
#include "io/bvh_reader.h"
#include "io/bvh_writer.h"
#include "io/clip_loader.h"
#include "skeleton/clip_match.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/synthetic_clip.h"
#include "test_support.h"

using namespace mgp;

namespace {
double worstEffectorGap(const Clip& a, const Clip& b) {
    REQUIRE(a.frameCount() == b.frameCount());
    FkState fa, fb;
    double worst = 0.0;
    for (int t = 0; t < a.frameCount(); ++t) {
        forwardKinematics(a.skeleton, a.frames[t], fa);
        forwardKinematics(b.skeleton, b.frames[t], fb);
        worst = std::max(worst, (fa.jointCm[0] - fb.jointCm[0]).norm());
        for (int e = 0; e < kEffectorCount; ++e) {
            const auto eff = static_cast<Effector>(e);
            worst = std::max(worst, (effectorCm(a.skeleton, fa, eff) - effectorCm(b.skeleton, fb, eff)).norm());
        }
    }
    return worst;
}
}  // namespace

TEST_CASE("BVH round trip keeps root and effector positions within 0.01 cm") {
    const std::string dir = test::scratchDir("bvh_writer");
    std::vector<std::string> sources;
    for (const char* shipped :
         {"asf_amc/35_01.amc", "asf_amc/10_02.amc", "bvh/02_03.bvh", "bvh/49_04.bvh", "bvh/131_01.bvh"})
        sources.push_back(test::mocap(shipped));
    // ACCAD's Swagger (not CMU, never shipped) when the full folder is here.
    if (const auto swagger = test::sharedMocap("bvh/Swagger.bvh"))
        sources.push_back(*swagger);
    else
        MESSAGE("Swagger.bvh (../shared/mocap) is absent: the CMU conventions only");
    for (const std::string& source : sources) {
        CAPTURE(source);
        const Clip clip = loadClip(source);
        const std::string out = dir + "/export.bvh";
        writeBvh(clip, out);
        const Clip back = readBvh(out);
        CHECK(back.frameCount() == clip.frameCount());
        const double gap = worstEffectorGap(clip, back);
        MESSAGE(source << ": worst root/effector gap after the round trip " << gap << " cm");
        CHECK(gap < 0.01);
        const std::string text = test::readText(out);
        CHECK(text.find('#') == std::string::npos);
        if (clip.format == ClipFormat::kBvh) {
            // A BVH comes back in its own hierarchy: the same joints, names, offsets, channel
            // orders, units, convention and rest frame, every joint where it was.
            std::string why;
            CHECK_MESSAGE(sameSkeleton(back.skeleton, clip.skeleton, &why), why);
            CHECK(back.convention == clip.convention);
            CHECK(back.cmPerFileUnit == clip.cmPerFileUnit);
            CHECK(back.restFrame == clip.restFrame);
            CHECK(text.rfind("HIERARCHY\nROOT " + clip.skeleton.joints[0].name + "\n", 0) == 0);
            FkState fa, fb;
            double worstJoint = 0.0;
            for (int t = 0; t < clip.frameCount(); ++t) {
                forwardKinematics(clip.skeleton, clip.frames[t], fa);
                forwardKinematics(back.skeleton, back.frames[t], fb);
                for (int j = 0; j < clip.skeleton.jointCount(); ++j)
                    worstJoint = std::max(worstJoint, (fa.jointCm[j] - fb.jointCm[j]).norm());
            }
            CHECK(worstJoint < 1e-5);
        } else {
            // Any other clip: the standard cm layout with ASF bone names.
            CHECK(back.convention == "asf-names");
            CHECK(back.cmPerFileUnit == 1.0);
            CHECK_FALSE(back.restFrame);
            CHECK(text.rfind("HIERARCHY\nROOT root\n{\n  OFFSET 0.000000000 0.000000000 0.000000000\n"
                             "  CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n",
                             0) == 0);
        }
    }
}

TEST_CASE("an exported CMU clip has exactly the root and the 22 model bones, named by ASF name") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Clip back = parseBvh("x.bvh", formatBvh(clip));
    CHECK(back.skeleton.jointCount() == 23);
    CHECK(back.unmappedJoints.empty());
    CHECK(missingModelBones(back.skeleton).empty());
    // lhipjoint sits at the root with OFFSET 0; lfemur's OFFSET is the lhipjoint vector.
    const Skeleton& a = clip.skeleton;
    const Skeleton& b = back.skeleton;
    CHECK((b.joints[b.findJoint("lfemur")].offsetCm - a.joints[a.findBone("lhipjoint")].tailCm).norm() < 1e-8);
    // Frame k of the export is clip frame k (no rest frame).
    CHECK((back.frames[0].rootCm - clip.frames[0].rootCm).norm() < 1e-8);
}

TEST_CASE("BVH export of the synthetic walk round-trips too") {
    const Clip clip = makeSyntheticWalk(30);
    const Clip back = parseBvh("walk.bvh", formatBvh(clip));
    CHECK(worstEffectorGap(clip, back) < 0.01);
}
