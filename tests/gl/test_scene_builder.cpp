// Building scenes from real clips (plain data, no GL).
#include <doctest/doctest.h>

#include <filesystem>

#include "gl_test_paths.h"
#include "io/clip_loader.h"
#include "render/scene_builder.h"
#include "skeleton/synthetic_clip.h"

using namespace mgp;
using namespace mgp::render;

using test::kMocap;

TEST_CASE("scene builder: sides come from the ASF bone role") {
    CHECK(sideOfBone("lfemur") == BodySide::kLeft);
    CHECK(sideOfBone("rhumerus") == BodySide::kRight);
    CHECK(sideOfBone("lowerback") == BodySide::kCentre);
    CHECK(sideOfBone("lowerneck") == BodySide::kCentre);
    CHECK(sideOfBone("root") == BodySide::kCentre);
    CHECK(sideOfBone("head") == BodySide::kCentre);
    CHECK(sideOfBone("") == BodySide::kCentre);
}

TEST_CASE("scene builder: 35_01 frame 1 gives a standing figure with five handles") {
    const Clip clip = loadClip(kMocap + "/asf_amc/35_01.amc");
    ClipSceneOptions opt;
    opt.paths = {Effector::kRFoot};
    const Scene scene = buildClipScene(clip, opt);
    REQUIRE(scene.figures.size() == 1);
    const Figure& fig = scene.figures[0];
    int left = 0, right = 0;
    for (const BoneSegment& b : fig.bones) {
        left += b.side == BodySide::kLeft;
        right += b.side == BodySide::kRight;
    }
    CHECK(left == right);
    CHECK(left >= 8);
    CHECK(scene.handles.size() == 5);
    const Bounds b = sceneBounds(scene);
    CHECK(b.radiusCm > 70.0f);
    CHECK(b.radiusCm < 150.0f);
    // The floor is under the feet but not far below them.
    for (const Handle& h : scene.handles)
        if (h.id == static_cast<int>(Effector::kLFoot) || h.id == static_cast<int>(Effector::kRFoot)) {
            CHECK(h.positionCm.y > scene.groundHeightCm);
            CHECK(h.positionCm.y < scene.groundHeightCm + 25.0f);
        }
    REQUIRE(scene.paths.size() == 1);
    CHECK(scene.paths[0].currentPoint == 0);
    CHECK(scene.paths[0].pointsCm.size() == 61);
    CHECK(scene.paths[0].keysCm.size() == 4);
    CHECK(scene.caption.find("35_01") != std::string::npos);
}

TEST_CASE("scene builder: the ghost is beside the figure, the forward direction is horizontal") {
    const Clip clip = makeSyntheticWalk(10);
    ClipSceneOptions opt;
    opt.ghostCaptured = true;
    opt.frameIndex = 3;
    const Scene scene = buildClipScene(clip, opt);
    REQUIRE(scene.figures.size() == 2);
    CHECK(scene.figures[1].ghost);
    CHECK_FALSE(scene.figures[1].castsShadow);
    const glm::vec3 d = scene.figures[1].joints[0].centreCm - scene.figures[0].joints[0].centreCm;
    CHECK(glm::length(d) == doctest::Approx(opt.ghostSideOffsetCm).epsilon(1e-4));
    FkState fk;
    forwardKinematics(clip.skeleton, clip.frames[3], fk);
    const glm::vec3 f = characterForward(clip.skeleton, fk);
    CHECK(f.y == 0.0f);
    CHECK(glm::length(f) == doctest::Approx(1.0f));
    opt.frameIndex = 10;
    CHECK_THROWS(buildClipScene(clip, opt));
}
