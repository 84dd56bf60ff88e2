#pragma once
// The document's path session (docs/maths.md §12): the effector path being edited — its keys,
// their offsets from the captured path and the mode — checked against the document's clip, with
// the captured effector trajectory cached. Each change calls `onChange` (the document counts it
// as a change to save). Regeneration of the span is the document's (it writes edits and undo).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "edit/path_edit.h"
#include "skeleton/clip.h"

namespace mgp {

class PathSession {
public:
    // `clip` is the document's own, read on every call (it outlives the session).
    explicit PathSession(const Clip& clip, std::function<void()> onChange = nullptr);

    void reset();  // a new clip: no path, no cached trajectory

    // Each returns "" or why not, and leaves the path unchanged then.
    std::string begin(Effector e, int frame);  // the default keys around `frame`, no offsets
    std::string set(PathEdit path);            // a whole path edit (a loaded session)
    void end();
    const std::optional<PathEdit>& edit() const { return path_; }
    // New key frames (0-based); keys at frames that were keys keep their offsets.
    std::string setKeyFrames(std::vector<int> keyFrames);
    std::string setKeyOffset(int key, const Eigen::Vector3d& offsetCm);
    // Moves a key to a world position (its offset becomes position − captured position).
    std::string setKeyPosition(int key, const Eigen::Vector3d& positionCm);
    void setMode(PathMode mode);

    Eigen::Vector3d keyPosition(int key) const;     // captured + offset (cm)
    std::vector<Eigen::Vector3d> targets() const;   // the edited path, frames first..last
    std::vector<Eigen::Vector3d> captured() const;  // the captured path, frames first..last

private:
    const std::vector<Eigen::Vector3d>& capturedTrajectory(Effector e) const;
    void changed() {
        if (onChange_) onChange_();
    }

    const Clip& clip_;
    std::function<void()> onChange_;
    std::optional<PathEdit> path_;
    mutable int trajectoryEffector_ = -1;
    mutable std::vector<Eigen::Vector3d> trajectory_;  // captured effector positions, every frame
};

}  // namespace mgp
