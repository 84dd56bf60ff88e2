#include "ui/actions/shortcuts.h"

#include <imgui.h>

namespace mgp::ui {

bool chordPressed(int key, unsigned mods, bool repeat) {
    const ImGuiIO& io = ImGui::GetIO();
    const unsigned held = (io.KeyCtrl ? kCtrl : 0u) | (io.KeyShift ? kShift : 0u) | (io.KeyAlt ? kAlt : 0u);
    return held == mods && !io.KeySuper && ImGui::IsKeyPressed(key, repeat);
}

}  // namespace mgp::ui
