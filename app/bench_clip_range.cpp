#include "bench_clip_range.h"

#include <algorithm>

#include "io/clip_loader.h"

namespace mgp::app {

Clip loadClipRange(const std::string& mocapDir, const BenchClipRange& range, int& first) {
    const Clip whole = loadClip(mocapDir + "/" + range.path);
    first = std::clamp(range.first, 1, whole.frameCount());
    const int last = std::clamp(range.last, first, whole.frameCount());
    Clip clip;
    appendFrames(clip, whole, first - 1, last - first + 1);
    return clip;
}

std::vector<int> spreadPicks(const std::vector<int>& candidates, int count, int minGap) {
    std::vector<int> out;
    for (int k = 0; k < count && !candidates.empty(); ++k) {
        const int t = candidates[(2 * static_cast<std::size_t>(k) + 1) * candidates.size() /
                                 (2 * static_cast<std::size_t>(count))];
        if (out.empty() || t - out.back() > minGap) out.push_back(t);
    }
    return out;
}

}  // namespace mgp::app
