#pragma once
// A protocol clip made of stretches of CMU trials (docs/maths.md §14): "10_03 [1:362]" or two
// runs joined. Frames are 1-based and inclusive, as the trials' own frame labels count them.
#include <map>
#include <string>
#include <vector>

#include "skeleton/clip.h"

namespace mgp {

struct ClipSegment {
    // "10_03": asf_amc/10_03.amc in the mocap folder; a name with '/' or '.' is a clip file
    // (AMC, BVH or glTF) read as it is (--clip).
    std::string trial;
    int first = 1, last = 1;  // last = 0 on a clip file: up to its end
};

// "FILE" or "FILE:A:B" (1-based, inclusive) as the protocols' --clip reads it: the whole clip when
// no range is given (last = 0). Throws std::invalid_argument naming what was found.
ClipSegment parseClipSpec(const std::string& spec);

// "10_03 [1:362] + 16_01 [1:70]".
std::string describeSegments(const std::vector<ClipSegment>& segments);

// Loaded trials by name (a clip file by its path), so that a protocol reads each file once.
using TrialCache = std::map<std::string, Clip>;

// The segments joined in order (not unwrapped, unnamed beyond the first trial's name). Throws
// std::invalid_argument naming the trial when a segment runs past its frames. A whole-clip
// segment (last = 0) takes every frame.
Clip joinSegments(const std::string& mocapDir, const std::vector<ClipSegment>& segments, TrialCache& cache);

}  // namespace mgp
