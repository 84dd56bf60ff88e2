#include "eval/clip_segments.h"

#include <stdexcept>

#include "io/clip_loader.h"

namespace mgp {

std::string describeSegments(const std::vector<ClipSegment>& segments) {
    std::string s;
    for (const ClipSegment& g : segments)
        s += (s.empty() ? "" : " + ") + g.trial + " [" + std::to_string(g.first) + ":" +
             (g.last == 0 ? "end" : std::to_string(g.last)) + "]";
    return s;
}

namespace {

bool isClipFile(const std::string& trial) { return trial.find_first_of("/.") != std::string::npos; }

bool parseFrameNumber(const std::string& s, int& out) {
    if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos) return false;
    out = std::stoi(s);
    return true;
}

}  // namespace

ClipSegment parseClipSpec(const std::string& spec) {
    ClipSegment seg{spec, 1, 0};
    // FILE:A:B: the last two fields are frame numbers; anything else is a path (which may hold ':').
    const std::size_t c2 = spec.rfind(':');
    const std::size_t c1 = c2 == std::string::npos || c2 == 0 ? std::string::npos : spec.rfind(':', c2 - 1);
    int a = 0, b = 0;
    if (c1 != std::string::npos && parseFrameNumber(spec.substr(c1 + 1, c2 - c1 - 1), a) &&
        parseFrameNumber(spec.substr(c2 + 1), b)) {
        if (a < 1 || b < a) throw std::invalid_argument("expected FILE:A:B with 1 ≤ A ≤ B, found '" + spec + "'");
        seg.trial = spec.substr(0, c1);
        seg.first = a;
        seg.last = b;
    }
    if (!isClipFile(seg.trial))
        throw std::invalid_argument("expected a clip file (a path with '/' or an extension) in FILE[:A:B], found '" +
                                    spec + "'");
    return seg;
}

Clip joinSegments(const std::string& mocapDir, const std::vector<ClipSegment>& segments, TrialCache& cache) {
    Clip joined;
    for (const ClipSegment& s : segments) {
        const std::string file = isClipFile(s.trial) ? s.trial : mocapDir + "/asf_amc/" + s.trial + ".amc";
        auto it = cache.find(s.trial);
        if (it == cache.end()) it = cache.emplace(s.trial, loadClip(file)).first;
        const Clip& clip = it->second;
        const int last = s.last == 0 && isClipFile(s.trial) ? clip.frameCount() : s.last;
        if (s.first < 1 || last < s.first || last > clip.frameCount())
            throw std::invalid_argument("expected " + s.trial + " frames " + std::to_string(s.first) + ".." +
                                        std::to_string(last) + " within 1.." + std::to_string(clip.frameCount()) +
                                        ", found a segment outside them");
        // A BVH converter's rest pose (frame 1) is not motion: a whole-file segment leaves it out.
        const int first = s.first == 1 && clip.restFrame ? 2 : s.first;
        if (first > last)
            throw std::invalid_argument("expected motion frames in " + s.trial + ", found only its rest frame");
        appendFrames(joined, clip, first - 1, last - first + 1);
    }
    return joined;
}

}  // namespace mgp
