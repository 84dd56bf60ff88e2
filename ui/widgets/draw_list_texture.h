#pragma once
// A picture drawn once with ImGui draw commands into a texture, through the same OpenGL3 backend
// that draws the window, and then shown each frame as one textured quad. For parts of a panel
// that change rarely but cost many small anti-aliased triangles every frame (the latent map's
// dots, rings and time path: about 20 000 triangles, several ms per frame on llvmpipe).
#include <imgui.h>

#include <functional>

namespace mgp::ui {

class DrawListTexture {
public:
    DrawListTexture() = default;
    ~DrawListTexture();
    DrawListTexture(const DrawListTexture&) = delete;
    DrawListTexture& operator=(const DrawListTexture&) = delete;

    // Draws `fill` into the texture. `fill` draws in screen coordinates; the texture covers
    // [origin, origin + size) of the screen at the window's framebuffer scale. Call between
    // ImGui::NewFrame and ImGui::Render (it uses the current font atlas and draw settings).
    void render(ImVec2 origin, ImVec2 size, const std::function<void(ImDrawList&)>& fill);
    // Adds the picture to `dl` over [p0, p1) (normally origin and origin + size).
    void draw(ImDrawList& dl, ImVec2 p0, ImVec2 p1) const;
    bool empty() const { return width_ == 0; }

private:
    unsigned framebuffer_ = 0, texture_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace mgp::ui
