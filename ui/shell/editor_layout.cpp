#include "ui/shell/editor_layout.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>

#include "ui/panels/model_panel.h"
#include "ui/panels/path_panel.h"
#include "ui/widgets/widgets.h"

namespace mgp::ui {

EditorLayout::EditorLayout(float scale, std::string layoutFile) : scale_(scale), layoutFile_(std::move(layoutFile)) {
    if (!layoutFile_.empty()) prefs_ = loadLayoutPrefs(layoutFile_);
}

void EditorLayout::reset() {
    prefs_ = LayoutPrefs{};
    if (!layoutFile_.empty()) saveLayoutPrefs(layoutFile_, prefs_);
}

void EditorLayout::draw(EditorState& state, ViewportPanel& viewport, LatentMapPanel& latent, TimelinePanel& timeline,
                        int w, int h) {
    const float menuH = ImGui::GetFrameHeight();
    // Sizes in pixels at scale 1; a HiDPI monitor's content scale multiplies them (and the fonts).
    const float k = scale_;
    // The timeline: its title, the transport row, a track at least 24 px tall and the status line,
    // in whatever font the editor has (DejaVu Sans is taller than the built-in one).
    const ImGuiStyle& st = ImGui::GetStyle();
    const float timelineNeed = ImGui::GetFrameHeight() + 2.0f * st.WindowPadding.y +
                               ImGui::GetFrameHeightWithSpacing() + 26.0f * k + ImGui::GetTextLineHeightWithSpacing() +
                               st.ItemSpacing.y;
    const float timelineH = std::max(104.0f * k, timelineNeed);
    // The right column: 380 px wide with fixed panel heights from 1280×800 up; in a smaller window
    // narrower (30 % of the width, at least 290 px) with the heights shared out so every panel
    // keeps its main controls in view down to 1024×600.
    const float avail = float(h) - menuH;
    // The readout below them gets the rest: at 1280×800 about 249 px, its whole drag report.
    float rightW = 380.0f * k, modelH = 232.0f * k, latentH = 300.0f * k;
    if (float(w) < 1280.0f * k || avail < modelH + latentH + 249.0f * k) {
        rightW = std::clamp(float(w) * 0.30f, std::min(290.0f * k, float(w) * 0.45f), 380.0f * k);
        modelH = std::clamp(avail * 0.30f, 132.0f * k, 232.0f * k);
        const float readoutH = std::max(avail * 0.29f, 140.0f * k);
        latentH = std::clamp(avail - modelH - readoutH, 120.0f * k, std::min(300.0f * k, rightW));
    }
    // While the Path tab is in front its keys and span report need about 340 px: the latent map gives
    // up to 100 px to them (down to 180 px, a map of about 125 px).
    if (pathTabSelected_ && state.doc.paths().edit()) latentH -= std::clamp(latentH - 180.0f * k, 0.0f, 100.0f * k);
    // The splitters' positions, as the user left them (scale-1 pixels), within sane bounds.
    if (prefs_.rightWidth > 0.0f)
        rightW = std::clamp(prefs_.rightWidth * k, std::min(240.0f * k, float(w) * 0.3f), float(w) * 0.6f);
    float timelineFinal = timelineH;
    if (prefs_.timelineHeight > 0.0f)
        timelineFinal = std::clamp(prefs_.timelineHeight * k, std::min(timelineNeed, float(h) * 0.2f), float(h) * 0.5f);
    panels(state, viewport, latent, timeline, w, h, menuH, rightW, timelineFinal, modelH, latentH);
}

void EditorLayout::panels(EditorState& state, ViewportPanel& viewport, LatentMapPanel& latent, TimelinePanel& timeline,
                          int w, int h, float menuH, float rightW, float timelineH, float modelH, float latentH) {
    const float leftW = float(w) - rightW;
    leftW_ = leftW;
    // The panels tile the window, so they draw no background of their own: EditorApp::frame clears the
    // window with their colour (the style's WindowBg), which a rasteriser on the CPU does far
    // faster than it blends 0.4 Mpx of window rectangles every frame. Without a background ImGui
    // draws no border either: panelBorder() draws it as ImGui would.
    const ImGuiWindowFlags fixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                                   ImGuiWindowFlags_NoBackground;
    auto place = [](float x, float y, float ww, float hh) {
        ImGui::SetNextWindowPos(ImVec2(x, y));
        ImGui::SetNextWindowSize(ImVec2(std::max(ww, 50.0f), std::max(hh, 40.0f)));
    };

    place(0, menuH, leftW, float(h) - menuH - timelineH);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::Begin("Viewport", nullptr,
                 fixed | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoBackground |
                     ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar();
    viewport.draw(state);
    ImGui::End();

    place(0, float(h) - timelineH, leftW, timelineH);
    ImGui::Begin("Timeline", nullptr, fixed | ImGuiWindowFlags_NoScrollbar);
    panelBorder();
    {
        // Track above, status line below.
        const float statusH = ImGui::GetTextLineHeightWithSpacing();
        ImGui::BeginChild("tl", ImVec2(0, -statusH), false, ImGuiWindowFlags_NoScrollbar);
        timeline.draw(state);
        ImGui::EndChild();
        if (const StatusMessage* m = state.messages.current()) statusLine(state, *m);
    }
    ImGui::End();

    place(leftW, menuH, rightW, modelH);
    ImGui::Begin("Model", nullptr, fixed);
    panelBorder();
    drawModelPanel(state);
    ImGui::End();

    place(leftW, menuH + modelH, rightW, latentH);
    ImGui::Begin("Latent map", nullptr, fixed | ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    panelBorder();
    latent.draw(state);
    ImGui::End();

    place(leftW, menuH + modelH + latentH, rightW, float(h) - menuH - modelH - latentH);
    ImGui::Begin("Readout and path", nullptr, fixed | ImGuiWindowFlags_NoTitleBar);
    panelBorder();
    if (ImGui::BeginTabBar("##bottomright")) {
        // The Path tab comes forward while a path is edited.
        const bool pathActive = state.doc.paths().edit().has_value();
        if (ImGui::BeginTabItem("IK readout")) {
            drawIkReadout(state);
            ImGui::EndTabItem();
        }
        pathTabSelected_ = false;
        if (ImGui::BeginTabItem("Path", nullptr, pathActive && !pathTabShown_ ? ImGuiTabItemFlags_SetSelected : 0)) {
            pathTabSelected_ = true;
            drawPathPanel(state);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Model details")) {
            drawModelDetails(state);
            ImGui::EndTabItem();
        }
        pathTabShown_ = pathActive;
        ImGui::EndTabBar();
    }
    ImGui::End();

    // Splitters, on top of the panels' edges: the right column's width and the timeline's height.
    bool released = false;
    const float dx = splitter("##split-right", leftW - 3.0f, menuH, 6.0f, float(h) - menuH, true, released);
    if (dx != 0.0f) prefs_.rightWidth = std::max(1.0f, (rightW - dx) / scale_);
    bool releasedTimeline = false;
    const float dy =
        splitter("##split-timeline", 0.0f, float(h) - timelineH - 3.0f, leftW - 3.0f, 6.0f, false, releasedTimeline);
    if (dy != 0.0f) prefs_.timelineHeight = std::max(1.0f, (timelineH - dy) / scale_);
    if ((released || releasedTimeline) && !layoutFile_.empty()) {
        const std::string err = saveLayoutPrefs(layoutFile_, prefs_);
        if (!err.empty()) state.setStatus("could not remember the layout: " + err, true);
    }
}

void EditorLayout::panelBorder() {
    // ImGui's own outer border (RenderWindowOuterBorders): the window's rectangle, with the border
    // size and rounding the window took at Begin().
    ImGuiWindow* window = ImGui::GetCurrentWindow();
    if (window->WindowBorderSize <= 0.0f) return;
    const ImRect rect = window->Rect();
    ImGui::PushClipRect(rect.Min, rect.Max, false);
    window->DrawList->AddRect(rect.Min, rect.Max, ImGui::GetColorU32(ImGuiCol_Border), window->WindowRounding, 0,
                              window->WindowBorderSize);
    ImGui::PopClipRect();
}

// One line: a message longer than the window's width ends in "..." and shows whole on hover.
void EditorLayout::statusLine(EditorState& state, const StatusMessage& m) {
    textEllipsized(m.error ? ImVec4(1.0f, 0.45f, 0.45f, 1) : ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled), m.text);
    state.recordControl("status line");
}

float EditorLayout::splitter(const char* id, float x, float y, float w, float h, bool vertical, bool& released) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0.0f);
    ImGui::Begin(id, nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    ImGui::PopStyleVar(3);
    ImGui::InvisibleButton("##strip", ImVec2(w, h));
    const bool active = ImGui::IsItemActive();
    released = ImGui::IsItemDeactivated();
    float delta = 0.0f;
    if (active || ImGui::IsItemHovered()) {
        ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
        ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(x, y), ImVec2(x + w, y + h),
                                                  IM_COL32(90, 140, 220, active ? 200 : 120));
        if (active) delta = vertical ? ImGui::GetIO().MouseDelta.x : ImGui::GetIO().MouseDelta.y;
    }
    ImGui::End();
    return delta;
}

}  // namespace mgp::ui
