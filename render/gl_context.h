#pragma once
// GL contexts the renderer draws into. `GlSurface` is the small interface both the offscreen
// EGL context (tests, CLI, bench) and the editor's GLFW window (ui::GlfwWindow, ui/shell/glfw_window.h)
// satisfy, so one drawing path (SceneRenderer::draw into framebuffer 0) serves both.
//
// OffscreenContext, the headless recipe that works with Mesa on these machines: EGL surfaceless platform
// (eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL)),
// eglBindAPI(EGL_OPENGL_API), an OpenGL 3.3 core context and a PBUFFER surface made current.
// No X server or environment variables are needed.
#include <memory>
#include <stdexcept>
#include <string>

namespace mgp::render {

// Thrown when a context cannot be created or GL reports a setup error (never in the frame loop).
struct RenderError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class GlSurface {
public:
    virtual ~GlSurface() = default;
    virtual void makeCurrent() = 0;
    // Size of the default framebuffer (framebuffer 0) in pixels.
    virtual int width() const = 0;
    virtual int height() const = 0;
    // Presents (window) or finishes (offscreen) the frame.
    virtual void present() = 0;
};

// Strings GL reports about the current context.
struct GlInfo {
    std::string vendor, renderer, version;
    bool isLlvmpipe() const;  // the reference software rasteriser the goldens were made with
};
GlInfo currentGlInfo();

class OffscreenContext final : public GlSurface {
public:
    // Creates the EGL display, a 3.3 core context and a width×height RGBA8 + depth24 pbuffer,
    // and makes it current. Throws RenderError saying which step failed.
    OffscreenContext(int width, int height);
    ~OffscreenContext() override;
    OffscreenContext(const OffscreenContext&) = delete;
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    void makeCurrent() override;
    int width() const override { return width_; }
    int height() const override { return height_; }
    void present() override;
    // Replaces the pbuffer with one of the new size (the context and its GL objects survive).
    void resize(int width, int height);

private:
    struct Egl;
    std::unique_ptr<Egl> egl_;
    int width_ = 0, height_ = 0;
};

}  // namespace mgp::render
