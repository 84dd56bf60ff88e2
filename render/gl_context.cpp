#include "render/gl_context.h"

#include "util/address_sanitizer.h"

#if MGP_ADDRESS_SANITIZER
#include <dlfcn.h>
#include <link.h>
#endif

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <sstream>

namespace mgp::render {

namespace {

std::string eglErrorText(const char* step) {
    std::ostringstream s;
    s << "offscreen GL context: " << step << " failed (EGL error 0x" << std::hex << eglGetError()
      << "); expected Mesa's EGL with the surfaceless platform (libegl-mesa0, libgl1-mesa-dri)";
    return s.str();
}

const char* glString(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

}  // namespace

bool GlInfo::isLlvmpipe() const { return renderer.find("llvmpipe") != std::string::npos; }

GlInfo currentGlInfo() { return {glString(GL_VENDOR), glString(GL_RENDERER), glString(GL_VERSION)}; }

struct OffscreenContext::Egl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLConfig config = nullptr;
    EGLContext context = EGL_NO_CONTEXT;
    EGLSurface surface = EGL_NO_SURFACE;
};

#if MGP_ADDRESS_SANITIZER
namespace {
// LeakSanitizer checks for leaks after Mesa has unloaded its driver at exit, so the driver's
// deliberate at-exit allocations show up as "<unknown module>" and no suppression can name them.
// In sanitizer builds, pin every loaded Mesa/LLVM library (RTLD_NODELETE) so their stacks keep
// their names and tests/sanitizer/lsan_gl.supp applies. Never compiled into normal builds.
int pinDriver(dl_phdr_info* info, std::size_t, void*) {
    const std::string path = info->dlpi_name ? info->dlpi_name : "";
    if (path.find("/dri/") != std::string::npos || path.find("libgallium") != std::string::npos ||
        path.find("libLLVM") != std::string::npos || path.find("libEGL_mesa") != std::string::npos ||
        path.find("libglapi") != std::string::npos)
        dlopen(path.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
    return 0;
}
}  // namespace
#endif

OffscreenContext::OffscreenContext(int width, int height) : egl_(std::make_unique<Egl>()) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
        throw RenderError("offscreen GL context: expected a size in 1..16384, found " + std::to_string(width) + "x" +
                          std::to_string(height));
    Egl& e = *egl_;
    e.display = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (e.display == EGL_NO_DISPLAY) throw RenderError(eglErrorText("eglGetPlatformDisplay(surfaceless)"));
    EGLint major = 0, minor = 0;
    if (!eglInitialize(e.display, &major, &minor)) throw RenderError(eglErrorText("eglInitialize"));
    if (!eglBindAPI(EGL_OPENGL_API)) {
        eglTerminate(e.display);
        throw RenderError(eglErrorText("eglBindAPI(EGL_OPENGL_API)"));
    }
    // Single-sampled pbuffer: antialiasing is the renderer's own MSAA framebuffer, resolved into
    // this surface, so the output does not depend on what the EGL config happens to offer.
    const EGLint configAttribs[] = {EGL_SURFACE_TYPE,
                                    EGL_PBUFFER_BIT,
                                    EGL_RENDERABLE_TYPE,
                                    EGL_OPENGL_BIT,
                                    EGL_RED_SIZE,
                                    8,
                                    EGL_GREEN_SIZE,
                                    8,
                                    EGL_BLUE_SIZE,
                                    8,
                                    EGL_ALPHA_SIZE,
                                    8,
                                    EGL_DEPTH_SIZE,
                                    24,
                                    EGL_SAMPLES,
                                    0,
                                    EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(e.display, configAttribs, &e.config, 1, &count) || count < 1) {
        eglTerminate(e.display);
        throw RenderError(eglErrorText("eglChooseConfig(RGBA8, depth 24, pbuffer)"));
    }
    const EGLint contextAttribs[] = {
        EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    e.context = eglCreateContext(e.display, e.config, EGL_NO_CONTEXT, contextAttribs);
    if (e.context == EGL_NO_CONTEXT) {
        eglTerminate(e.display);
        throw RenderError(eglErrorText("eglCreateContext(OpenGL 3.3 core)"));
    }
#if MGP_ADDRESS_SANITIZER
    dl_iterate_phdr(pinDriver, nullptr);
#endif
    try {
        resize(width, height);
    } catch (...) {
        eglDestroyContext(e.display, e.context);
        eglTerminate(e.display);
        throw;
    }
}

OffscreenContext::~OffscreenContext() {
    Egl& e = *egl_;
    eglMakeCurrent(e.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (e.surface != EGL_NO_SURFACE) eglDestroySurface(e.display, e.surface);
    eglDestroyContext(e.display, e.context);
    eglTerminate(e.display);
}

void OffscreenContext::resize(int width, int height) {
    Egl& e = *egl_;
    if (e.surface != EGL_NO_SURFACE && width == width_ && height == height_) return;
    const EGLint attribs[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
    EGLSurface surface = eglCreatePbufferSurface(e.display, e.config, attribs);
    if (surface == EGL_NO_SURFACE) throw RenderError(eglErrorText("eglCreatePbufferSurface"));
    if (!eglMakeCurrent(e.display, surface, surface, e.context)) {
        eglDestroySurface(e.display, surface);
        throw RenderError(eglErrorText("eglMakeCurrent"));
    }
    if (e.surface != EGL_NO_SURFACE) eglDestroySurface(e.display, e.surface);
    e.surface = surface;
    width_ = width;
    height_ = height;
}

void OffscreenContext::makeCurrent() {
    if (!eglMakeCurrent(egl_->display, egl_->surface, egl_->surface, egl_->context))
        throw RenderError(eglErrorText("eglMakeCurrent"));
}

void OffscreenContext::present() { glFinish(); }

}  // namespace mgp::render
