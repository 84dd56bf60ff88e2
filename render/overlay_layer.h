#pragma once
// A cached picture of the scene's still overlays: onion skins and trails, which stay put while the
// current frame is posed. It keeps colour (premultiplied alpha) and depth at the frame's size and
// is drawn again only when its content or the view changes; every frame lays it in by depth, so
// the figure still hides what is behind it (docs/architecture.md §3.7). On llvmpipe a drag frame
// then pays for one textured pass over the overlays' screen rectangle instead of their geometry.
#include <vector>

#include "render/shader_program.h"

namespace mgp::render {

// Pixels x0 ≤ x < x1, y0 ≤ y < y1 (GL's window coordinates, origin bottom-left).
struct ScreenRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
};

class OverlayLayer {
public:
    OverlayLayer();  // needs a current OpenGL 3.3 core context
    ~OverlayLayer();
    OverlayLayer(const OverlayLayer&) = delete;
    OverlayLayer& operator=(const OverlayLayer&) = delete;

    // Whether the picture held was drawn from exactly this key (the overlays' content and the view,
    // as bytes): then composite() alone shows them.
    bool holds(const std::vector<unsigned char>& key) const { return valid_ && key == key_; }
    // Binds the layer's own framebuffer at width×height, cleared to transparent on the far plane;
    // draw the overlays into it (blending with premultiplied alpha), then call endDraw.
    void beginDraw(int width, int height);
    // What was drawn came from `key` and covers `rect` (nothing outside it is laid in).
    void endDraw(std::vector<unsigned char> key, const ScreenRect& rect);
    // Lays the picture into the bound framebuffer (same size): each pixel the overlays cover, where
    // it is not behind what is there, blended over it with its depth written. Leaves blending on.
    void composite();
    // How many times the picture was drawn (tests count cache misses).
    long draws() const { return draws_; }

private:
    void ensureSize(int width, int height);
    ShaderProgram program_;
    unsigned fbo_ = 0, colour_ = 0, depth_ = 0, vao_ = 0;
    int width_ = 0, height_ = 0;
    bool valid_ = false;
    std::vector<unsigned char> key_;
    ScreenRect rect_;
    long draws_ = 0;
};

}  // namespace mgp::render
