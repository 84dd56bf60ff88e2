#pragma once
// Whether two clips hold the same capture, and whether two skeletons are one.
//
// sameCapture: whether two clips hold the same capture: the editor's open clip and the clip a model
// was trained on (gp/model.h keeps it). The model's copy keeps only the DOFs of the pose vector
// (docs/maths.md §2: toes, fingers and thumbs dropped) and went through unwrapping and JSON, so the
// test compares joints by name, the frame count, and every frame's root position and pose angles
// (modulo 360°), each to 1e-6 cm or degrees: not bytes, file names or dropped bones.
#include <string>

#include "skeleton/clip.h"

namespace mgp {

// True when they match; otherwise `difference` (if given) says what differs first, in words a
// user reads ("358 frames against 362", "frame 12, lfemur rx: 3.1° apart").
bool sameCapture(const Clip& a, const Clip& b, std::string* difference = nullptr);

// Whether two skeletons are one skeleton, so clips of both can train one model (their pose
// vectors mean the same angles and the same FK): the same joints in the same order, each with the
// same name, parent, rotation order and animated axes (DOF channels), and offset, tail (bone
// direction × length) and axis frame C equal within kSkeletonToleranceCm (cm) and
// kSkeletonAxisTolerance (matrix entries). Clips of one ASF subject pass; two subjects' ASF files
// differ in bone lengths. Otherwise `difference` names the first mismatch in words a user reads
// ("joint 3 lfemur: tail (0, -17.3, 0) cm against (0, -18.1, 0) cm").
constexpr double kSkeletonToleranceCm = 1e-3;
constexpr double kSkeletonAxisTolerance = 1e-6;
bool sameSkeleton(const Skeleton& a, const Skeleton& b, std::string* difference = nullptr);

}  // namespace mgp
