// The cached overlay picture (overlay_layer.h).
#include "render/overlay_layer.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <string>
#include <utility>

#include "render/gl_context.h"

namespace mgp::render {

namespace {

const char* kCompositeVs = R"(#version 330 core
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

// Pixel for pixel (the layer has the frame's size): what the overlays left there, at their depth.
const char* kCompositeFs = R"(#version 330 core
uniform sampler2D uColour;  // premultiplied alpha
uniform sampler2D uDepth;
out vec4 fragColour;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 c = texelFetch(uColour, p, 0);
    if (c.a <= 0.0) discard;
    gl_FragDepth = texelFetch(uDepth, p, 0).r;
    fragColour = c;
}
)";

}  // namespace

OverlayLayer::OverlayLayer() : program_("overlay composite", kCompositeVs, kCompositeFs) {
    glGenFramebuffers(1, &fbo_);
    glGenTextures(1, &colour_);
    glGenTextures(1, &depth_);
    glGenVertexArrays(1, &vao_);
    for (unsigned texture : {colour_, depth_}) {
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    program_.use();
    program_.set("uColour", 0);
    program_.set("uDepth", 1);
}

OverlayLayer::~OverlayLayer() {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteTextures(1, &colour_);
    glDeleteTextures(1, &depth_);
    glDeleteVertexArrays(1, &vao_);
}

void OverlayLayer::ensureSize(int width, int height) {
    if (width == width_ && height == height_) return;
    glBindTexture(GL_TEXTURE_2D, colour_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    // The frame's depth buffers are 24-bit: the same precision, so the layer's depth written
    // back compares with the frame's as the overlays' own fragments would.
    glBindTexture(GL_TEXTURE_2D, depth_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, width, height, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
                 nullptr);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RenderError("renderer: the overlay layer's framebuffer of " + std::to_string(width) + "x" +
                          std::to_string(height) + " is incomplete");
    width_ = width;
    height_ = height;
}

void OverlayLayer::beginDraw(int width, int height) {
    valid_ = false;
    ensureSize(width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void OverlayLayer::endDraw(std::vector<unsigned char> key, const ScreenRect& rect) {
    key_ = std::move(key);
    rect_ = rect;
    valid_ = true;
    ++draws_;
}

void OverlayLayer::composite() {
    if (!valid_ || rect_.empty()) return;
    program_.use();
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, depth_);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, colour_);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect_.x0, rect_.y0, rect_.x1 - rect_.x0, rect_.y1 - rect_.y0);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_SCISSOR_TEST);
}

}  // namespace mgp::render
