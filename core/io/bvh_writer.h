#pragma once
// BVH export of a clip (every frame; BVH frame k = clip frame k; no rest frame added).
//
// A clip read from BVH (a channel pose vector, skeleton/pose_layout.h) is written in its source
// hierarchy: the same joints, names and order, OFFSETs and End Sites in the source's units
// (Clip::cmPerFileUnit), each joint's rotation channels in its source order with the angles as
// they are, root positions absolute (root OFFSET 0). Our reader then gives back the same joints,
// convention and poses (a rest frame stays frame 1), and FK equals the source's within 1e-6 cm.
// Position channels of non-root joints (which the reader does not keep) are not written.
//
// Any other clip (ASF/AMC, synthetic): units cm (1 unit = 1 cm), Y up. One joint per bone of the
// 22-bone skeleton present in the clip, plus `root`, named by ASF bone name and placed at the
// bone's start (OFFSET = the parent bone's vector in cm); an `End Site` at the end of each leaf
// bone. Unmapped source joints are written only where a model bone hangs below them (their rotation
// matters), under their own names.
//   root:   OFFSET 0 0 0, CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation
//           (positions absolute)
//   others: CHANNELS 3 Zrotation Yrotation Xrotation (the bone's local rotation C·E·Cᵀ)
// Standard layout, one item per line, first line HIERARCHY, no comments, 9 decimals.
// Our reader recognises such a file (ASF bone names) as cm and never treats frame 1 as a rest
// frame; FK of the export equals FK of the source within 1e-6 cm.
#include <string>

#include "skeleton/clip.h"

namespace mgp {

std::string formatBvh(const Clip& clip);
void writeBvh(const Clip& clip, const std::string& path);  // atomic (temp + rename)

}  // namespace mgp
