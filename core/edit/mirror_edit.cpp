#include "edit/mirror_edit.h"

#include "skeleton/pose_mirror.h"

namespace mgp {

std::string mirrorPoseLabel(int frame) { return "mirror pose on frame " + std::to_string(frame + 1); }

std::string mirrorCurrentPose(EditorDocument& doc) {
    if (!doc.hasClip()) return "no clip to mirror: open one first";
    std::string err;
    const std::optional<PoseMirror> mirror = PoseMirror::make(doc.clip().skeleton, err);
    if (!mirror) return err;
    return doc.setCurrentPose(mirror->mirror(doc.currentPose()), mirrorPoseLabel(doc.frame()),
                              EditorDocument::PoseHolds::kResolve);
}

}  // namespace mgp
