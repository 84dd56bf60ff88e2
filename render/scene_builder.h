#pragma once
// Filling a Scene from core data (skeleton, FK, clips). Plain data out, no GL.
// Units: cm, Y up (docs/maths.md, conventions). Frames are 0-based here (the CLI converts from 1-based).
#include <optional>
#include <vector>

#include "render/motion_overlays.h"
#include "render/rotate_gizmo.h"
#include "render/scene.h"
#include "skeleton/clip.h"
#include "skeleton/forward_kinematics.h"

namespace mgp::render {

// A core point (cm, world Y up) as the renderer takes it: the same axes, in float.
glm::vec3 toGlm(const Eigen::Vector3d& v);

// Side of a bone from its ASF role: 'l…' left, 'r…' right (root excluded), else centre.
BodySide sideOfBone(const std::string& boneRole);

// How thick a bone of ASF role `boneRole` is drawn: its larger end radius (cm).
float boneRadiusCm(const std::string& boneRole);
// Solid bones and joint balls of one posed skeleton (bones shorter than 0.5 cm are skipped).
Figure makeFigure(const Skeleton& skeleton, const FkState& fk);
// Moves every bone and joint of a figure by `offsetCm`.
void translateFigure(Figure& figure, const glm::vec3& offsetCm);
// Handles at the five effectors the skeleton has (id = int(Effector)).
std::vector<Handle> effectorHandles(const Skeleton& skeleton, const FkState& fk);

// The horizontal direction the character faces (up × (right hip − left hip)); +Z if unknown.
glm::vec3 characterForward(const Skeleton& skeleton, const FkState& fk);

// Bounding sphere of the figures' solids (centre and radius, cm).
struct Bounds {
    glm::vec3 centreCm{0.0f};
    float radiusCm = 100.0f;
};
Bounds sceneBounds(const Scene& scene);

// The floor height of a clip: the lowest foot/toe surface point over its frames (a rest frame,
// Clip::restFrame, left out).
float clipGroundHeight(const Clip& clip);

// An effector's trajectory over frames [first, last] (clamped), keys every `keyEvery` frames,
// `current` highlighted.
Path effectorPath(const Clip& clip, Effector e, int first, int last, int keyEvery, int current);

// What the CLI and the tests draw for one frame of a clip. A model's source clip (the MODEL form
// of `motiongp render`) goes through the same call once models can be loaded.
struct ClipSceneOptions {
    int frameIndex = 0;          // 0-based
    bool ghostCaptured = false;  // the captured pose as a ghost beside the shown one
    // There is no edit in the CLIP form (shown pose = captured pose), so the ghost is placed
    // beside it, this far along the character's left, to be visible.
    float ghostSideOffsetCm = 75.0f;
    std::optional<Pose> editedPose;  // shown instead of the captured frame when set
    bool handles = true;
    std::optional<Effector> selected;
    std::optional<Effector> hovered;
    std::vector<Effector> paths;  // trajectories over ±pathHalfSpan frames
    int pathHalfSpan = 60;
    int pathKeyEvery = 20;
    bool caption = true;
    std::optional<OnionSkin> onion;  // ghosts of the clip's frames around this one
    std::vector<TrailPart> trails;   // motion trails (a tick per frame) over ±trailHalfSpan frames
    int trailHalfSpan = 30;
    int gizmoJoint = -1;  // the rotate gizmo of this joint (-1 none), rings of gizmoRadiusCm
    float gizmoRadiusCm = 16.0f;
};
Scene buildClipScene(const Clip& clip, const ClipSceneOptions& options);

}  // namespace mgp::render
