#pragma once
// Where the editor's panels go: the viewport in the centre, the timeline and status line below
// it, the Model panel, latent map and IK readout / Path / Model details tabs on the right, and the two splitters
// between them (their positions remembered in LayoutPrefs, layout_store.h). Sizes are pixels at
// scale 1 times the monitor's content scale.
#include <string>

#include "ui/panels/latent_map_panel.h"
#include "ui/panels/timeline_panel.h"
#include "ui/panels/viewport_panel.h"
#include "ui/shell/editor_state.h"
#include "ui/shell/layout_store.h"

namespace mgp::ui {

class EditorLayout {
public:
    // `layoutFile` remembers the splitters ("" = not remembered).
    EditorLayout(float scale, std::string layoutFile);

    // Places and draws every panel for a width×height window (between NewFrame and Render).
    void draw(EditorState& state, ViewportPanel& viewport, LatentMapPanel& latent, TimelinePanel& timeline, int width,
              int height);
    float leftWidth() const { return leftW_; }  // the viewport column's width, as last laid out
    bool customized() const { return prefs_.rightWidth > 0.0f || prefs_.timelineHeight > 0.0f; }
    void reset();  // back to the automatic layout (and remembered so)

private:
    void panels(EditorState& state, ViewportPanel& viewport, LatentMapPanel& latent, TimelinePanel& timeline, int w,
                int h, float menuH, float rightW, float timelineH, float modelH, float latentH);
    static void statusLine(EditorState& state, const StatusMessage& message);
    // The window border ImGui leaves out of a window drawn without its background.
    static void panelBorder();
    // A draggable strip between panels; returns the mouse's move along it this frame.
    float splitter(const char* id, float x, float y, float w, float h, bool vertical, bool& released);

    float scale_;
    std::string layoutFile_;
    LayoutPrefs prefs_;             // the splitters, as the user left them
    bool pathTabShown_ = false;     // a path was edited on the last frame
    bool pathTabSelected_ = false;  // the Path tab was in front on the last frame
    float leftW_ = 0.0f;
};

}  // namespace mgp::ui
