#pragma once
// Mirror pose on the document's current frame, as one undo step (skeleton/pose_mirror.h has the
// maths; docs/maths.md §21).
#include <string>

#include "edit/editor_document.h"

namespace mgp {

// Mirrors the current frame's pose left/right; "" or why not (no clip, a skeleton without a
// symmetry). The undo step is named mirrorPoseLabel(frame).
std::string mirrorCurrentPose(EditorDocument& doc);
std::string mirrorPoseLabel(int frame);  // "mirror pose on frame N" (N 1-based)

}  // namespace mgp
