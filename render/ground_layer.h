#pragma once
// A cached picture of the scene's still backdrop: the background gradient and the ground grid
// without contact shadows, colour and depth, at the frame's size. While the camera holds still
// (a handle drag, a key drag, a rotation) every frame starts from a copy of it instead of
// shading the ground again; only the square the contact shadows cover is shaded anew, and the
// solids are depth-tested against the copied ground as they would be against the drawn one
// (docs/architecture.md §3.7). On llvmpipe a same-size copy between framebuffers of one format
// is a memory copy, while the ground's grid shader is the frame's most expensive pass.
//
// The layer's framebuffer is RGBA8 with DEPTH24_STENCIL8: the frame's target must have exactly
// these formats (the editor viewport's framebuffer does), or the copy is refused by OpenGL.
#include <vector>

namespace mgp::render {

class GroundLayer {
public:
    GroundLayer();  // needs a current OpenGL 3.3 core context
    ~GroundLayer();
    GroundLayer(const GroundLayer&) = delete;
    GroundLayer& operator=(const GroundLayer&) = delete;

    // Whether the picture held was drawn from exactly this key (view, size, ground and style as
    // bytes): then copyInto() alone starts the frame.
    bool holds(const std::vector<unsigned char>& key) const { return valid_ && key == key_; }
    // Binds the layer's framebuffer at width×height, colour and depth cleared as a frame's are;
    // draw the backdrop into it, then call endDraw.
    void beginDraw(int width, int height, float clearR, float clearG, float clearB);
    void endDraw(std::vector<unsigned char> key);
    // Copies colour, depth and stencil into `targetFramebuffer` (same size) and binds it.
    void copyInto(unsigned targetFramebuffer) const;
    // How many times the picture was drawn (tests count cache misses).
    long draws() const { return draws_; }

private:
    unsigned fbo_ = 0, colour_ = 0, depth_ = 0;
    int width_ = 0, height_ = 0;
    bool valid_ = false;
    std::vector<unsigned char> key_;
    long draws_ = 0;
};

}  // namespace mgp::render
