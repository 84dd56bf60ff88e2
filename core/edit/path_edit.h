#pragma once
// The effector path being edited in the editor (docs/maths.md §12): which effector, the key
// frames, each key's offset from the captured path, direct or displacement mode.
#include <string>
#include <vector>

#include "motion/motion_edit.h"

namespace mgp {

struct PathEdit {
    Effector effector = Effector::kRFoot;
    std::vector<int> keyFrames;                 // 0-based, strictly increasing, ≥ 2
    std::vector<Eigen::Vector3d> keyOffsetsCm;  // one per key (cm, from the captured position)
    PathMode mode = PathMode::kDisplacement;
};

// The paper's pattern: four keys 14 frames apart centred on `frame` (frame 110 → 89, 103, 117,
// 131, 1-based), moved to fit inside the clip and spaced closer on short clips. Empty when the
// clip has fewer than 3 frames (a path needs a frame between two keys).
std::vector<int> defaultPathKeys(int frame, int frameCount);

// "" or "expected …, found …" for key frames of a clip with `frameCount` frames.
std::string validatePathKeys(const std::vector<int>& keyFrames, int frameCount);

}  // namespace mgp
