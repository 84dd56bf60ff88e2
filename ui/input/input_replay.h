#pragma once
// Replays presses and releases across frames. Dear ImGui 1.86 reads button and key state once
// per frame, so a click or key tap that starts and ends between two frames would never be seen.
// InputReplay queues the InputState's events and hands ImGui, each frame, the state after as many
// events as can apply without changing any one button or key twice: a tap is down on one frame
// and up on the next. With no events queued the state is the InputState's own (tests and
// scripts may set it directly).
#include <array>
#include <deque>

#include "ui/input/input_state.h"

namespace mgp::ui {

class InputReplay {
public:
    // Takes in.events and sets this frame's button and key state.
    void next(InputState& in);
    const std::array<bool, 3>& buttons() const { return buttons_; }
    const std::array<bool, key::kCount>& keys() const { return keys_; }
    bool shift() const { return keys_[key::kLeftShift] || keys_[key::kRightShift]; }
    bool ctrl() const { return keys_[key::kLeftCtrl] || keys_[key::kRightCtrl]; }
    bool alt() const { return keys_[key::kLeftAlt] || keys_[key::kRightAlt]; }
    bool pending() const { return !queue_.empty(); }  // events wait for a later frame

private:
    std::deque<InputEvent> queue_;
    std::array<bool, 3> buttons_{};
    std::array<bool, key::kCount> keys_{};
};

}  // namespace mgp::ui
