#pragma once
// Whether two clips hold the same capture: the editor's open clip and the clip a model was
// trained on (gp/model.h keeps it). The model's copy keeps only the 47 DOFs of the pose vector
// (docs/maths.md §2: toes, fingers and thumbs dropped) and went through unwrapping and JSON, so
// the test compares joints by name, the frame count, and every frame's root position and 47 pose
// angles (modulo 360°), each to 1e-6 cm or degrees: not bytes, file names or dropped bones.
#include <string>

#include "skeleton/clip.h"

namespace mgp {

// True when they match; otherwise `difference` (if given) says what differs first, in words a
// user reads ("358 frames against 362", "frame 12, lfemur rx: 3.1° apart").
bool sameCapture(const Clip& a, const Clip& b, std::string* difference = nullptr);

}  // namespace mgp
