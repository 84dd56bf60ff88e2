// Onion skins and motion trails as scene data (render/motion_overlays.h), from the shipped walk:
// which frames the ghosts show and how they fade, and that a trail is the point's FK position on
// every frame of its window.
#include <doctest/doctest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "gl_test_paths.h"
#include "io/clip_loader.h"
#include "render/motion_overlays.h"
#include "render/scene_builder.h"
#include "skeleton/forward_kinematics.h"

using namespace mgp;
using namespace mgp::render;

namespace {

std::vector<int> onionFramesOf(const std::vector<OnionGhostFrame>& g) {
    std::vector<int> f;
    for (const OnionGhostFrame& x : g) f.push_back(x.frame);
    return f;
}

// Runs a shell command; its exit status and what it printed (stdout and stderr).
int runOverlayCli(const std::string& command, std::string& output) {
    output.clear();
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    REQUIRE(pipe);
    char buf[512];
    while (std::fgets(buf, sizeof buf, pipe)) output += buf;
    const int status = ::pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool trailPointIs(const glm::vec3& a, const Eigen::Vector3d& b) {
    return std::abs(a.x - b.x()) < 1e-3 && std::abs(a.y - b.y()) < 1e-3 && std::abs(a.z - b.z()) < 1e-3;
}

}  // namespace

TEST_CASE("onion skin: the ghosts' frames, farthest first on each side, inside the clip") {
    const std::vector<OnionGhostFrame> g = onionFrames(OnionSkin{2, 3, 5}, 50, 100);
    CHECK(onionFramesOf(g) == std::vector<int>{40, 45, 65, 60, 55});
    REQUIRE(g.size() == 5);
    CHECK(g[0].step == -2);
    CHECK(g[1].step == -1);
    CHECK(g[2].step == 3);
    CHECK(g[4].step == 1);
    // Near the clip's ends only the ghosts inside it.
    CHECK(onionFramesOf(onionFrames(OnionSkin{2, 2, 5}, 3, 100)) == std::vector<int>{13, 8});
    CHECK(onionFramesOf(onionFrames(OnionSkin{2, 2, 5}, 96, 100)) == std::vector<int>{86, 91});
    CHECK(onionFrames(OnionSkin{0, 0, 5}, 50, 100).empty());
    // Counts and spacing are clamped to what the View menu offers.
    CHECK(onionFrames(OnionSkin{99, 0, 1}, 500, 1000).size() == static_cast<std::size_t>(kMaxOnionGhosts));
    CHECK(onionFramesOf(onionFrames(OnionSkin{1, 0, 0}, 50, 100)) == std::vector<int>{49});
    CHECK(onionFramesOf(onionFrames(OnionSkin{1, 0, 1000}, 500, 1000)) == std::vector<int>{500 - kMaxOnionSpacing});
}

TEST_CASE("onion skin: ghosts fade with distance, green before and blue after, and cast no shadow") {
    const Clip clip = loadClip(test::kMocap + "/asf_amc/35_01.amc");
    const OnionSkin o{3, 1, 5};
    const Figure nearBefore = onionGhost(clip.skeleton, clip.frames[95], -1, o);
    const Figure midBefore = onionGhost(clip.skeleton, clip.frames[90], -2, o);
    const Figure farBefore = onionGhost(clip.skeleton, clip.frames[85], -3, o);
    const Figure after = onionGhost(clip.skeleton, clip.frames[105], 1, o);
    for (const Figure* f : {&nearBefore, &midBefore, &farBefore, &after}) {
        CHECK(f->ghost);
        CHECK(f->stillOverlay);  // another frame's pose: cached while this one is posed
        CHECK_FALSE(f->castsShadow);
        CHECK_FALSE(f->bones.empty());
    }
    CHECK(nearBefore.ghostAlpha == doctest::Approx(0.45));
    CHECK(midBefore.ghostAlpha == doctest::Approx(0.325));
    CHECK(farBefore.ghostAlpha == doctest::Approx(0.20));
    CHECK(after.ghostAlpha == doctest::Approx(0.45));        // one ghost after: the nearest one
    CHECK(nearBefore.ghostTint.g > nearBefore.ghostTint.r);  // green before
    CHECK(after.ghostTint.b > after.ghostTint.g);            // blue after
    // The ghost is the frame's pose, slim: the figure's bones at half their thickness, no joint balls.
    FkState fk;
    forwardKinematics(clip.skeleton, clip.frames[90], fk);
    const Figure solid = makeFigure(clip.skeleton, fk);
    REQUIRE(solid.bones.size() == midBefore.bones.size());
    for (std::size_t b = 0; b < solid.bones.size(); ++b) {
        CHECK(solid.bones[b].startCm == midBefore.bones[b].startCm);
        CHECK(solid.bones[b].endCm == midBefore.bones[b].endCm);
        CHECK(midBefore.bones[b].startRadiusCm == doctest::Approx(0.5 * solid.bones[b].startRadiusCm));
    }
    CHECK(midBefore.joints.empty());
}

TEST_CASE("motion trail: the point's FK position on every frame of the window, a tick on each") {
    const Clip clip = loadClip(test::kMocap + "/asf_amc/35_01.amc");
    const auto poseAt = [&clip](int f) -> const Pose& { return clip.frames[f]; };
    const Path hand = motionTrail(clip.skeleton, poseAt, clip.frameCount(), TrailPart::kRHand, 90, 110, 100, false);
    REQUIRE(hand.pointsCm.size() == 21);
    for (int f = 90; f <= 110; ++f) {
        CAPTURE(f);
        CHECK(trailPointIs(hand.pointsCm[f - 90], effectorCm(clip.skeleton, clip.frames[f], Effector::kRHand)));
    }
    CHECK(hand.currentPoint == 10);
    CHECK(hand.tickRadiusCm > hand.radiusCm);
    // The root's trail is joint 0's path.
    const Path root = motionTrail(clip.skeleton, poseAt, clip.frameCount(), TrailPart::kRoot, 0, 4, 2, false);
    REQUIRE(root.pointsCm.size() == 5);
    FkState fk;
    forwardKinematics(clip.skeleton, clip.frames[3], fk);
    CHECK(trailPointIs(root.pointsCm[3], fk.jointCm[0]));
    // Clamped to the clip; the captured reference is thinner, unticked and has no current point.
    const Path captured =
        motionTrail(clip.skeleton, poseAt, clip.frameCount(), TrailPart::kLFoot, -30, clip.frameCount() + 30, 0, true);
    CHECK(captured.pointsCm.size() == static_cast<std::size_t>(clip.frameCount()));
    CHECK(captured.radiusCm < hand.radiusCm);
    CHECK(captured.tickRadiusCm == 0.0f);
    CHECK(captured.currentPoint == -1);
}

TEST_CASE("motion trail: cut for posing, the stretches away from the current frame are still overlays") {
    Path trail;
    for (int i = 0; i < 7; ++i) trail.pointsCm.push_back(glm::vec3(float(i), 0.0f, 0.0f));
    trail.tickRadiusCm = 0.7f;
    trail.currentPoint = 3;
    const std::vector<Path> pieces = splitForPosing(trail);
    REQUIRE(pieces.size() == 3);
    // Before (0..2) and after (4..6) are still; the live piece runs 2..4 and carries the mark.
    CHECK(pieces[0].stillOverlay);
    CHECK(pieces[0].pointsCm == std::vector<glm::vec3>(trail.pointsCm.begin(), trail.pointsCm.begin() + 3));
    CHECK(pieces[0].currentPoint == -1);
    CHECK_FALSE(pieces[1].stillOverlay);
    CHECK(pieces[1].pointsCm == std::vector<glm::vec3>(trail.pointsCm.begin() + 2, trail.pointsCm.begin() + 5));
    CHECK(pieces[1].currentPoint == 1);
    CHECK(pieces[2].stillOverlay);
    CHECK(pieces[2].pointsCm == std::vector<glm::vec3>(trail.pointsCm.begin() + 4, trail.pointsCm.end()));
    for (const Path& p : pieces) CHECK(p.tickRadiusCm == trail.tickRadiusCm);
    // At the window's first point there is nothing before; without a current point, one still piece.
    trail.currentPoint = 0;
    const std::vector<Path> atStart = splitForPosing(trail);
    REQUIRE(atStart.size() == 2);
    CHECK(atStart[0].pointsCm.size() == 2);
    CHECK(atStart[0].currentPoint == 0);
    CHECK(atStart[1].pointsCm.size() == 6);
    trail.currentPoint = -1;
    const std::vector<Path> none = splitForPosing(trail);
    REQUIRE(none.size() == 1);
    CHECK(none[0].stillOverlay);
    CHECK(none[0].pointsCm == trail.pointsCm);
}

TEST_CASE("motion trail: part names round-trip and unknown ones are refused") {
    for (int i = 0; i < kTrailPartCount; ++i) {
        TrailPart p{};
        REQUIRE(parseTrailPart(trailPartName(static_cast<TrailPart>(i)), p));
        CHECK(static_cast<int>(p) == i);
    }
    TrailPart p{};
    CHECK_FALSE(parseTrailPart("tail", p));
    CHECK_FALSE(parseTrailPart("", p));
}

TEST_CASE("render --onion and --trail draw onion skins and trails, and bad values are one clear error") {
    namespace fs = std::filesystem;
    const std::string dir = std::string(MOTIONGP_GL_OUT_DIR) + "/render_overlays_" + std::to_string(::getpid());
    fs::create_directories(dir);
    const std::string bin = std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") + MOTIONGP_TEST_BINARY + "' render '" +
                            test::kMocap + "/asf_amc/35_01.amc' --frame 100 --size 240x160 ";
    std::string out;
    REQUIRE(runOverlayCli(bin + "--out '" + dir + "/plain.png'", out) == 0);
    REQUIRE(runOverlayCli(
                bin + "--onion 2:2:5 --trail rfoot --trail root --trail-frames 20 --out '" + dir + "/overlays.png'",
                out) == 0);
    auto bytes = [](const std::string& p) {
        std::ifstream f(p, std::ios::binary);
        return std::vector<char>(std::istreambuf_iterator<char>(f), {});
    };
    CHECK(bytes(dir + "/plain.png") != bytes(dir + "/overlays.png"));
    const struct {
        std::string args, expected;
    } bad[] = {{"--onion 2:2", "expected --onion BEFORE:AFTER:SPACING"},
               {"--onion 11:0:5", "expected --onion BEFORE:AFTER:SPACING with BEFORE and AFTER in 0..10"},
               {"--onion 1:1:0", "SPACING in 1..60"},
               {"--trail tail", "expected --trail among {lhand, rhand, lfoot, rfoot, head, root}, found 'tail'"},
               {"--trail-frames 0", "expected --trail-frames of at least 1, found 0"}};
    for (const auto& b : bad) {
        CAPTURE(b.args);
        CHECK(runOverlayCli(bin + b.args + " --out '" + dir + "/bad.png'", out) == 2);
        CHECK(out.find(b.expected) != std::string::npos);
        CHECK(std::count(out.begin(), out.end(), '\n') == 1);
        CHECK_FALSE(fs::exists(dir + "/bad.png"));
    }
    fs::remove_all(dir);
}

TEST_CASE("motion trail: the captured trail's stretches that differ from the edited one, one path each") {
    Path captured, edited;
    for (int i = 0; i < 10; ++i) {
        captured.pointsCm.push_back(glm::vec3(float(i), 0.0f, 0.0f));
        edited.pointsCm.push_back(glm::vec3(float(i), 0.0f, 0.0f));
    }
    CHECK(differingParts(captured, edited, 0.05f).empty());  // the same trail: nothing to draw beneath
    edited.pointsCm[2].y = 3.0f;
    edited.pointsCm[7].y = 3.0f;
    edited.pointsCm[8].y = 0.04f;  // within the tolerance
    const std::vector<Path> parts = differingParts(captured, edited, 0.05f);
    REQUIRE(parts.size() == 2);
    REQUIRE(parts[0].pointsCm.size() == 3);  // points 1, 2, 3
    CHECK(parts[0].pointsCm.front().x == 1.0f);
    CHECK(parts[0].pointsCm.back().x == 3.0f);
    REQUIRE(parts[1].pointsCm.size() == 3);  // points 6, 7, 8
    CHECK(parts[1].pointsCm.front().x == 6.0f);
    CHECK(parts[1].currentPoint == -1);
}
