#pragma once
// The editor's Dear ImGui context: no ini or log file, the GLFW key codes the InputState uses
// (input_state.h), DejaVu Sans at 15 px × scale (the built-in bitmap font, scaled, when
// `builtinFont` or when DejaVu is missing: the goldens use it), and the editor's dark style.
namespace mgp::ui {

void createImGuiContext(float scale, bool builtinFont);

}  // namespace mgp::ui
