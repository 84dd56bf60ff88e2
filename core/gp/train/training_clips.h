#pragma once
// The clips one model trains on, checked and reduced to their training frames: the one path both
// `motiongp train CLIP [CLIP …]` and the editor's Model ▸ Train on clips… take (through
// TrainingJob, core/edit/training_job.h). Several clips train one model only when they share one
// skeleton (sameSkeleton, skeleton/clip_match.h): the same ASF subject, or BVH files of one
// hierarchy (a BVH trains on its own rotation channels, skeleton/pose_layout.h). The frame
// selection applies to each clip on its own, frames counted within it; a BVH converter's rest
// frame (Clip::restFrame) is never a training row.
#include <stdexcept>
#include <string>
#include <vector>

#include "gp/model.h"
#include "gp/train/trainer.h"
#include "skeleton/clip.h"

namespace mgp::gp {

// Bad training input (clips of two skeletons, a frame range outside a clip, too few
// frames): one line a user reads. The CLI maps it to exit 2.
class TrainingInputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Frames A..B (1-based, inclusive; B = 0: to the clip's end) of each clip, then every step-th.
struct FrameSelection {
    int first = 1, last = 0;
    int step = 1;
};

// The 0-based frames of a clip of `frameCount` frames that `selection` keeps. Throws
// TrainingInputError naming the clip `name` when the range does not fit it.
std::vector<int> selectFrames(int frameCount, const FrameSelection& selection, const std::string& name);

// selectFrames on one clip, less its rest frame (frame 0 when Clip::restFrame) if the selection
// holds it.
std::vector<int> trainingFrames(int frameCount, bool restFrame, const FrameSelection& selection,
                                const std::string& name);

struct TrainingClip {
    Clip clip;                // unwrapped, so the model's clip matches its training rows
    std::string path;         // as given (messages); "" for the synthetic clip
    std::string sha256;       // of the file ("" without one)
    std::vector<int> frames;  // 0-based training frames
};

// Checks `clips` (the first becomes the model's primary clip) and selects their frames: one
// skeleton (against the first), distinct names (file stems), the selection fitting every clip and
// at least 3 rows in all. `paths[i]` is clip i's file as given ("" for none); the SHA-256 of each
// existing file is recorded. Throws TrainingInputError.
std::vector<TrainingClip> prepareTrainingClips(std::vector<Clip> clips, const std::vector<std::string>& paths,
                                               const FrameSelection& selection);

// The training matrix of prepared clips (trainingDataFromClips).
TrainingData trainingDataOf(const std::vector<TrainingClip>& clips);
// Stores the clips in a freshly trained model: the first as its primary clip, the others in
// moreClips, with file names, hashes and the frame selection (TrainingSettings; B = 0 recorded as
// the primary clip's last frame).
void attachTrainingClips(GpModel& model, std::vector<TrainingClip> clips, const FrameSelection& selection);

}  // namespace mgp::gp
