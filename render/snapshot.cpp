#include "render/snapshot.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include "render/scene_builder.h"

namespace mgp::render {

Image snapshot(GlSurface& surface, SceneRenderer& renderer, const Scene& scene, const OrbitCamera& camera) {
    renderer.draw(scene, camera, surface.width(), surface.height(), 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glFinish();
    Image img = readFramebuffer(surface.width(), surface.height());
    if (const GLenum err = glGetError(); err != GL_NO_ERROR)
        throw RenderError("snapshot: GL error 0x" + std::to_string(err) + " while drawing");
    return img;
}

OrbitCamera framedPresetCamera(CameraPreset preset, const Scene& scene, const glm::vec3& forward, int width,
                               int height) {
    const Bounds b = sceneBounds(scene);
    return presetCamera(preset, forward, b.centreCm, b.radiusCm,
                        static_cast<float>(width) / static_cast<float>(height));
}

}  // namespace mgp::render
