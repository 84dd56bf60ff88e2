#pragma once
// Which clips Model ▸ Train on clips… offers beside the open clip, and why it refuses the others
// (docs/architecture.md, ui/windows/train_clips_window.h). The open clip comes first and is always part
// of the training (it becomes the model's primary clip). The other candidates are the clip files
// in the open clip's folder: a clip whose skeleton is the open clip's (sameSkeleton,
// skeleton/clip_match.h: AMCs of one ASF subject, or BVH files of one hierarchy) is offered; a
// clip of another skeleton or format (or whose skeleton cannot be read) is listed as refused,
// with the reason, so the user sees why a file next to the clip is not offered. For AMC clips
// only skeletons are read (one ASF per subject), not the motions; a BVH is read whole.
#include <string>
#include <vector>

#include "skeleton/clip.h"

namespace mgp {

struct TrainingCandidate {
    std::string path;    // the clip file ("" for a clip without one, e.g. the synthetic walk)
    std::string name;    // its file stem, the name the model will give it
    bool open = false;   // the open clip
    bool usable = true;  // it can train one model with the open clip
    std::string reason;  // why not ("" when usable)
};

// The open clip first, then the offered clips, then the refused ones, each group by name. The
// open clip is always usable.
std::vector<TrainingCandidate> trainingCandidates(const Clip& open);
// One file the user adds by path: the same checks (a missing or unreadable file is refused with
// the reader's message).
TrainingCandidate trainingCandidate(const Clip& open, const std::string& path);

}  // namespace mgp
