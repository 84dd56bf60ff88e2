#pragma once
// Draws a Scene with OpenGL 3.3 core: background gradient, ground grid (1 m squares, 10 cm
// minor lines) with soft contact shadows, lit solid bones and joints (left grey, right warm,
// spine neutral), ghosts, paths, targets, pins, effector handles and a caption.
//
// The frame is drawn into the renderer's own multisampled framebuffer (4× MSAA by default) and
// resolved into `targetFramebuffer` (0 = the window or the offscreen pbuffer), so the offscreen
// context and the GLFW window run exactly the same code. Output is deterministic: nothing depends
// on time, and the only state is the scene and the camera.
#include <memory>

#include "render/camera.h"
#include "render/mesh.h"
#include "render/scene.h"
#include "render/shader_program.h"

namespace mgp::render {

struct RenderStyle {
    glm::vec3 backgroundTop{0.17f, 0.19f, 0.23f};
    glm::vec3 backgroundHorizon{0.42f, 0.45f, 0.49f};
    glm::vec3 ground{0.60f, 0.61f, 0.62f};
    glm::vec3 gridMinor{0.53f, 0.54f, 0.55f};
    glm::vec3 gridMajor{0.36f, 0.37f, 0.39f};
    glm::vec3 centreBone{0.90f, 0.87f, 0.80f};
    glm::vec3 leftBone{0.58f, 0.60f, 0.63f};   // the paper's grey left side
    glm::vec3 rightBone{0.96f, 0.52f, 0.18f};  // warm orange right side
    glm::vec3 handleIdle{0.20f, 0.80f, 0.85f};
    glm::vec3 handleHover{1.00f, 0.88f, 0.25f};
    glm::vec3 handleSelected{1.00f, 0.30f, 0.22f};
    glm::vec3 targetReached{0.30f, 0.85f, 0.35f};
    glm::vec3 targetMissed{0.95f, 0.20f, 0.45f};
    glm::vec3 pin{0.62f, 0.35f, 0.90f};
    float groundHalfSizeCm = 1000.0f;  // the grid fades out towards this radius
};

class SceneRenderer {
public:
    // Needs a current 3.3 core context; compiles the shaders and builds the meshes.
    // msaaSamples 4 (the default, used for PNGs and goldens) or 1 (no antialiasing: draws straight
    // into the target, cheaper on llvmpipe). Asking for more than the driver offers throws.
    explicit SceneRenderer(int msaaSamples = 4);
    int msaaSamples() const;
    ~SceneRenderer();
    SceneRenderer(const SceneRenderer&) = delete;
    SceneRenderer& operator=(const SceneRenderer&) = delete;

    RenderStyle& style() { return style_; }

    // Draws the scene over the whole width×height viewport of `targetFramebuffer`.
    void draw(const Scene& scene, const OrbitCamera& camera, int width, int height, unsigned targetFramebuffer = 0);
    // How many times the still overlays' cached layer was drawn (without MSAA; tests count misses).
    long overlayLayerDraws() const;
    // Without MSAA: start each frame from a cached backdrop (render/ground_layer.h) instead of
    // shading the ground again while the view holds still (from its second frame with the same
    // view, ground and style on; a frame with a view seen once is drawn directly). The target must be
    // RGBA8 with DEPTH24_STENCIL8, as the editor viewport's is. Off by default; a no-op with MSAA.
    void useBackdropLayer(bool on);
    long backdropLayerDraws() const;  // how many times the backdrop was drawn (tests count misses)

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    RenderStyle style_;
};

}  // namespace mgp::render
