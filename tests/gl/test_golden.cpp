// Golden-image tests: fixed scenes from real clips drawn offscreen (EGL surfaceless + pbuffer,
// the same path as `motiongp render`) and compared with PNGs committed in assets/goldens/.
//
// Regenerate the goldens (only on llvmpipe, after an intended visual change):
//   MOTIONGP_UPDATE_GOLDENS=1 ctest --test-dir build -L gl
//
// Threshold: a pixel matches when every channel is within 2/255 of the golden, and at least
// 99.9 % of the pixels must match. On the machine that made the goldens the output is
// byte-identical (see the determinism tests), so the tolerance is not for run-to-run noise: it
// absorbs llvmpipe differences between Mesa versions and CPUs (LLVM code generation for a
// different SIMD width rounds pow/exp in the shaders and edge coverage of MSAA samples slightly
// differently), which move a few edge pixels by a few levels. A real regression (a moved bone,
// a colour change, a missing grid) changes far more than 0.1 % of the pixels.
// On failure the actual image and an amplified diff are written to <build>/tests/gl/out/.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "gl_test_paths.h"
#include "io/clip_loader.h"
#include "render/scene_builder.h"
#include "render/snapshot.h"

#define STB_IMAGE_IMPLEMENTATION
#include "skip.h"
#include "stb_image_include.h"

using namespace mgp;
using namespace mgp::render;
namespace fs = std::filesystem;

namespace {

using test::kGoldenDir;
using test::kMocap;
using test::kOutDir;
constexpr int kTolerance = 2;           // per channel, out of 255
constexpr double kMinMatching = 0.999;  // fraction of pixels within kTolerance
constexpr int kWidth = 400, kHeight = 300;

bool updateMode() {
    const char* v = std::getenv("MOTIONGP_UPDATE_GOLDENS");
    return v && std::string(v) == "1";
}

// Creates the offscreen context, or says why the test is skipped (no EGL/Mesa, not llvmpipe).
std::unique_ptr<OffscreenContext> referenceContext(int w, int h) {
    std::unique_ptr<OffscreenContext> ctx;
    try {
        ctx = std::make_unique<OffscreenContext>(w, h);
    } catch (const RenderError& e) {
        MGP_MARK_SKIPPED("no offscreen GL context: " << e.what());
        return nullptr;
    }
    const GlInfo info = currentGlInfo();
    if (!info.isLlvmpipe()) {
        MGP_MARK_SKIPPED("goldens are made with Mesa llvmpipe; this context is '" << info.renderer << "' ("
                                                                                  << info.version << ")");
        return nullptr;
    }
    return ctx;
}

struct GoldenScene {
    Scene scene;
    OrbitCamera camera;
};

// A frame of a clip exactly as `motiongp render CLIP --frame T --camera C` draws it.
GoldenScene clipScene(const std::string& amc, int frame1, CameraPreset preset, ClipSceneOptions opt = {},
                      int width = kWidth, int height = kHeight) {
    const Clip clip = loadClip(kMocap + "/asf_amc/" + amc);
    opt.frameIndex = frame1 - 1;
    GoldenScene g;
    g.scene = buildClipScene(clip, opt);
    FkState fk;
    forwardKinematics(clip.skeleton, clip.frames[opt.frameIndex], fk);
    g.camera = framedPresetCamera(preset, g.scene, characterForward(clip.skeleton, fk), width, height);
    return g;
}

// Editor overlays: hover and selected handles, a reached and a missed target, pins, a path.
GoldenScene overlayScene() {
    ClipSceneOptions opt;
    opt.hovered = Effector::kLHand;
    opt.selected = Effector::kRHand;
    opt.paths = {Effector::kLHand};
    GoldenScene g = clipScene("35_01.amc", 100, CameraPreset::kThreeQuarter, opt);
    for (const Handle& h : g.scene.handles) {
        if (h.id == static_cast<int>(Effector::kRHand)) {
            Target t;
            t.positionCm = h.positionCm + glm::vec3(0.0f, 25.0f, 20.0f);
            t.hasFrom = true;
            t.fromCm = h.positionCm;
            g.scene.targets.push_back(t);
        }
        if (h.id == static_cast<int>(Effector::kHead)) {
            Target t;
            t.positionCm = h.positionCm + glm::vec3(0.0f, 12.0f, 0.0f);
            t.reached = true;
            g.scene.targets.push_back(t);
        }
        if (h.id == static_cast<int>(Effector::kLFoot) || h.id == static_cast<int>(Effector::kRFoot))
            g.scene.pins.push_back({h.positionCm});
    }
    return g;
}

Image renderOnce(const GoldenScene& g, OffscreenContext& ctx) {
    SceneRenderer renderer;
    return snapshot(ctx, renderer, g.scene, g.camera);
}

void compareWithGolden(const std::string& name, const Image& actual) {
    const std::string goldenPath = kGoldenDir + "/" + name + ".png";
    if (updateMode()) {
        fs::create_directories(kGoldenDir);
        writePng(actual, goldenPath);
        MESSAGE("updated golden " << goldenPath);
        return;
    }
    int w = 0, h = 0, n = 0;
    stbi_uc* golden = stbi_load(goldenPath.c_str(), &w, &h, &n, 4);
    fs::create_directories(kOutDir);
    if (!golden) {
        writePng(actual, kOutDir + "/" + name + ".actual.png");
        FAIL("missing golden " << goldenPath
                               << " (regenerate: MOTIONGP_UPDATE_GOLDENS=1 ctest --test-dir build -L gl)");
        return;
    }
    REQUIRE(w == actual.width);
    REQUIRE(h == actual.height);
    Image diff;
    diff.width = w;
    diff.height = h;
    diff.rgba.assign(actual.rgba.size(), 255);
    long matching = 0;
    int worst = 0;
    for (long p = 0; p < static_cast<long>(w) * h; ++p) {
        int pixelMax = 0;
        for (int c = 0; c < 4; ++c) {
            const int d = std::abs(int(actual.rgba[p * 4 + c]) - int(golden[p * 4 + c]));
            pixelMax = std::max(pixelMax, d);
            if (c < 3) diff.rgba[p * 4 + c] = static_cast<std::uint8_t>(std::min(255, d * 16));
        }
        worst = std::max(worst, pixelMax);
        matching += pixelMax <= kTolerance;
    }
    stbi_image_free(golden);
    const double fraction = static_cast<double>(matching) / (static_cast<double>(w) * h);
    INFO(name << ": " << fraction * 100.0 << " % of pixels within " << kTolerance << "/255 (need "
              << kMinMatching * 100.0 << " %), worst channel difference " << worst);
    if (fraction >= kMinMatching) {  // drop the outputs of an earlier failure
        fs::remove(kOutDir + "/" + name + ".actual.png");
        fs::remove(kOutDir + "/" + name + ".diff.png");
    } else {
        writePng(actual, kOutDir + "/" + name + ".actual.png");
        writePng(diff, kOutDir + "/" + name + ".diff.png");
        MESSAGE("wrote " << kOutDir << "/" << name << ".actual.png and .diff.png");
    }
    CHECK(fraction >= kMinMatching);
}

void runGolden(const std::string& name, const GoldenScene& g, int width = kWidth, int height = kHeight) {
    auto ctx = referenceContext(width, height);
    if (!ctx) return;
    const Image img = renderOnce(g, *ctx);
    // Not an empty frame: the figure and the grid put many distinct colours in the picture.
    std::size_t differentFromCorner = 0;
    for (std::size_t i = 0; i < img.rgba.size(); i += 4)
        differentFromCorner += img.rgba[i] != img.rgba[0] || img.rgba[i + 1] != img.rgba[1];
    CHECK(differentFromCorner > img.rgba.size() / 4 / 4);
    compareWithGolden(name, img);
}

}  // namespace

