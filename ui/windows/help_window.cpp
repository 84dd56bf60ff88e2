#include "ui/windows/help_window.h"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "ui/actions/editor_actions.h"

namespace mgp::ui {

namespace {
// The summary's first clause ("open an ASF/AMC or BVH clip"): the rest is for docs/guide.md.
std::string firstClause(const std::string& summary) {
    return summary.substr(0, std::min(summary.find("; "), summary.find(" (")));
}
}  // namespace

void drawHelpWindow(bool& open, float x, float y, double autosaveSeconds) {
    if (!open) return;
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::Begin("Controls", &open, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings);
    ImGui::Text("Viewport");
    ImGui::BulletText("Hover a hand/foot/head handle, left-drag: pose with learned IK (camera-facing plane)");
    ImGui::BulletText("Shift while dragging a handle or a path key: move on the horizontal plane");
    ImGui::BulletText("X, Y or Z while dragging a handle: along that world axis (again: free); the offset shows in cm");
    ImGui::BulletText("Right-click or P on a handle: pin / unpin (keeps a foot planted)");
    ImGui::BulletText("Left-drag empty space: orbit   Middle-drag or Shift+left: pan   Wheel: zoom   F: frame");
    ImGui::BulletText("Esc during a drag: cancel");
    ImGui::Text("Path editing (Edit menu or the Path tab)");
    ImGui::BulletText("Drag a key point in the viewport, or type its offset in the Path tab");
    ImGui::BulletText("Drag the edges between the viewport, the right column and the timeline to resize them");
    ImGui::Text("Timeline and latent map");
    ImGui::BulletText("Click or drag the track: scrub   Hover the latent map: nearest training frame");
    ImGui::BulletText("Click a latent point: go to its frame   Drag the red point: pose from the model mean f(x)");
    ImGui::Text("Keys");
    // Two shortcuts per row, so the window fits a 1280×800 editor.
    if (ImGui::BeginTable("##keys", 4, ImGuiTableFlags_SizingFixedFit)) {
        int column = 0;
        for (const EditorAction& a : ActionTable::editor().actions()) {
            if (a.shortcut.empty()) continue;
            if (column++ % 2 == 0) ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(a.shortcut.c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(firstClause(a.summary).c_str());
        }
        ImGui::EndTable();
    }
    ImGui::TextDisabled("Unsaved work is autosaved every %.0f s and offered back after a crash.", autosaveSeconds);
    ImGui::End();
}

}  // namespace mgp::ui
