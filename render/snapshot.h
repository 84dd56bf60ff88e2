#pragma once
// One call from a scene to pixels: draw into framebuffer 0 of a surface and read it back.
// The CLI, the golden tests and the bench all use this, so goldens are made on the test path.
#include "render/camera.h"
#include "render/gl_context.h"
#include "render/png_capture.h"
#include "render/scene.h"
#include "render/skeleton_renderer.h"

namespace mgp::render {

// Draws `scene` over the whole surface (its current size) and returns the picture (top row
// first). The surface's context must be current.
Image snapshot(GlSurface& surface, SceneRenderer& renderer, const Scene& scene, const OrbitCamera& camera);

// The camera of a preset framing the scene's first figure (forward from that figure's hips).
OrbitCamera framedPresetCamera(CameraPreset preset, const Scene& scene, const glm::vec3& forward, int width,
                               int height);

}  // namespace mgp::render
