#include "gp/train/training_clips.h"

#include <filesystem>

#include "gp/sha256.h"
#include "skeleton/clip_match.h"

namespace mgp::gp {

namespace {
std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }
}  // namespace

std::vector<int> selectFrames(int frameCount, const FrameSelection& s, const std::string& name) {
    const int last = s.last == 0 ? frameCount : s.last;
    if (s.first < 1 || last > frameCount || s.first > last)
        throw TrainingInputError("expected --frames A:B with 1 ≤ A ≤ B ≤ " + std::to_string(frameCount) + " (" + name +
                                 "'s frames counted from 1), found '" + std::to_string(s.first) + ":" +
                                 std::to_string(last) + "'");
    if (s.step < 1) throw TrainingInputError("expected --step ≥ 1, found " + std::to_string(s.step));
    std::vector<int> frames;
    for (int t = s.first; t <= last; t += s.step) frames.push_back(t - 1);
    return frames;
}

std::vector<int> trainingFrames(int frameCount, bool restFrame, const FrameSelection& selection,
                                const std::string& name) {
    std::vector<int> frames = selectFrames(frameCount, selection, name);
    // A converter's rest or T-pose (a BVH's frame 1) is not captured motion: never a training row.
    if (restFrame && !frames.empty() && frames.front() == 0) frames.erase(frames.begin());
    return frames;
}

std::vector<TrainingClip> prepareTrainingClips(std::vector<Clip> clips, const std::vector<std::string>& paths,
                                               const FrameSelection& selection) {
    if (clips.empty() || clips.size() != paths.size())
        throw std::invalid_argument("prepareTrainingClips: expected one path per clip (at least one clip)");
    std::vector<TrainingClip> out;
    std::size_t rows = 0;
    for (std::size_t i = 0; i < clips.size(); ++i) {
        Clip& clip = clips[i];
        const std::string& path = paths[i];
        const std::string shown = path.empty() ? clip.name : path;
        if (!out.empty()) {
            std::string difference;
            if (!sameSkeleton(out.front().clip.skeleton, clip.skeleton, &difference))
                throw TrainingInputError(
                    "expected clips of one skeleton (retargeting is not supported), found " + shown + " against " +
                    (paths.front().empty() ? out.front().clip.name : paths.front()) + ": " + difference);
        }
        for (const TrainingClip& c : out)
            if (c.clip.name == clip.name)
                throw TrainingInputError("expected clips with distinct names (file stems), found " + clip.name +
                                         " twice");
        TrainingClip t;
        t.frames = trainingFrames(clip.frameCount(), clip.restFrame, selection, clip.name);
        rows += t.frames.size();
        unwrapClip(clip);
        t.path = path;
        t.sha256 = path.empty() || !std::filesystem::is_regular_file(path) ? "" : sha256OfFile(path);
        t.clip = std::move(clip);
        out.push_back(std::move(t));
    }
    if (rows < 3)
        throw TrainingInputError("expected at least 3 training frames after --frames/--step, found " +
                                 std::to_string(rows));
    return out;
}

TrainingData trainingDataOf(const std::vector<TrainingClip>& clips) {
    std::vector<const Clip*> ptrs;
    std::vector<std::vector<int>> frames;
    for (const TrainingClip& c : clips) {
        ptrs.push_back(&c.clip);
        frames.push_back(c.frames);
    }
    return trainingDataFromClips(ptrs, frames);
}

void attachTrainingClips(GpModel& model, std::vector<TrainingClip> clips, const FrameSelection& selection) {
    if (clips.empty()) throw std::invalid_argument("attachTrainingClips: expected at least one clip");
    // The range as it applied to the primary clip ("to the end" resolved), as train always recorded it.
    model.settings.frameFirst = selection.first;
    model.settings.frameLast = selection.last == 0 ? clips.front().clip.frameCount() : selection.last;
    model.settings.frameStep = selection.step;
    model.clip = std::move(clips.front().clip);
    model.sourceFile = fileName(clips.front().path);
    model.sourceSha256 = clips.front().sha256;
    model.moreClips.clear();
    for (std::size_t c = 1; c < clips.size(); ++c)
        model.moreClips.push_back({fileName(clips[c].path), clips[c].sha256, std::move(clips[c].clip)});
}

}  // namespace mgp::gp
