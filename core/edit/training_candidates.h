#pragma once
// Which clips Model ▸ Train on clips… offers beside the open clip, and why it refuses the others
// (docs/architecture.md, ui/train_clips_window.h). The open clip comes first and is always part
// of the training (it becomes the model's primary clip). The other candidates are the clip files
// in the open clip's folder: an AMC whose ASF skeleton is the open clip's (sameSkeleton,
// skeleton/clip_match.h: clips of one subject) is offered; an AMC of another skeleton (or whose
// ASF cannot be read) and every BVH are listed as refused, with the reason, so the user sees why
// a file next to the clip is not offered. Only skeletons are read here (one ASF per subject), not
// the motions: a folder of many clips lists quickly.
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
// open clip is refused itself when it is BVH (training on BVH is not supported yet); then no
// other clip is listed.
std::vector<TrainingCandidate> trainingCandidates(const Clip& open);
// One file the user adds by path: the same checks (a missing or unreadable file is refused with
// the reader's message).
TrainingCandidate trainingCandidate(const Clip& open, const std::string& path);

}  // namespace mgp
