#pragma once
// EditRecord: one accepted pose of one frame (what a drag, a latent drag or a regeneration leaves).
#include <Eigen/Core>
#include <map>
#include <optional>

#include "skeleton/pose_layout.h"

namespace mgp {

struct EditRecord {
    Pose pose;
    Eigen::VectorXd x;  // latent point of the accepted pose (empty if solved without a model)
};

// A change of edits, per frame (0-based): the new edit, or none for the captured pose.
using FrameEdits = std::map<int, std::optional<EditRecord>>;

}  // namespace mgp
