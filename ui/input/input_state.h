#pragma once
// The input the editor reads each frame, filled either by the GLFW window (interactive) or by a
// GuiScript (tests, --script, --offscreen). Key codes are GLFW's values (ASCII for printable
// keys), so the window passes them through unchanged and ui/ needs no GLFW header.
#include <array>
#include <string>
#include <vector>

namespace mgp::ui {

namespace key {
constexpr int kSpace = 32, kEscape = 256, kEnter = 257, kTab = 258, kBackspace = 259, kDelete = 261;
constexpr int kRight = 262, kLeft = 263, kDown = 264, kUp = 265, kPageUp = 266, kPageDown = 267;
constexpr int kHome = 268, kEnd = 269, kF1 = 290;
constexpr int kLeftShift = 340, kLeftCtrl = 341, kLeftAlt = 342, kRightShift = 344, kRightCtrl = 345, kRightAlt = 346;
constexpr int kCount = 512;
}  // namespace key

inline bool isModifierKey(int k) {
    return k == key::kLeftShift || k == key::kRightShift || k == key::kLeftCtrl || k == key::kRightCtrl ||
           k == key::kLeftAlt || k == key::kRightAlt;
}

// One press or release, in the order it happened (InputState::events).
struct InputEvent {
    bool isKey = false;  // else a mouse button (0 left, 1 right, 2 middle)
    int code = 0;
    bool down = false;
};

struct InputState {
    float mouseX = -1.0f, mouseY = -1.0f;  // window pixels, y down; negative = outside
    std::array<bool, 3> mouseDown{};       // left, right, middle
    float wheel = 0.0f;                    // accumulated since the last frame (+ = away from the user)
    std::array<bool, key::kCount> keys{};
    std::u32string chars;  // typed characters since the last frame
    // Every change of mouseDown and keys made through setButton/setKey since the last frame, so
    // that a tap shorter than a frame still reaches the editor (ui/input/input_replay.h).
    std::vector<InputEvent> events;
    void setButton(int b, bool down) {
        if (b < 0 || b >= int(mouseDown.size()) || mouseDown[b] == down) return;
        mouseDown[b] = down;
        events.push_back({false, b, down});
    }
    void setKey(int k, bool down) {
        if (k < 0 || k >= key::kCount || keys[k] == down) return;
        keys[k] = down;
        events.push_back({true, k, down});
    }
    bool shift() const { return keys[key::kLeftShift] || keys[key::kRightShift]; }
    bool ctrl() const { return keys[key::kLeftCtrl] || keys[key::kRightCtrl]; }
    bool alt() const { return keys[key::kLeftAlt] || keys[key::kRightAlt]; }
};

// "A".."Z", "0".."9", "SPACE", "LEFT", "RIGHT", "UP", "DOWN", "ESCAPE", "ENTER", "TAB",
// "DELETE", "BACKSPACE", "HOME", "END", "PAGEUP", "PAGEDOWN", "F1".."F12", "SHIFT", "CTRL", "ALT"
// (case-insensitive) -> key code, or -1.
int keyFromName(const std::string& name);

}  // namespace mgp::ui
