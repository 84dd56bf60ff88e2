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
//   down BUTTON            press a mouse button: left | right | middle
//   up BUTTON              release it
//   wheel DY               scroll (positive zooms in)
//   key NAME               press a key; it is released on the next frame
//   keydown NAME           hold a key (e.g. SHIFT for a ground-plane drag or a pan)
//   keyup NAME             release a held key
//   action NAME [ARGS]     a named UI action:
//       open PATH            open an ASF/AMC or BVH clip
//       open-model PATH      open a saved model (its clip comes with it)
//       save-model PATH      save the current model
//       train [fas|sgplvm] [M] [T]   start training on the open clip (defaults from the panel)
//       train-compare        train the compare model (the other kernel) for `compare model`
//       cancel-train         cancel the training run
//       wait                 block until training, adaptive updates and the latent map are done
//       play | pause         timeline playback
//       frame N              go to frame N (1-based, as the timeline shows it)
//       pin EFFECTOR         toggle a pin
//       compare none|plain|model   the compare ghost
//       frame-camera         frame the character (same as F)
//       undo | redo          one step of the edit history (Ctrl+Z / Ctrl+Shift+Z)
//       path EFFECTOR        edit that effector's path (default keys around the current frame)
//       path-keys F1 F2 ...  the path's key frames (1-based, increasing)
//       path-offset K DX DY DZ   key K's (1-based) offset from the captured path, cm
//       path-mode direct|displacement
//       regenerate [ITERS]   solve the path span (background; `wait` waits for it)
//       save-session PATH    save the session (becomes the current session file)
//       open-session PATH    open a session
//       export-bvh PATH      the edited motion as BVH
//       export-png PATH      the 3-D viewport as PNG
//       autosave             write this editor's autosave file now
//       restore-autosave [PATH]   restore an autosave (default: newest left by a dead editor)
//       quit                 quit (asks about unsaved changes)   discard-and-quit: without asking
//       screenshot PATH      save a PNG of the whole window after this frame
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

#include "input_state.h"

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
