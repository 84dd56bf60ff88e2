// ViewportPanel::renderImage: the viewport's 3-D view as a picture (File > Export viewport PNG).
#include <GL/gl.h>
#include <GL/glext.h>

#include "render/gl_context.h"
#include "ui/panels/viewport_panel.h"

namespace mgp::ui {

render::Image ViewportPanel::renderImage(const EditorState& state) {
    if (!fbo_ || width_ <= 0 || height_ <= 0 || !state.doc.hasClip())
        throw render::RenderError("expected a drawn viewport to export, found none yet");
    // The interactive renderer has no MSAA (llvmpipe speed); an export is worth the edges.
    if (!exportRenderer_) exportRenderer_ = std::make_unique<render::SceneRenderer>(4);
    exportRenderer_->draw(buildScene(state), state.camera, width_, height_, fbo_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
    glFinish();
    render::Image image = render::readFramebuffer(width_, height_);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    lastSignature_.clear();  // the viewport texture now holds the export: redraw it next frame
    return image;
}

}  // namespace mgp::ui
