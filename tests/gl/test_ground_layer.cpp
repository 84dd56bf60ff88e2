// The cached backdrop (render/ground_layer.h, SceneRenderer::useBackdropLayer): a frame started
// from it, with only the contact shadows' square shaded again, is the frame drawn directly; the
// backdrop is drawn again when the view or the ground changes (on the second frame that shows
// the new one), not when the figure moves.
#include <doctest/doctest.h>

#include <GL/gl.h>
#include <GL/glext.h>

#include <memory>

#include "gl_test_paths.h"
#include "io/clip_loader.h"
#include "render/png_capture.h"
#include "render/scene_builder.h"
#include "render/snapshot.h"
#include "skeleton/forward_kinematics.h"
#include "skip.h"

using namespace mgp;
using namespace mgp::render;

namespace {

constexpr int kBackdropWidth = 900, kBackdropHeight = 597;  // the editor viewport's size at 1280×720

// A framebuffer of the formats the backdrop copies into (the editor viewport's).
class BackdropTarget {
public:
    BackdropTarget() {
        glGenFramebuffers(1, &fbo_);
        glGenTextures(1, &colour_);
        glGenRenderbuffers(1, &depth_);
        glBindTexture(GL_TEXTURE_2D, colour_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kBackdropWidth, kBackdropHeight, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     nullptr);
        glBindRenderbuffer(GL_RENDERBUFFER, depth_);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, kBackdropWidth, kBackdropHeight);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_);
        REQUIRE(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    ~BackdropTarget() {
        glDeleteFramebuffers(1, &fbo_);
        glDeleteTextures(1, &colour_);
        glDeleteRenderbuffers(1, &depth_);
    }
    Image draw(SceneRenderer& renderer, const Scene& scene, const OrbitCamera& camera) const {
        renderer.draw(scene, camera, kBackdropWidth, kBackdropHeight, fbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
        Image img = readFramebuffer(kBackdropWidth, kBackdropHeight);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        CHECK(glGetError() == GL_NO_ERROR);
        return img;
    }

private:
    unsigned fbo_ = 0, colour_ = 0, depth_ = 0;
};

long pixelsNotEqual(const Image& a, const Image& b) {
    REQUIRE(a.rgba.size() == b.rgba.size());
    long n = 0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4)
        n += a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] || a.rgba[i + 2] != b.rgba[i + 2] ||
             a.rgba[i + 3] != b.rgba[i + 3];
    return n;
}

struct BackdropWalk {
    Scene scene;
    OrbitCamera camera;
};

// The walk's frame 100 as the editor shows it while posing: handles, contact shadows, ground.
BackdropWalk backdropWalk() {
    const Clip clip = loadClip(test::kMocap + "/asf_amc/35_01.amc");
    ClipSceneOptions opt;
    opt.frameIndex = 99;
    opt.caption = false;
    BackdropWalk w;
    w.scene = buildClipScene(clip, opt);
    FkState fk;
    forwardKinematics(clip.skeleton, clip.frames[99], fk);
    w.camera = framedPresetCamera(CameraPreset::kThreeQuarter, w.scene, characterForward(clip.skeleton, fk),
                                  kBackdropWidth, kBackdropHeight);
    return w;
}

void shiftFigure(Figure& f, const glm::vec3& by) {
    for (BoneSegment& b : f.bones) {
        b.startCm += by;
        b.endCm += by;
    }
    for (JointBall& j : f.joints) j.centreCm += by;
}

std::unique_ptr<OffscreenContext> backdropContext() {
    try {
        return std::make_unique<OffscreenContext>(kBackdropWidth, kBackdropHeight);
    } catch (const RenderError& e) {
        MGP_MARK_SKIPPED("no offscreen GL context: " << e.what());
        return nullptr;
    }
}

}  // namespace

