#pragma once
// EditRecord: one accepted pose of one frame (what a drag, a latent drag or a regeneration leaves).
#include <Eigen/Core>
#include <map>
#include <optional>
#include <vector>

#include "skeleton/pose_layout.h"

namespace mgp {

struct EditRecord {
    Pose pose;
    Eigen::VectorXd x;  // latent point of the accepted pose (empty if solved without a model)
    // The effectors the edit put where the animator asked (a drag's handle, a path's effector):
    // the admission judges the rest of the body against the capture (eval/admission.h).
    std::vector<Effector> moved;
};

// A change of edits, per frame (0-based): the new edit, or none for the captured pose.
using FrameEdits = std::map<int, std::optional<EditRecord>>;

}  // namespace mgp
