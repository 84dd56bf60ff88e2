#include "ui/input/input_replay.h"

#include <algorithm>
#include <vector>

namespace mgp::ui {

void InputReplay::next(InputState& in) {
    queue_.insert(queue_.end(), in.events.begin(), in.events.end());
    in.events.clear();
    std::vector<int> touched;  // buttons as -1-b, keys as their code
    bool pressed = false;      // a key (not a modifier) or a button went down this frame
    while (!queue_.empty()) {
        const InputEvent e = queue_.front();
        const int id = e.isKey ? e.code : -1 - e.code;
        if (std::find(touched.begin(), touched.end(), id) != touched.end()) break;  // next frame
        // A modifier changing after a press waits a frame, so the press is seen with the
        // modifiers held when it happened: X11 delivers xdotool's ctrl+z as Ctrl↓ Z↓ Ctrl↑ Z↑,
        // and applied together Z↓ Ctrl↑ would make it a plain Z.
        const bool modifier = e.isKey && isModifierKey(e.code);
        if (pressed && modifier) break;
        pressed = pressed || (e.down && !modifier);
        touched.push_back(id);
        if (e.isKey)
            keys_[e.code] = e.down;
        else
            buttons_[e.code] = e.down;
        queue_.pop_front();
    }
    if (queue_.empty()) {
        // Everything replayed: the live state is the truth (it also covers direct writes).
        buttons_ = in.mouseDown;
        keys_ = in.keys;
    }
}

}  // namespace mgp::ui
