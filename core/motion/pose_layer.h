#pragma once
// A whole-pose change on one frame (paste, mirror, a joint rotation) as an additive animation
// layer with blend in and out, as Maya's animation layers and Blender's NLA strips do it: the
// change Δ of frame t0 (root position and every Euler channel, angles the short way round) is
// added to frames t0−r..t0+r with weight
//
//   w(t) = (1 − d)²(1 + 2d),   d = |t − t0| / r
//
// (the cubic Hermite blend): 1 at t0, 0 with zero slope at t0 ± r, so the layered motion joins
// the motion around it C¹. The drag falloff then re-solves that span from the layered motion
// under the learned prior with contacts held (EditorDocument::setCurrentPose, docs/maths-regeneration.md).
#include <vector>

#include "skeleton/pose_layout.h"

namespace mgp {

// w(t) above; 0 outside t0 ± radius; radius < 1 gives 1 at t0 and 0 elsewhere.
double poseLayerWeight(int t, int t0, int radius);

// `from` → `to` is the change on frame t0; adds w(t)·Δ to frames[t] for t in t0 ± radius (clamped
// to the clip). Frame t0 becomes `to` up to rounding of the angle wrap (callers that need it exact
// set it). The poses must all be of one skeleton.
void addPoseLayer(std::vector<Pose>& frames, int t0, int radius, const Pose& from, const Pose& to);

}  // namespace mgp
