// The still overlays' cached layer (render/overlay_layer.h): drawn through it, onion skins and
// trails give the picture the direct path gives, and the layer is drawn again only when they or
// the view change, not when the posed figure does.
#include <doctest/doctest.h>

#include <memory>

#include "gl_test_paths.h"
#include "io/clip_loader.h"
#include "render/scene_builder.h"
#include "render/snapshot.h"
#include "skeleton/forward_kinematics.h"
#include "skip.h"

using namespace mgp;
using namespace mgp::render;

namespace {

constexpr int kLayerWidth = 1280, kLayerHeight = 720;
constexpr long kDepthTiePixels = 10;  // see the first test
constexpr long kOverlapPixels = 300;

// The walk's frame 100 with onion skins (2:2:10) and the trails of both feet, the right hand and
// the root over ±30 frames, each trail cut at the current frame as the editor cuts it; the onion
// ghosts and the trails' stretches away from the current frame are still overlays.
struct LayerScene {
    Scene scene;
    OrbitCamera camera;
};

LayerScene walkWithOverlays() {
    const Clip clip = loadClip(test::kMocap + "/asf_amc/35_01.amc");
    ClipSceneOptions opt;
    opt.frameIndex = 99;
    opt.onion = OnionSkin{2, 2, 10};
    opt.trails = {TrailPart::kLFoot, TrailPart::kRFoot, TrailPart::kRHand, TrailPart::kRoot};
    opt.handles = false;
    opt.caption = false;
    LayerScene l;
    l.scene = buildClipScene(clip, opt);
    l.scene.paths = splitEachForPosing(l.scene.paths);
    FkState fk;
    forwardKinematics(clip.skeleton, clip.frames[99], fk);
    l.camera = framedPresetCamera(CameraPreset::kThreeQuarter, l.scene, characterForward(clip.skeleton, fk),
                                  kLayerWidth, kLayerHeight);
    return l;
}

// The same scene with nothing marked still: every overlay drawn straight into the frame.
Scene withoutStillOverlays(Scene scene) {
    for (Figure& f : scene.figures) f.stillOverlay = false;
    for (Path& p : scene.paths) p.stillOverlay = false;
    return scene;
}

int countStill(const Scene& scene) {
    int n = 0;
    for (const Figure& f : scene.figures) n += f.stillOverlay;
    for (const Path& p : scene.paths) n += p.stillOverlay;
    return n;
}

// Pixels whose channels differ from b's by more than `tolerance` (out of 255).
long pixelsDiffering(const Image& a, const Image& b, int tolerance) {
    REQUIRE(a.rgba.size() == b.rgba.size());
    long n = 0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        bool differs = false;
        for (std::size_t c = 0; c < 4; ++c)
            differs = differs || std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) > tolerance;
        n += differs;
    }
    return n;
}

std::unique_ptr<OffscreenContext> layerContext() {
    try {
        return std::make_unique<OffscreenContext>(kLayerWidth, kLayerHeight);
    } catch (const RenderError& e) {
        MGP_MARK_SKIPPED("no offscreen GL context: " << e.what());
        return nullptr;
    }
}

}  // namespace

TEST_CASE("overlay layer: onion skins and trails through the cached layer look as drawn directly") {
    std::unique_ptr<OffscreenContext> ctx = layerContext();
    if (!ctx) return;
    const LayerScene l = walkWithOverlays();
    REQUIRE(countStill(l.scene) >= 4 + 8);  // four ghosts, two still stretches per trail
    const auto compare = [&](const Scene& scene) {
        SceneRenderer layered(1), direct(1);
        const Image viaLayer = snapshot(*ctx, layered, scene, l.camera);
        const Image straight = snapshot(*ctx, direct, withoutStillOverlays(scene), l.camera);
        CHECK(layered.overlayLayerDraws() == 1);
        CHECK(direct.overlayLayerDraws() == 0);  // nothing still: no layer
        return pixelsDiffering(viaLayer, straight, 2);
    };
    // Trails alone, and ghosts alone: the same picture but for depth ties. The ghosts' colour is
    // kept premultiplied in 8 bits (a level of rounding), and where two surfaces meet at the same
    // depth a fragment compared at its exact depth directly is compared at the layer's 24-bit depth
    // through it: 1 and 2 pixels of 921 600 flip when this was written.
    Scene trailsOnly = l.scene, ghostsOnly = l.scene;
    trailsOnly.figures.resize(1);
    ghostsOnly.paths.clear();
    CHECK(compare(trailsOnly) <= kDepthTiePixels);
    CHECK(compare(ghostsOnly) <= kDepthTiePixels);
    // Both: the layer keeps only the nearest overlay surface of a pixel, so where a ghost lies in
    // front of the figure and a trail behind it, the trail shows through the ghost: 120 pixels
    // here. A missing or misplaced overlay costs thousands.
    CHECK(compare(l.scene) <= kOverlapPixels);
    // And the overlays are there at all: the plain frame differs from them in many pixels.
    SceneRenderer direct(1);
    Scene plain = l.scene;
    plain.figures.resize(1);
    plain.paths.clear();
    CHECK(pixelsDiffering(snapshot(*ctx, direct, plain, l.camera),
                          snapshot(*ctx, direct, withoutStillOverlays(l.scene), l.camera), 8) > 5000);
    // A renderer with MSAA (stills, goldens) draws them as any other item: no layer. (A driver
    // without MSAA gives a 1-sample renderer, which uses the layer.)
    SceneRenderer still(4);
    snapshot(*ctx, still, l.scene, l.camera);
    CHECK(still.overlayLayerDraws() == (still.msaaSamples() > 1 ? 0 : 1));
}

TEST_CASE("overlay layer: drawn again when the overlays or the view change, not when the figure moves") {
    std::unique_ptr<OffscreenContext> ctx = layerContext();
    if (!ctx) return;
    LayerScene l = walkWithOverlays();
    SceneRenderer layered(1), direct(1);
    snapshot(*ctx, layered, l.scene, l.camera);
    snapshot(*ctx, layered, l.scene, l.camera);
    CHECK(layered.overlayLayerDraws() == 1);
    // A pose edit moves the figure (not an overlay): the layer is reused, and the frame is still the
    // direct one, the figure hiding the ghosts behind it where it now stands.
    for (BoneSegment& b : l.scene.figures[0].bones) {
        b.startCm += glm::vec3(25.0f, 10.0f, 0.0f);
        b.endCm += glm::vec3(25.0f, 10.0f, 0.0f);
    }
    for (JointBall& j : l.scene.figures[0].joints) j.centreCm += glm::vec3(25.0f, 10.0f, 0.0f);
    const Image moved = snapshot(*ctx, layered, l.scene, l.camera);
    CHECK(layered.overlayLayerDraws() == 1);
    CHECK(pixelsDiffering(moved, snapshot(*ctx, direct, withoutStillOverlays(l.scene), l.camera), 2) <= kOverlapPixels);
    // An overlay that changes, and a camera that turns, draw it again.
    l.scene.paths.front().pointsCm.front().y += 5.0f;
    snapshot(*ctx, layered, l.scene, l.camera);
    CHECK(layered.overlayLayerDraws() == 2);
    l.camera.orbit(5.0f, 0.0f);
    const Image turned = snapshot(*ctx, layered, l.scene, l.camera);
    CHECK(layered.overlayLayerDraws() == 3);
    CHECK(pixelsDiffering(turned, snapshot(*ctx, direct, withoutStillOverlays(l.scene), l.camera), 2) <=
          kOverlapPixels);
}
