#pragma once
// A built-in demo clip the project makes itself, used when no mocap folder is found: a 22-bone
// CMU-like skeleton (plus rigid hands and toes for display) with human proportions and a periodic
// walk (hip/knee/ankle/arm swing phase-locked, feet near the ground), 120 fps.
#include "skeleton/clip.h"

namespace mgp {

// `frames` ≥ 1; the walk cycle is 120 frames (1 s), so the default shows two cycles.
Clip makeSyntheticWalk(int frames = 240);

}  // namespace mgp
