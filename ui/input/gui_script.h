#pragma once
// GuiScript: timed input events that drive the editor without a person (tests, --script,
// --offscreen). The script format:
//
//   # comment (also after an event)             blank lines are ignored
//   <frame> <verb> [arguments]                  frame: 0-based UI frame the event is applied at
//
//   move X Y               mouse to window pixel (X right, Y down from the top-left corner)
//   moveby DX DY           mouse by a pixel offset
//   hover EFFECTOR         mouse onto an effector handle's current screen position
//                          (lhand rhand lfoot rfoot head), resolved when the event runs
//   hover key:N            mouse onto key N (1-based) of the path being edited
//   hover dot:CLIP:N       mouse onto the latent map's dot of frame N (1-based) of training clip CLIP
//   down BUTTON            press a mouse button: left | right | middle
//   up BUTTON              release it
//   wheel DY               scroll (positive zooms in)
//   key NAME               press a key; it is released on the next frame
//   keydown NAME           hold a key (e.g. SHIFT for a ground-plane drag or a pan)
//   keyup NAME             release a held key
//   action NAME [ARGS]     an action of the editor's action table (editor_actions.h; listed
//                          in docs/guide.md): e.g. `open PATH`, `frame N`, `undo`, `wait`, and
//                          `screenshot PATH` (a PNG of the whole window after this frame)
//
// Key names: A-Z, 0-9, SPACE, LEFT, RIGHT, UP, DOWN, ESCAPE, ENTER, TAB, DELETE, BACKSPACE, HOME,
// END, PAGEUP, PAGEDOWN, F1-F12, SHIFT, CTRL, ALT. Events on the same frame apply in file order.
// ImGui 1.86 reads button state once per frame, so leave at least one frame between a button's
// down and up (and between a move and a down on a new spot). Example: a drag of the right foot
//
//   5  hover rfoot
//   7  down left
//   9  moveby 0 -20
//   11 moveby 0 -20
//   13 up left
//   16 action screenshot out.png
#include <string>
#include <vector>

#include "ui/input/input_state.h"

namespace mgp::ui {

struct ScriptEvent {
    int frame = 0;
    std::string verb;
    std::vector<std::string> args;
    int line = 0;
};

class GuiScript {
public:
    // Throws mgp::ParseError "file:line: expected ..., found ..." on a malformed line.
    static GuiScript parse(const std::string& text, const std::string& fileName = "<script>");
    static GuiScript load(const std::string& path);
    void add(int frame, std::string verb, std::vector<std::string> args = {});
    const std::vector<ScriptEvent>& events() const { return events_; }
    int lastFrame() const;  // -1 if empty

private:
    std::vector<ScriptEvent> events_;  // sorted by frame (stable)
};

}  // namespace mgp::ui
