#include "ui/shell/imgui_setup.h"

#include <dlfcn.h>
#include <imgui.h>

#include <cmath>
#include <filesystem>

#include "ui/input/input_state.h"

namespace mgp::ui {

namespace {

void applyStyle() {
    ImGui::StyleColorsDark();
    ImGuiStyle& st = ImGui::GetStyle();
    st.WindowRounding = 0.0f;
    st.FrameRounding = 3.0f;
    st.GrabRounding = 3.0f;
    st.WindowBorderSize = 1.0f;
    st.FramePadding = ImVec2(6, 3);
    st.ItemSpacing = ImVec2(7, 5);
    ImVec4* c = st.Colors;
    c[ImGuiCol_WindowBg] = ImVec4(0.16f, 0.165f, 0.18f, 1.0f);
    c[ImGuiCol_TitleBg] = ImVec4(0.12f, 0.125f, 0.14f, 1.0f);
    c[ImGuiCol_TitleBgActive] = ImVec4(0.14f, 0.15f, 0.17f, 1.0f);
    c[ImGuiCol_MenuBarBg] = ImVec4(0.12f, 0.125f, 0.14f, 1.0f);
    c[ImGuiCol_FrameBg] = ImVec4(0.24f, 0.25f, 0.28f, 1.0f);
    c[ImGuiCol_Button] = ImVec4(0.27f, 0.29f, 0.33f, 1.0f);
    c[ImGuiCol_ButtonHovered] = ImVec4(0.35f, 0.40f, 0.48f, 1.0f);
    c[ImGuiCol_ButtonActive] = ImVec4(0.28f, 0.50f, 0.80f, 1.0f);
    c[ImGuiCol_Header] = ImVec4(0.28f, 0.32f, 0.38f, 1.0f);
    c[ImGuiCol_PlotHistogram] = ImVec4(0.28f, 0.58f, 0.92f, 1.0f);
    c[ImGuiCol_Border] = ImVec4(0.08f, 0.08f, 0.09f, 1.0f);
}
}  // namespace

void createImGuiContext(float scale, bool builtinFont) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // a fixed layout; nothing written beside the working directory
    io.LogFilename = nullptr;
    io.BackendPlatformName = "motiongp";
    for (int k = 0; k < ImGuiKey_COUNT; ++k) io.KeyMap[k] = -1;
    io.KeyMap[ImGuiKey_Tab] = key::kTab;
    io.KeyMap[ImGuiKey_LeftArrow] = key::kLeft;
    io.KeyMap[ImGuiKey_RightArrow] = key::kRight;
    io.KeyMap[ImGuiKey_UpArrow] = key::kUp;
    io.KeyMap[ImGuiKey_DownArrow] = key::kDown;
    io.KeyMap[ImGuiKey_PageUp] = key::kPageUp;
    io.KeyMap[ImGuiKey_PageDown] = key::kPageDown;
    io.KeyMap[ImGuiKey_Home] = key::kHome;
    io.KeyMap[ImGuiKey_End] = key::kEnd;
    io.KeyMap[ImGuiKey_Delete] = key::kDelete;
    io.KeyMap[ImGuiKey_Backspace] = key::kBackspace;
    io.KeyMap[ImGuiKey_Space] = key::kSpace;
    io.KeyMap[ImGuiKey_Enter] = key::kEnter;
    io.KeyMap[ImGuiKey_Escape] = key::kEscape;
    io.KeyMap[ImGuiKey_A] = 'A';
    io.KeyMap[ImGuiKey_C] = 'C';
    io.KeyMap[ImGuiKey_V] = 'V';
    io.KeyMap[ImGuiKey_X] = 'X';
    io.KeyMap[ImGuiKey_Y] = 'Y';
    io.KeyMap[ImGuiKey_Z] = 'Z';
    std::error_code ec;
    // Latin-1 plus what messages and panels print: Greek (α β γ η σ), dashes and ellipsis,
    // arrows, and maths (≥ ≤ √ ²); DejaVu Sans has them all.
    static const ImWchar kGlyphs[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x2027, 0x2070,
                                      0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};
    if (!builtinFont && std::filesystem::exists(kEditorFontPath, ec))
        io.Fonts->AddFontFromFileTTF(kEditorFontPath, std::round(15.0f * scale), nullptr, kGlyphs);
    else
        io.FontGlobalScale = scale;  // the built-in bitmap font only comes in one size
    applyStyle();
    ImGui::GetStyle().ScaleAllSizes(scale);
}

std::string imguiOpenGlLibraryProblem() {
    // The same dlopen the loader makes (imgui_impl_opengl3_loader.h), for the system's own reason.
    void* libgl = dlopen("libGL.so.1", RTLD_LAZY | RTLD_LOCAL);
    if (libgl) {
        dlclose(libgl);
        return "";
    }
    const char* why = dlerror();
    return std::string(
               "expected libGL.so.1, the OpenGL library the editor's Dear ImGui renderer loads "
               "(Debian: apt-get install libgl1), found none: ") +
           (why ? why : "dlopen failed");
}

}  // namespace mgp::ui
