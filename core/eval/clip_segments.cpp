#include "eval/clip_segments.h"

#include <stdexcept>

#include "io/clip_loader.h"

namespace mgp {

std::string describeSegments(const std::vector<ClipSegment>& segments) {
    std::string s;
    for (const ClipSegment& g : segments)
        s += (s.empty() ? "" : " + ") + g.trial + " [" + std::to_string(g.first) + ":" + std::to_string(g.last) + "]";
    return s;
}

Clip joinSegments(const std::string& mocapDir, const std::vector<ClipSegment>& segments, TrialCache& cache) {
    Clip joined;
    for (const ClipSegment& s : segments) {
        auto it = cache.find(s.trial);
        if (it == cache.end()) it = cache.emplace(s.trial, loadClip(mocapDir + "/asf_amc/" + s.trial + ".amc")).first;
        const Clip& clip = it->second;
        if (s.first < 1 || s.last < s.first || s.last > clip.frameCount())
            throw std::invalid_argument("expected " + s.trial + " frames " + std::to_string(s.first) + ".." +
                                        std::to_string(s.last) + " within 1.." + std::to_string(clip.frameCount()) +
                                        ", found a segment outside them");
        appendFrames(joined, clip, s.first - 1, s.last - s.first + 1);
    }
    return joined;
}

}  // namespace mgp
