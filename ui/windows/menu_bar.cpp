#include "ui/windows/menu_bar.h"

#include <imgui.h>

#include <filesystem>

#include "session/recent_files.h"
#include "ui/actions/editor_actions.h"
#include "ui/actions/editor_commands.h"
#include "ui/shell/editor_state.h"
#include "ui/widgets/widgets.h"
#include "ui/windows/joint_rotation_window.h"

namespace mgp::ui {

namespace {
// Esc closes an open menu (and the menus above it).
bool beginMenu(const char* label, bool escape, bool enabled = true) {
    if (!ImGui::BeginMenu(label, enabled)) return false;
    if (escape) ImGui::CloseCurrentPopup();
    return true;
}

void fileMenu(EditorCommands& app, const ActionTable& t, bool escape) {
    t.menuItem(app, "open", "Open...");
    const RecentFiles* recent = app.recentFiles();
    if (beginMenu("Open recent", escape, recent && !recent->entries().empty())) {
        const std::vector<RecentFile> entries = recent->entries();  // a copy: opening reorders the list
        for (const RecentFile& r : entries) {
            const std::string label =
                std::filesystem::path(r.path).filename().string() + "  (" + recentKindName(r.kind) + ")";
            if (ImGui::MenuItem(label.c_str())) app.openRecent(r.path);
            if (ImGui::IsItemHovered()) tooltip("%s", r.path.c_str());
        }
        ImGui::EndMenu();
    }
    t.menuItem(app, "save-session", "Save session");
    t.menuItem(app, "save-session-as", "Save session as...");
    ImGui::Separator();
    t.menuItem(app, "open-model", "Open model...");
    t.menuItem(app, "save-model", "Save model...");
    ImGui::Separator();
    t.menuItem(app, "export-bvh", "Export motion as BVH...");
    t.menuItem(app, "export-gltf", "Export motion as glTF...");
    t.menuItem(app, "export-fbx", "Export motion as FBX (Blender)...");
    t.menuItem(app, "export-png", "Export viewport as PNG...");
    ImGui::Separator();
    t.menuItem(app, "demo-clip", "Synthetic demo clip");
    ImGui::Separator();
    t.menuItem(app, "quit", "Quit");
}

void editMenu(EditorCommands& app, const ActionTable& t, bool escape) {
    const EditorDocument& doc = app.state().doc;
    t.menuItem(app, "undo", doc.canUndo() ? "Undo " + doc.undoLabel() : "Undo");
    t.menuItem(app, "redo", doc.canRedo() ? "Redo " + doc.redoLabel() : "Redo");
    ImGui::Separator();
    t.menuItem(app, "revert-frame", "Revert frame to capture");
    t.menuItem(app, "copy-pose", "Copy pose");
    t.menuItem(app, "paste-pose", "Paste pose");
    t.menuItem(app, "mirror-pose", "Mirror pose");
    t.menuItem(app, "rotate-joint", "Rotate joint...");
    const bool follow = app.jointWindow().followPrior();
    t.menuItem(app, "follow-prior", "Rotate joint follows learned prior", {follow ? "off" : "on"}, follow,
               doc.hasModel());
    if (beginMenu("Pins", escape)) {
        for (int i = 0; i < kEffectorCount; ++i) {
            const auto e = static_cast<Effector>(i);
            t.menuItem(app, "pin", effectorName(e), {effectorName(e)}, doc.pinned(e), doc.hasEffector(e));
        }
        ImGui::EndMenu();
    }
    if (beginMenu("Held", escape)) {  // what earlier edits placed on this frame (edit/held_effectors.h)
        for (int i = 0; i < kEffectorCount; ++i) {
            const auto e = static_cast<Effector>(i);
            t.menuItem(app, "release", std::string("Release ") + effectorName(e), {effectorName(e)}, false,
                       doc.held(e));
        }
        ImGui::Separator();
        t.menuItem(app, "release-all", "Release all held (whole clip)");
        ImGui::EndMenu();
    }
    ImGui::Separator();
    const Effector pathEffector = app.state().selected.value_or(Effector::kRFoot);
    t.menuItem(app, "path", std::string("Edit path of ") + effectorName(pathEffector), {effectorName(pathEffector)},
               false, doc.hasEffector(pathEffector));
    t.menuItem(app, "regenerate", "Regenerate path span", {}, false, doc.hasModel());
    t.menuItem(app, "cancel-regenerate", "Cancel regeneration");
    t.menuItem(app, "end-path", "Stop editing the path");
    ImGui::Separator();
    const bool isKey = doc.keys().count(doc.frame()) > 0;
    t.menuItem(app, "key", "Key on this frame", {}, isKey);
    t.menuItem(app, "fill-between-keys", "Fill between keys");
}

void viewMenu(EditorCommands& app, const ActionTable& t, bool escape, bool& showMessages) {
    EditorState& s = app.state();
    t.menuItem(app, "frame-camera", "Frame character");
    ImGui::MenuItem("Messages", nullptr, &showMessages);
    t.menuItem(app, "reset-layout", "Reset layout");
    ImGui::MenuItem("Follow character", nullptr, &s.followCharacter);
    ImGui::MenuItem("Pose range tint", nullptr, &s.showRangeTint, s.doc.hasModel());
    ImGui::MenuItem("Balance (centre of mass, support)", nullptr, &s.showBalance, s.doc.hasClip());
    ImGui::MenuItem("Interpolation between keys (ghost)", nullptr, &s.showInterpolationGhost, s.doc.hasClip());
    if (beginMenu("Onion skins", escape)) {
        ImGui::MenuItem("Show", nullptr, &s.showOnionSkin, s.doc.hasClip());
        // AlwaysClamp: a value typed with Ctrl+click stays in range too.
        ImGui::SliderInt("Before", &s.onionSkin.before, 0, render::kMaxOnionGhosts, "%d", ImGuiSliderFlags_AlwaysClamp);
        ImGui::SliderInt("After", &s.onionSkin.after, 0, render::kMaxOnionGhosts, "%d", ImGuiSliderFlags_AlwaysClamp);
        ImGui::SliderInt("Spacing (frames)", &s.onionSkin.spacing, 1, render::kMaxOnionSpacing, "%d",
                         ImGuiSliderFlags_AlwaysClamp);
        ImGui::EndMenu();
    }
    if (beginMenu("Motion trails", escape)) {
        static const char* const kLabels[render::kTrailPartCount] = {"Left hand",  "Right hand", "Left foot",
                                                                     "Right foot", "Head",       "Root"};
        for (int i = 0; i < render::kTrailPartCount; ++i)
            ImGui::MenuItem(
                kLabels[i], nullptr, &s.trails[i],
                s.doc.hasClip() && render::hasTrailPart(s.doc.clip().skeleton, static_cast<render::TrailPart>(i)));
        ImGui::Separator();
        ImGui::SliderInt("Frames each side", &s.trailHalfSpan, 1, EditorState::kMaxTrailHalfSpan, "%d",
                         ImGuiSliderFlags_AlwaysClamp);
        ImGui::MenuItem("Captured motion beneath", nullptr, &s.showCapturedTrails);
        ImGui::EndMenu();
    }
    if (beginMenu("Compare ghost", escape)) {
        const CompareMode mode = s.doc.compareMode();
        t.menuItem(app, "compare", "Off", {compareModeName(CompareMode::kNone)}, mode == CompareMode::kNone);
        t.menuItem(app, "compare", "Plain IK", {compareModeName(CompareMode::kPlainIk)}, mode == CompareMode::kPlainIk);
        t.menuItem(app, "compare", "Second model", {compareModeName(CompareMode::kSecondModel)},
                   mode == CompareMode::kSecondModel);
        ImGui::EndMenu();
    }
}

void playbackMenu(EditorCommands& app, const ActionTable& t) {
    t.menuItem(app, "play-pause", app.state().playing ? "Pause" : "Play");
    t.menuItem(app, "next-frame", "Next frame");
    t.menuItem(app, "previous-frame", "Previous frame");
    t.menuItem(app, "forward-10", "Forward 10 frames");
    t.menuItem(app, "back-10", "Back 10 frames");
    t.menuItem(app, "first-frame", "First frame");
    t.menuItem(app, "last-frame", "Last frame");
}
}  // namespace

void drawMenuBar(EditorCommands& app, bool& showMessages, const char* latentBusyText) {
    if (!ImGui::BeginMainMenuBar()) return;
    const ActionTable& t = ActionTable::editor();
    const bool escape = ImGui::IsKeyPressed(key::kEscape, false);
    if (beginMenu("File", escape)) {
        fileMenu(app, t, escape);
        ImGui::EndMenu();
    }
    if (beginMenu("Edit", escape)) {
        editMenu(app, t, escape);
        ImGui::EndMenu();
    }
    if (beginMenu("Model", escape)) {
        t.menuItem(app, "train", "Train");
        t.menuItem(app, "train-clips", "Train on clips...");
        t.menuItem(app, "cancel-train", "Cancel training");
        const bool adaptive = app.state().doc.models().adaptiveEnabled();
        t.menuItem(app, "adaptive", "Adaptive active set", {adaptive ? "off" : "on"}, adaptive);
        ImGui::EndMenu();
    }
    if (beginMenu("View", escape)) {
        viewMenu(app, t, escape, showMessages);
        ImGui::EndMenu();
    }
    if (beginMenu("Playback", escape)) {
        playbackMenu(app, t);
        ImGui::EndMenu();
    }
    if (beginMenu("Help", escape)) {
        t.menuItem(app, "help", "Controls");
        ImGui::EndMenu();
    }
    // Right side of the menu bar: background work.
    const EditorState& s = app.state();
    std::string bg;
    if (s.training.running()) {
        const TrainingProgress p = s.training.progress();
        bg = "training " + std::to_string(p.iteration) + "/" + std::to_string(p.total);
    } else if (s.doc.filling()) {
        bg = "filling between keys...";
    } else if (s.doc.models().pending() > 0) {
        bg = "adaptive update...";
    } else if (latentBusyText && *latentBusyText) {
        bg = latentBusyText;
    }
    if (!bg.empty()) {
        ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(bg.c_str()).x - 16);
        ImGui::TextColored(ImVec4(0.45f, 0.8f, 1.0f, 1), "%s", bg.c_str());
    }
    ImGui::EndMainMenuBar();
}

}  // namespace mgp::ui
