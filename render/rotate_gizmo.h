#pragma once
// The rotate gizmo of one joint (Edit > Rotate joint): a ring per rotation DOF the joint animates,
// centred on the joint, about that DOF's world axis at the current angles. This is the "gimbal"
// orientation of Maya's rotate tool: each ring turns exactly one Euler channel of the joint, so a
// one-DOF knee shows one ring and no drag asks for an axis the joint does not have. Rings are red,
// green and blue for the x, y and z channels and drawn over the figure; the joint's bone is
// highlighted. A joint that animates all three axes also gets a white view ring, larger, facing
// the camera: it turns the joint about the line of sight, as Blender's and Maya's outer ring does.
// Plain data and screen maths, no GL.
#include <vector>

#include "render/camera.h"
#include "render/scene.h"
#include "skeleton/clip.h"
#include "skeleton/forward_kinematics.h"

namespace mgp::render {

constexpr int kViewRing = 3;   // GizmoRing::axis of the view ring
constexpr int kTrackball = 4;  // not a ring: the disc inside the view ring, free rotation

struct GizmoRing {
    int axis = 0;                     // the joint's DOF: 0 x, 1 y, 2 z; or kViewRing
    glm::vec3 axisWorld{0.0f};        // unit
    std::vector<glm::vec3> pointsCm;  // closed: the last point is the first
};

struct RotateGizmo {
    int joint = -1;  // -1: no gizmo
    glm::vec3 pivotCm{0.0f};
    glm::vec3 boneEndCm{0.0f};
    float radiusCm = 15.0f;
    std::vector<GizmoRing> rings;  // one per animated DOF, in x, y, z order, then the view ring
};

// The gizmo of `joint` in `pose` (`fk` its forward kinematics) with rings of `radiusCm` (-1 joints
// and joints without rotation DOFs give an empty gizmo). With `eyeCm` (the camera's eye) a joint
// that animates x, y and z also gets the view ring, 1.25 times as large, its axis towards the eye.
RotateGizmo rotateGizmo(const Skeleton& skeleton, const Pose& pose, const FkState& fk, int joint, float radiusCm,
                        const glm::vec3* eyeCm = nullptr);
glm::vec3 gizmoAxisColour(int axis);  // red, green, blue; the view ring light grey
// Adds the rings (the hovered or dragged one, by GizmoRing::axis, brighter and thicker; -1 none) and the
// highlighted bone to the scene, drawn over everything else.
void addRotateGizmo(Scene& scene, const RotateGizmo& gizmo, int highlightedAxis);

// The GizmoRing::axis (a DOF, or kViewRing) of the ring whose outline passes within `slackPx` of pixel (x, y) of a w×h
// viewport, the nearest if several; -1 for none.
int pickGizmoRing(const RotateGizmo& gizmo, const OrbitCamera& camera, float x, float y, int w, int h,
                  float slackPx = 7.0f);
// Whether pixel (x, y) lies inside the view ring's disc on screen (a trackball drag there turns the
// joint freely); false for a gizmo without a view ring.
bool insideTrackball(const RotateGizmo& gizmo, const OrbitCamera& camera, float x, float y, int w, int h);
// The world rotation a trackball drag by (dx, dy) screen pixels makes: about the axis in the view
// plane perpendicular to the motion (unit), half a degree per pixel, so that the joint's side
// facing the viewer follows the mouse. No motion: 0 degrees.
struct TrackballTurn {
    glm::vec3 axisWorld{0.0f, 1.0f, 0.0f};
    float degrees = 0.0f;
};
TrackballTurn trackballTurn(const OrbitCamera& camera, float dx, float dy);
// What a ring is called in the editor's tooltips and readout: "rx ring" … "view ring", "free rotation".
const char* gizmoRingName(int axis);
// The rotation (degrees) about the ring `axis` (a DOF, or kViewRing) that moving the mouse from (x0, y0) to
// (x1, y1) sweeps around the joint on screen: the angle between the two pixels as seen from the
// projected pivot, positive counter-clockwise on screen when the axis points towards the camera
// (a right-handed turn as the viewer sees it) and negated when it points away. One degree of
// mouse sweep is one degree of rotation. 0 if the pivot is behind the camera or a pixel lies on it.
double gizmoSweepDeg(const RotateGizmo& gizmo, int axis, const OrbitCamera& camera, float x0, float y0, float x1,
                     float y1, int w, int h);

}  // namespace mgp::render
