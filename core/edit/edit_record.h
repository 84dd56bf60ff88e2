#pragma once
// EditRecord: one accepted pose of one frame (what a drag, a latent drag or a regeneration leaves).
#include <Eigen/Core>

#include "skeleton/pose_layout.h"

namespace mgp {

struct EditRecord {
    Pose pose;
    Eigen::VectorXd x;  // latent point of the accepted pose (empty if solved without a model)
};

}  // namespace mgp
