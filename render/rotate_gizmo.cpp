// The rotate gizmo (rotate_gizmo.h).
#include "render/rotate_gizmo.h"

#include <cmath>

#include "render/scene_builder.h"
#include "skeleton/forward_kinematics.h"

namespace mgp::render {

namespace {

constexpr int kRingSegments = 64;

// Distance from p to the segment [a, b] in the plane.
float pixelSegmentDistance(const glm::vec2& p, const glm::vec2& a, const glm::vec2& b) {
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? glm::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + t * ab));
}

}  // namespace

RotateGizmo rotateGizmo(const Skeleton& skeleton, const Pose& pose, const FkState& fk, int joint, float radiusCm,
                        const glm::vec3* eyeCm) {
    RotateGizmo g;
    if (joint < 0 || joint >= skeleton.jointCount()) return g;
    const Joint& jt = skeleton.joints[joint];
    if (!(jt.dof[0] || jt.dof[1] || jt.dof[2])) return g;
    g.joint = joint;
    g.pivotCm = toGlm(fk.jointCm[joint]);
    g.boneEndCm = toGlm(boneEndCm(skeleton, fk, joint));
    g.radiusCm = radiusCm;
    // A ring of `radius` round the pivot in the plane normal to `axisWorld`.
    auto ringAbout = [&](int axis, const glm::vec3& axisWorld, float radius) {
        GizmoRing ring;
        ring.axis = axis;
        ring.axisWorld = axisWorld;
        // Two unit vectors spanning the ring's plane.
        const glm::vec3 helper = std::abs(ring.axisWorld.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::vec3 u = glm::normalize(glm::cross(ring.axisWorld, helper));
        const glm::vec3 v = glm::cross(ring.axisWorld, u);
        for (int k = 0; k <= kRingSegments; ++k) {
            const float t = 6.28318530718f * static_cast<float>(k % kRingSegments) / kRingSegments;
            ring.pointsCm.push_back(g.pivotCm + radius * (std::cos(t) * u + std::sin(t) * v));
        }
        g.rings.push_back(std::move(ring));
    };
    for (int a = 0; a < 3; ++a)
        if (jt.dof[a]) ringAbout(a, glm::normalize(toGlm(dofWorldAxis(skeleton, fk, pose, joint, a))), radiusCm);
    if (eyeCm && jt.dof[0] && jt.dof[1] && jt.dof[2] && glm::length(*eyeCm - g.pivotCm) > 1e-3f)
        ringAbout(kViewRing, glm::normalize(*eyeCm - g.pivotCm), radiusCm * 1.25f);
    return g;
}

glm::vec3 gizmoAxisColour(int axis) {
    switch (axis) {
        case 0: return {0.92f, 0.25f, 0.25f};
        case 1: return {0.30f, 0.85f, 0.30f};
        case 2: return {0.25f, 0.45f, 0.98f};
        default: return {0.86f, 0.87f, 0.90f};
    }
}

void addRotateGizmo(Scene& scene, const RotateGizmo& g, int highlightedAxis) {
    if (g.joint < 0) return;
    Path bone;
    bone.pointsCm = {g.pivotCm, g.boneEndCm};
    bone.colour = {1.0f, 0.85f, 0.35f};
    bone.radiusCm = g.radiusCm * 0.035f;
    bone.onTop = true;
    scene.paths.push_back(std::move(bone));
    for (const GizmoRing& ring : g.rings) {
        Path p;
        p.pointsCm = ring.pointsCm;
        const bool lit = ring.axis == highlightedAxis;
        p.colour = lit ? glm::mix(gizmoAxisColour(ring.axis), glm::vec3(1.0f, 0.95f, 0.6f), 0.55f)
                       : gizmoAxisColour(ring.axis);
        p.radiusCm = g.radiusCm * (lit ? 0.055f : 0.035f);
        p.onTop = true;
        scene.paths.push_back(std::move(p));
    }
}

int pickGizmoRing(const RotateGizmo& g, const OrbitCamera& camera, float x, float y, int w, int h, float slackPx) {
    int best = -1;
    float bestDistance = slackPx;
    const glm::vec2 mouse(x, y);
    for (const GizmoRing& ring : g.rings) {
        glm::vec3 prev(0.0f);
        bool havePrev = false;
        for (const glm::vec3& q : ring.pointsCm) {
            glm::vec3 pix(0.0f);
            const bool ok = camera.project(q, w, h, pix);
            if (ok && havePrev) {
                const float d = pixelSegmentDistance(mouse, glm::vec2(prev), glm::vec2(pix));
                if (d <= bestDistance) {
                    bestDistance = d;
                    best = ring.axis;
                }
            }
            prev = pix;
            havePrev = ok;
        }
    }
    return best;
}

const char* gizmoRingName(int axis) {
    switch (axis) {
        case 0: return "rx ring";
        case 1: return "ry ring";
        case 2: return "rz ring";
        case kViewRing: return "view ring";
        case kTrackball: return "free rotation";
        default: return "?";
    }
}

bool insideTrackball(const RotateGizmo& g, const OrbitCamera& camera, float x, float y, int w, int h) {
    if (g.rings.empty() || g.rings.back().axis != kViewRing || g.rings.back().pointsCm.empty()) return false;
    glm::vec3 pivot, rim;
    if (!camera.project(g.pivotCm, w, h, pivot) || !camera.project(g.rings.back().pointsCm.front(), w, h, rim))
        return false;
    const float radius = glm::length(glm::vec2(rim) - glm::vec2(pivot));
    return glm::length(glm::vec2(x, y) - glm::vec2(pivot)) < 0.92f * radius;
}

TrackballTurn trackballTurn(const OrbitCamera& camera, float dx, float dy) {
    const float pixels = std::sqrt(dx * dx + dy * dy);
    if (pixels <= 0.0f) return {};
    const glm::mat4 view = camera.view();
    const glm::vec3 right(view[0][0], view[1][0], view[2][0]), up(view[0][1], view[1][1], view[2][1]);
    // Screen y grows downwards: a drag right turns about up, a drag down about right.
    return {glm::normalize(dx * up + dy * right), 0.5f * pixels};
}

double gizmoSweepDeg(const RotateGizmo& g, int axis, const OrbitCamera& camera, float x0, float y0, float x1, float y1,
                     int w, int h) {
    const GizmoRing* ring = nullptr;
    for (const GizmoRing& r : g.rings)
        if (r.axis == axis) ring = &r;
    glm::vec3 pivot;
    if (!ring || !camera.project(g.pivotCm, w, h, pivot)) return 0.0;
    // Screen vectors from the pivot with y up, so that atan2 is counter-clockwise as seen.
    const glm::dvec2 a(x0 - pivot.x, pivot.y - y0), b(x1 - pivot.x, pivot.y - y1);
    if (glm::length(a) < 1e-6 || glm::length(b) < 1e-6) return 0.0;
    const double sweep = std::atan2(a.x * b.y - a.y * b.x, glm::dot(a, b)) * 57.29577951308232;
    const bool towardsViewer = glm::dot(ring->axisWorld, camera.eye() - g.pivotCm) > 0.0f;
    return towardsViewer ? sweep : -sweep;
}

}  // namespace mgp::render