TEST_CASE("backdrop layer: a frame started from it is the frame drawn directly, shadows and all") {
    std::unique_ptr<OffscreenContext> ctx = backdropContext();
    if (!ctx) return;
    BackdropWalk w = backdropWalk();
    BackdropTarget target;
    SceneRenderer cached(1), direct(1);
    cached.useBackdropLayer(true);
    const Image first = target.draw(cached, w.scene, w.camera);  // a view seen once: drawn directly
    CHECK(cached.backdropLayerDraws() == 0);
    const Image again = target.draw(cached, w.scene, w.camera);  // seen again: drawn into the layer, copied
    CHECK(cached.backdropLayerDraws() == 1);
    const Image third = target.draw(cached, w.scene, w.camera);  // copied
    CHECK(cached.backdropLayerDraws() == 1);
    CHECK(direct.backdropLayerDraws() == 0);
    const Image straight = target.draw(direct, w.scene, w.camera);
    // Only a solid exactly at the ground's depth could differ (the ground wins such a tie drawn
    // directly, the solid through the copy): none here.
    CHECK(pixelsNotEqual(first, straight) == 0);
    CHECK(pixelsNotEqual(again, straight) == 0);
    CHECK(pixelsNotEqual(third, straight) == 0);
    // The shadows are there to be redrawn: without them the frame differs in many pixels, so a
    // missing shadow patch would fail the comparison above.
    Scene unshadowed = w.scene;
    for (Figure& f : unshadowed.figures) f.castsShadow = false;
    CHECK(pixelsNotEqual(target.draw(direct, unshadowed, w.camera), straight) > 500);
    // A renderer with MSAA draws the ground itself whatever is asked.
    SceneRenderer still(4);
    still.useBackdropLayer(true);
    if (still.msaaSamples() > 1) {
        still.draw(w.scene, w.camera, kBackdropWidth, kBackdropHeight, 0);
        CHECK(still.backdropLayerDraws() == 0);
    }
}

TEST_CASE("backdrop layer: drawn again when the view or the ground changes, not when the figure moves") {
    std::unique_ptr<OffscreenContext> ctx = backdropContext();
    if (!ctx) return;
    BackdropWalk w = backdropWalk();
    BackdropTarget target;
    SceneRenderer cached(1), direct(1);
    cached.useBackdropLayer(true);
    // Shows `scene` twice (the backdrop is kept from a view's second frame); returns the second.
    const auto show = [&](const Scene& scene) {
        target.draw(cached, scene, w.camera);
        return target.draw(cached, scene, w.camera);
    };
    show(w.scene);
    REQUIRE(cached.backdropLayerDraws() == 1);
    // A drag moves the figure and its shadows, over the same ground.
    shiftFigure(w.scene.figures.front(), glm::vec3(20.0f, 15.0f, -10.0f));
    const Image moved = target.draw(cached, w.scene, w.camera);
    CHECK(cached.backdropLayerDraws() == 1);
    CHECK(pixelsNotEqual(moved, target.draw(direct, w.scene, w.camera)) == 0);
    // The camera turns, the ground's centre moves, the style changes: each draws it again.
    w.camera.orbit(5.0f, 0.0f);
    const Image turned = show(w.scene);
    CHECK(cached.backdropLayerDraws() == 2);
    CHECK(pixelsNotEqual(turned, target.draw(direct, w.scene, w.camera)) == 0);
    w.scene.groundCentreCm.x += 150.0f;
    show(w.scene);
    CHECK(cached.backdropLayerDraws() == 3);
    cached.style().ground = glm::vec3(0.5f, 0.4f, 0.3f);
    direct.style().ground = cached.style().ground;
    const Image restyled = show(w.scene);
    CHECK(cached.backdropLayerDraws() == 4);
    CHECK(pixelsNotEqual(restyled, target.draw(direct, w.scene, w.camera)) == 0);
    // A view that changes on every frame (playback, an orbit) is drawn directly each time.
    for (int k = 0; k < 3; ++k) {
        w.camera.orbit(2.0f, 0.0f);
        const Image orbiting = target.draw(cached, w.scene, w.camera);
        CHECK(pixelsNotEqual(orbiting, target.draw(direct, w.scene, w.camera)) == 0);
    }
    CHECK(cached.backdropLayerDraws() == 4);
    // Without a ground there is no backdrop to start from: the frame is cleared and drawn as before.
    w.scene.showGround = false;
    const Image bare = show(w.scene);
    CHECK(cached.backdropLayerDraws() == 4);
    CHECK(pixelsNotEqual(bare, target.draw(direct, w.scene, w.camera)) == 0);
}

TEST_CASE("the drawn floor of a BVH with a rest frame is the capture's, not the T-pose's") {
    const Clip clip = loadClip(test::kMocap + "/bvh/49_04.bvh");  // frame 1: a T-pose 9 cm below
    REQUIRE(clip.restFrame);
    Clip captured = clip;  // the same frames without the rest frame
    captured.frames.erase(captured.frames.begin());
    captured.restFrame = false;
    const float withRest = clipGroundHeight(clip), without = clipGroundHeight(captured);
    Clip restOnly = clip;
    restOnly.frames.resize(1);
    restOnly.restFrame = false;
    MESSAGE("floor " << withRest << " cm; the rest frame alone would put it at " << clipGroundHeight(restOnly)
                     << " cm");
    CHECK(withRest == without);
    CHECK(clipGroundHeight(restOnly) < without - 5.0f);
}
