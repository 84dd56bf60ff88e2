#pragma once
// A protocol clip made of stretches of CMU trials (docs/maths.md §14): "10_03 [1:362]" or two
// runs joined. Frames are 1-based and inclusive, as the trials' own frame labels count them.
#include <map>
#include <string>
#include <vector>

#include "skeleton/clip.h"

namespace mgp {

struct ClipSegment {
    std::string trial;  // "10_03": asf_amc/10_03.amc in the mocap folder
    int first = 1, last = 1;
};

// "10_03 [1:362] + 16_01 [1:70]".
std::string describeSegments(const std::vector<ClipSegment>& segments);

// Loaded trials by name, so that a protocol reads each file once.
using TrialCache = std::map<std::string, Clip>;

// The segments joined in order (not unwrapped, unnamed beyond the first trial's name). Throws
// std::invalid_argument naming the trial when a segment runs past its frames.
Clip joinSegments(const std::string& mocapDir, const std::vector<ClipSegment>& segments, TrialCache& cache);

}  // namespace mgp
