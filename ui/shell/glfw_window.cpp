#include "ui/shell/glfw_window.h"

#include <GLFW/glfw3.h>

#include <utility>

namespace mgp::ui {

namespace {
GlfwWindow& windowOf(GLFWwindow* w) { return *static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w)); }
InputState& inputOf(GLFWwindow* w) { return windowOf(w).input(); }
}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title) : title_(title) {
    if (!glfwInit())
        throw render::RenderError("GLFW could not start (no display? run under xvfb-run or use --offscreen)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        glfwTerminate();
        throw render::RenderError("GLFW could not create a " + std::to_string(width) + "x" + std::to_string(height) +
                                  " OpenGL 3.3 core window");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    glfwSetWindowUserPointer(window_, this);
    glfwSetWindowRefreshCallback(window_, [](GLFWwindow* w) { windowOf(w).damaged_ = true; });
    glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
        inputOf(w).mouseX = float(x);
        inputOf(w).mouseY = float(y);
    });
    glfwSetCursorEnterCallback(window_, [](GLFWwindow* w, int entered) {
        if (!entered) inputOf(w).mouseX = inputOf(w).mouseY = -1.0f;
    });
    glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
        const int b = button == GLFW_MOUSE_BUTTON_LEFT     ? 0
                      : button == GLFW_MOUSE_BUTTON_RIGHT  ? 1
                      : button == GLFW_MOUSE_BUTTON_MIDDLE ? 2
                                                           : -1;
        inputOf(w).setButton(b, action == GLFW_PRESS);
    });
    glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) { inputOf(w).wheel += float(dy); });
    glfwSetKeyCallback(window_, [](GLFWwindow* w, int k, int, int action, int) {
        if (action != GLFW_REPEAT) inputOf(w).setKey(k, action == GLFW_PRESS);
    });
    glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned c) { inputOf(w).chars.push_back(char32_t(c)); });
    glfwSetWindowFocusCallback(window_, [](GLFWwindow* w, int focused) {
        if (!focused) {
            for (int k = 0; k < key::kCount; ++k) inputOf(w).setKey(k, false);
            for (int b = 0; b < 3; ++b) inputOf(w).setButton(b, false);
        }
    });
}

GlfwWindow::~GlfwWindow() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

void GlfwWindow::makeCurrent() { glfwMakeContextCurrent(window_); }

int GlfwWindow::width() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return w;
}

int GlfwWindow::height() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return h;
}

void GlfwWindow::present() { glfwSwapBuffers(window_); }

bool GlfwWindow::takeDamage() { return std::exchange(damaged_, false); }

void GlfwWindow::pollEvents() { glfwPollEvents(); }
void GlfwWindow::waitEvents(double timeoutSeconds) { glfwWaitEventsTimeout(timeoutSeconds); }
bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_) != 0; }

void GlfwWindow::cancelClose() { glfwSetWindowShouldClose(window_, GLFW_FALSE); }

void GlfwWindow::setTitle(const std::string& title) {
    if (title == title_) return;
    title_ = title;
    glfwSetWindowTitle(window_, title.c_str());
}

float GlfwWindow::contentScale() const {
    float x = 1.0f, y = 1.0f;
    glfwGetWindowContentScale(window_, &x, &y);
    return x > 0.0f ? x : 1.0f;
}

}  // namespace mgp::ui
