// The ASF/AMC reader (docs/maths.md §2) and the AMC edge cases (frame labels, CRLF/LF, bone order by name).
#include <algorithm>

#include "io/amc_reader.h"
#include "io/asf_reader.h"
#include "io/clip_loader.h"
#include "skeleton/pose_layout.h"
#include "skip.h"
#include "test_support.h"

using namespace mgp;

TEST_CASE("35.asf / 35_01.amc: bones, channels, DOF selection, frames") {
    const AsfSkeleton asf = readAsf(test::mocap("asf_amc/35.asf"));
    CHECK(asf.skeleton.jointCount() == 31);  // 30 bones + root
    CHECK(asf.channelCount() == 62);
    std::vector<std::string> zeroDof;
    for (int j = 1; j < asf.skeleton.jointCount(); ++j)
        if (asf.channels[j].empty()) zeroDof.push_back(asf.skeleton.joints[j].name);
    CHECK(zeroDof == std::vector<std::string>{"lhipjoint", "rhipjoint"});
    CHECK(asf.cmPerUnit == doctest::Approx(2.54 / 0.45).epsilon(1e-15));

    // Every DOF of the docs/maths.md §2.1 order exists in the ASF: 47 rotational + 3 root translations = 50.
    const PoseLayout layout(asf.skeleton);
    int rotational = 0;
    for (int i = 0; i < kAsfPoseDofs; ++i) {
        REQUIRE(layout.joint(i) >= 0);
        CHECK(asf.skeleton.joints[layout.joint(i)].dof[layout.axis(i)]);
        ++rotational;
    }
    int translations = 0;
    for (const Channel& c : asf.channels[0]) translations += c.translation;
    CHECK(rotational + translations == 50);
    CHECK(missingModelBones(asf.skeleton).empty());

    const Clip clip = readAmc(test::mocap("asf_amc/35_01.amc"), asf);
    CHECK(clip.frameCount() == 358);
    CHECK(clip.firstFrameLabel == 1);
    CHECK(clip.fps == 120.0);
}

TEST_CASE("AMC frame numbers may start anywhere (124_03 is numbered 700-1319, full CMU set)") {
    const auto path = test::sharedMocap("asf_amc/124_03.amc");
    if (!path) MGP_SKIP("124_03.amc is not shipped; it is in the full CMU set (../shared/mocap), absent here");
    const Clip clip = loadClip(*path);
    CHECK(clip.frameCount() == 620);
    CHECK(clip.firstFrameLabel == 700);
}

TEST_CASE("LF and CRLF files parse to the same values") {
    // 16_35.amc is LF, 16.asf is CRLF; converting a CRLF file to LF must not change anything.
    const std::string crlf = test::readText(test::mocap("asf_amc/35_01.amc"));
    REQUIRE(crlf.find("\r\n") != std::string::npos);
    std::string lf;
    for (char c : crlf)
        if (c != '\r') lf += c;
    const AsfSkeleton asf = readAsf(test::mocap("asf_amc/35.asf"));
    const Clip a = parseAmc("crlf.amc", crlf, asf);
    const Clip b = parseAmc("lf.amc", lf, asf);
    REQUIRE(a.frameCount() == b.frameCount());
    for (int t = 0; t < a.frameCount(); t += 37)
        for (int j = 0; j < asf.skeleton.jointCount(); ++j) CHECK(a.frames[t].anglesDeg[j] == b.frames[t].anglesDeg[j]);
}

TEST_CASE("AMC bones are matched by name, not position") {
    const AsfSkeleton asf = readAsf(test::mocap("asf_amc/35.asf"));
    const std::string text = test::readText(test::mocap("asf_amc/35_01.amc"));
    // Take frame 1 and reverse its bone lines.
    const std::size_t f1 = text.find("\n1\r\n") + 1;
    const std::size_t f2 = text.find("\n2\r\n");
    std::string header = text.substr(0, f1);
    std::string block = text.substr(f1, f2 + 1 - f1);
    std::vector<std::string> lines;
    std::size_t s = 0;
    while (s < block.size()) {
        const std::size_t e = block.find('\n', s);
        lines.push_back(block.substr(s, e - s + 1));
        s = e + 1;
    }
    std::reverse(lines.begin() + 1, lines.end());
    std::string shuffled = header;
    for (const auto& l : lines) shuffled += l;
    const Clip a = parseAmc("orig.amc", header + block, asf);
    const Clip b = parseAmc("shuffled.amc", shuffled, asf);
    REQUIRE(a.frameCount() == 1);
    REQUIRE(b.frameCount() == 1);
    for (int j = 0; j < asf.skeleton.jointCount(); ++j) CHECK(a.frames[0].anglesDeg[j] == b.frames[0].anglesDeg[j]);
    CHECK(a.frames[0].rootCm == b.frames[0].rootCm);
}

TEST_CASE("every shipped AMC clip loads with its subject's ASF") {
    for (const char* name : {"02_03", "10_02", "10_03", "16_01", "16_35", "16_36", "35_01"}) {
        const std::string clipName = name;
        CAPTURE(clipName);
        const Clip clip = loadClip(test::mocap(std::string("asf_amc/") + name + ".amc"));
        CHECK(clip.frameCount() > 100);
        CHECK(missingModelBones(clip.skeleton).empty());
    }
}

TEST_CASE("every AMC clip of the full CMU set loads with its subject's ASF") {
    if (test::sharedMocapDir().empty()) MGP_SKIP("the full CMU set (../shared/mocap) is absent here");
    for (const char* name :
         {"02_03", "09_01", "09_02", "09_03", "10_01", "10_02", "10_03", "13_17", "16_01", "16_02",
          "16_03", "16_04", "16_05", "16_06", "16_35", "16_36", "35_01", "49_18", "49_19", "124_03"}) {
        const std::string clipName = name;
        CAPTURE(clipName);
        const auto path = test::sharedMocap(std::string("asf_amc/") + name + ".amc");
        REQUIRE_MESSAGE(path, "the full CMU set lacks " << clipName);
        const Clip clip = loadClip(*path);
        CHECK(clip.frameCount() > 100);
        CHECK(missingModelBones(clip.skeleton).empty());
    }
}