TEST_CASE("golden: 35_01 frame 1, front camera") {
    runGolden("35_01_f1_front", clipScene("35_01.amc", 1, CameraPreset::kFront));
}

TEST_CASE("golden: 35_01 frame 1, side camera") {
    runGolden("35_01_f1_side", clipScene("35_01.amc", 1, CameraPreset::kSide));
}

TEST_CASE("golden: 35_01 frame 1, three-quarter camera with the captured ghost") {
    ClipSceneOptions opt;
    opt.ghostCaptured = true;
    runGolden("35_01_f1_three_quarter_ghost", clipScene("35_01.amc", 1, CameraPreset::kThreeQuarter, opt));
}

TEST_CASE("golden: 10_02 kick (frame 362), side camera, right-foot path selected") {
    ClipSceneOptions opt;
    opt.selected = Effector::kRFoot;
    opt.paths = {Effector::kRFoot};
    runGolden("10_02_f362_kick_side", clipScene("10_02.amc", 362, CameraPreset::kSide, opt));
}

TEST_CASE("golden: editor overlays (hover, selected, targets, pins, path)") {
    runGolden("35_01_f100_overlays", overlayScene());
}

TEST_CASE("golden: onion skins (2 before, 2 after, 10 frames apart) and motion trails, 1280x720") {
    ClipSceneOptions opt;
    opt.onion = OnionSkin{2, 2, 10};
    opt.trails = {TrailPart::kLFoot, TrailPart::kRFoot, TrailPart::kRHand, TrailPart::kRoot};
    opt.trailHalfSpan = 30;
    opt.handles = false;
    runGolden("35_01_f100_onion_trails", clipScene("35_01.amc", 100, CameraPreset::kThreeQuarter, opt, 1280, 720), 1280,
              720);
}

