#pragma once
// The editor's Dear ImGui context: no ini or log file, the GLFW key codes the InputState uses
// (input_state.h), DejaVu Sans at 15 px × scale (the built-in bitmap font, scaled, when
// `builtinFont` or when DejaVu is missing: the goldens use it), and the editor's dark style.
#include <string>

namespace mgp::ui {

void createImGuiContext(float scale, bool builtinFont);
// Where the editor's font is looked for (fonts-dejavu-core).
inline constexpr const char* kEditorFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// "" when libGL.so.1 opens, else one line saying it is missing and why: Dear ImGui's OpenGL renderer
// loads it by name, which a machine with EGL but no GLX library lacks. Asked before the renderer
// starts, so that its own message and assertions never come first.
std::string imguiOpenGlLibraryProblem();

}  // namespace mgp::ui
