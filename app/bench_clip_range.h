#pragma once
// What the editing benches (locality, pose_ops) share: a stretch of a CMU clip to train and edit
// on, and frames picked evenly from a candidate list.
#include <string>
#include <vector>

#include "skeleton/clip.h"

namespace mgp::app {

struct BenchClipRange {
    const char* path;  // under the mocap folder
    int first, last;   // 1-based frames kept (a long take is cut); clamped to the clip
};

// The clip at mocapDir/path cut to its frames first..last; `first` receives the clamped first frame
// (1-based), so that a frame t of the cut clip is frame t + first of the file.
Clip loadClipRange(const std::string& mocapDir, const BenchClipRange& range, int& first);

// Up to `count` of `candidates` (increasing frames) at evenly spread ranks, each more than
// `minGap` frames after the previous pick.
std::vector<int> spreadPicks(const std::vector<int>& candidates, int count, int minGap);

}  // namespace mgp::app
