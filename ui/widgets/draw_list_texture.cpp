#include "ui/widgets/draw_list_texture.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace mgp::ui {

DrawListTexture::~DrawListTexture() {
    if (framebuffer_) glDeleteFramebuffers(1, &framebuffer_);
    if (texture_) glDeleteTextures(1, &texture_);
}

void DrawListTexture::render(ImVec2 origin, ImVec2 size, const std::function<void(ImDrawList&)>& fill) {
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    const int w = std::max(1, static_cast<int>(std::lround(size.x * scale.x)));
    const int h = std::max(1, static_cast<int>(std::lround(size.y * scale.y)));
    GLint previous = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous);
    if (!framebuffer_) {
        glGenFramebuffers(1, &framebuffer_);
        glGenTextures(1, &texture_);
    }
    if (w != width_ || h != height_) {
        glBindTexture(GL_TEXTURE_2D, texture_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
        width_ = w;
        height_ = h;
    }

    // One draw list, set up as ImGui sets up a window's: the frame's draw flags, the font atlas
    // (its white texel is what shapes are filled with), clipped to the texture.
    ImDrawList list(ImGui::GetDrawListSharedData());
    list._ResetForNewFrame();
    list.PushTextureID(ImGui::GetIO().Fonts->TexID);
    list.PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y));
    fill(list);
    list._PopUnusedDrawCmd();
    ImDrawList* lists[] = {&list};
    ImDrawData data;
    data.Valid = true;
    data.CmdLists = lists;
    data.CmdListsCount = 1;
    data.TotalVtxCount = list.VtxBuffer.Size;
    data.TotalIdxCount = list.IdxBuffer.Size;
    data.DisplayPos = origin;
    data.DisplaySize = size;
    data.FramebufferScale = scale;

    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(&data);  // saves and restores the GL state it changes
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous));
}

void DrawListTexture::draw(ImDrawList& dl, ImVec2 p0, ImVec2 p1) const {
    if (empty()) return;
    // GL's row 0 is the bottom of the picture: flip v.
    dl.AddImage(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(texture_)), p0, p1, ImVec2(0, 1),
                ImVec2(1, 0));
}

}  // namespace mgp::ui