TEST_CASE("golden: the rotate gizmo on the right thigh (three rings over the figure), 1280x720") {
    const Clip clip = loadClip(kMocap + "/asf_amc/35_01.amc");
    ClipSceneOptions opt;
    opt.gizmoJoint = clip.skeleton.findBone("rfemur");
    REQUIRE(opt.gizmoJoint >= 0);
    opt.handles = false;
    runGolden("35_01_f100_rotate_gizmo", clipScene("35_01.amc", 100, CameraPreset::kThreeQuarter, opt, 1280, 720), 1280,
              720);
}

TEST_CASE("determinism: two fresh contexts draw byte-identical PNGs") {
    const GoldenScene g = overlayScene();
    std::vector<std::uint8_t> first, second;
    {
        auto ctx = referenceContext(kWidth, kHeight);
        if (!ctx) return;
        first = encodePng(renderOnce(g, *ctx));
    }
    {
        auto ctx = referenceContext(kWidth, kHeight);
        if (!ctx) return;
        SceneRenderer renderer;
        snapshot(*ctx, renderer, g.scene, g.camera);  // a frame drawn before must not matter
        second = encodePng(snapshot(*ctx, renderer, g.scene, g.camera));
    }
    CHECK(first == second);
}

TEST_CASE("determinism: `motiongp render` twice writes identical PNGs, with no display") {
    if (!referenceContext(64, 64)) return;
    fs::create_directories(kOutDir);
    const std::string a = kOutDir + "/cli_a.png", b = kOutDir + "/cli_b.png";
    const std::string base = std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") + MOTIONGP_TEST_BINARY + "' render '" +
                             kMocap + "/asf_amc/10_02.amc' --frame 362 --size 320x240 " +
                             "--camera three-quarter --ghost-captured --path rfoot --out ";
    REQUIRE(std::system((base + "'" + a + "' > /dev/null").c_str()) == 0);
    REQUIRE(std::system((base + "'" + b + "' > /dev/null").c_str()) == 0);
    auto bytes = [](const std::string& p) {
        std::ifstream f(p, std::ios::binary);
        return std::vector<char>(std::istreambuf_iterator<char>(f), {});
    };
    // A third run on one llvmpipe thread: the picture must not depend on the tiling across threads.
    const std::string c = kOutDir + "/cli_c.png";
    REQUIRE(std::system(("LP_NUM_THREADS=1 " + base + "'" + c + "' > /dev/null").c_str()) == 0);
    const auto ba = bytes(a), bb = bytes(b), bc = bytes(c);
    CHECK(!ba.empty());
    CHECK(ba == bb);
    CHECK(ba == bc);
    int w = 0, h = 0, n = 0;
    REQUIRE(stbi_info(a.c_str(), &w, &h, &n));
    CHECK(w == 320);
    CHECK(h == 240);
    // Bad arguments give one clear error and a non-zero exit.
    CHECK(std::system((std::string("'") + MOTIONGP_TEST_BINARY + "' render '" + kMocap +
                       "/asf_amc/35_01.amc' --frame 0 --out /dev/null 2> /dev/null")
                          .c_str()) != 0);
    CHECK(std::system(
              (std::string("'") + MOTIONGP_TEST_BINARY + "' render no-such.model --frame 1 --out x.png 2> /dev/null")
                  .c_str()) != 0);
}

TEST_CASE("offscreen context: 3.3 core or newer, resize keeps the context") {
    auto ctx = referenceContext(64, 48);
    if (!ctx) return;
    const GlInfo info = currentGlInfo();
    int major = 0, minor = 0;
    REQUIRE(std::sscanf(info.version.c_str(), "%d.%d", &major, &minor) == 2);
    CHECK(major * 10 + minor >= 33);
    ctx->resize(32, 16);
    CHECK(ctx->width() == 32);
    CHECK(ctx->height() == 16);
    SceneRenderer renderer;
    const Image img = snapshot(*ctx, renderer, Scene{}, OrbitCamera{});
    CHECK(img.width == 32);
    CHECK(img.rgba.size() == 32u * 16u * 4u);
    CHECK(img.rgba[3] == 255);
}

TEST_CASE("renderer without MSAA draws straight into the target and matches the 4x frame closely") {
    auto ctx = referenceContext(kWidth, kHeight);
    if (!ctx) return;
    const GoldenScene g = clipScene("35_01.amc", 1, CameraPreset::kFront);
    SceneRenderer plain(1);
    CHECK(plain.msaaSamples() == 1);
    const Image a = snapshot(*ctx, plain, g.scene, g.camera);
    SceneRenderer msaa(4);
    const Image b = snapshot(*ctx, msaa, g.scene, g.camera);
    // Only edge pixels differ (antialiasing); the picture is the same.
    long close = 0;
    for (std::size_t p = 0; p < a.rgba.size(); p += 4) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c])));
        close += d <= 8;
    }
    CHECK(static_cast<double>(close) / (kWidth * kHeight) > 0.95);
    CHECK_THROWS_AS(SceneRenderer(4096), RenderError);
}
