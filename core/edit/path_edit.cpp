#include "edit/path_edit.h"

#include <algorithm>

namespace mgp {

std::vector<int> defaultPathKeys(int frame, int frameCount) {
    if (frameCount < 3) return {};
    constexpr int kSpacing = 14;
    const int count = std::min(4, frameCount);  // 3 frames: keys 1, 2, 3
    const int spacing = std::min(kSpacing, (frameCount - 1) / (count - 1));
    const int span = spacing * (count - 1);
    const int first = std::clamp(frame - span / 2, 0, frameCount - 1 - span);
    std::vector<int> keys;
    for (int i = 0; i < count; ++i) keys.push_back(first + i * spacing);
    return keys;
}

std::string validatePathKeys(const std::vector<int>& keys, int frameCount) {
    if (keys.size() < 2) return "expected at least 2 key frames, found " + std::to_string(keys.size());
    for (std::size_t i = 0; i < keys.size(); ++i) {
        if (keys[i] < 0 || keys[i] >= frameCount)
            return "expected key frames in 1.." + std::to_string(frameCount) + ", found " + std::to_string(keys[i] + 1);
        if (i > 0 && keys[i] <= keys[i - 1])
            return "expected strictly increasing key frames, found " + std::to_string(keys[i - 1] + 1) + " then " +
                   std::to_string(keys[i] + 1);
    }
    if (keys.back() - keys.front() < 2) return "expected at least one frame between the first and last key, found none";
    return "";
}

}  // namespace mgp
