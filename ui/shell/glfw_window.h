#pragma once
// A GLFW window with an OpenGL 3.3 core context (the interactive editor). It implements
// render::GlSurface and collects mouse, wheel, key and character events into an InputState
// (GLFW key codes pass through unchanged). GLFW needs a display (a desktop or xvfb-run); tests
// never create one: they draw offscreen (render/gl_context.h).
#include <string>

#include "render/gl_context.h"
#include "ui/input/input_state.h"

struct GLFWwindow;

namespace mgp::ui {

class GlfwWindow final : public render::GlSurface {
public:
    // Throws render::RenderError when GLFW or the context cannot start (e.g. no DISPLAY).
    GlfwWindow(int width, int height, const std::string& title);
    ~GlfwWindow() override;
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    void makeCurrent() override;
    int width() const override;  // framebuffer pixels
    int height() const override;
    void present() override;  // swap buffers

    void pollEvents();
    void waitEvents(double timeoutSeconds);  // sleeps until input or the timeout
    bool shouldClose() const;
    void cancelClose();  // the app asked about unsaved changes and the user stayed
    void setTitle(const std::string& title);
    // The monitor's content scale (1 on a 96 dpi display, 2 at 200 %), for HiDPI sizes.
    float contentScale() const;
    InputState& input() { return input_; }
    // Whether the window's contents were lost since the last call (exposed, resized): the next
    // frame must be drawn even if it shows what the last one did.
    bool takeDamage();

private:
    GLFWwindow* window_ = nullptr;
    InputState input_;
    bool damaged_ = false;  // the editor's first frame draws anyway
    std::string title_;
};

}  // namespace mgp::ui
