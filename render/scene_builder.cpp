#include "render/scene_builder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>

namespace mgp::render {

glm::vec3 toGlm(const Eigen::Vector3d& v) {
    return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

namespace {

struct BoneStyle {
    float startRadius, endRadius;
};

// Radii (cm) per ASF bone role without its side letter, for a ~170 cm adult.
BoneStyle styleOf(const std::string& role) {
    static const std::map<std::string, BoneStyle> table = {
        {"hipjoint", {4.2f, 4.8f}},  {"femur", {6.0f, 4.0f}},   {"tibia", {4.4f, 3.0f}},
        {"foot", {3.2f, 2.6f}},      {"toes", {2.6f, 1.8f}},    {"lowerback", {7.0f, 7.5f}},
        {"upperback", {7.5f, 8.5f}}, {"thorax", {8.5f, 6.0f}},  {"lowerneck", {4.0f, 3.6f}},
        {"upperneck", {3.6f, 3.4f}}, {"head", {3.4f, 3.0f}},    {"clavicle", {3.4f, 3.4f}},
        {"humerus", {4.2f, 3.2f}},   {"radius", {3.2f, 2.5f}},  {"wrist", {2.5f, 2.4f}},
        {"hand", {2.6f, 2.0f}},      {"fingers", {1.6f, 1.1f}}, {"thumb", {1.3f, 1.0f}},
    };
    std::string key = role;
    if (sideOfBone(role) != BodySide::kCentre) key = role.substr(1);
    auto it = table.find(key);
    return it != table.end() ? it->second : BoneStyle{3.0f, 2.5f};
}

}  // namespace

float boneRadiusCm(const std::string& boneRole) {
    const BoneStyle style = styleOf(boneRole);
    return std::max(style.startRadius, style.endRadius);
}

BodySide sideOfBone(const std::string& role) {
    if (role.size() < 2 || role == "root" || role == "lowerback" || role == "lowerneck") return BodySide::kCentre;
    if (role[0] == 'l') return BodySide::kLeft;
    if (role[0] == 'r') return BodySide::kRight;
    return BodySide::kCentre;
}

Figure makeFigure(const Skeleton& skeleton, const FkState& fk) {
    Figure fig;
    // Joints without an ASF role (BVH fingers, thumbs, extra spine joints) take their side from
    // the parent and are drawn thinner than it.
    std::vector<BodySide> sides(static_cast<std::size_t>(skeleton.jointCount()), BodySide::kCentre);
    std::vector<BoneStyle> styles(static_cast<std::size_t>(skeleton.jointCount()), BoneStyle{3.0f, 2.5f});
    for (int j = 0; j < skeleton.jointCount(); ++j) {
        const Joint& joint = skeleton.joints[j];
        const auto ju = static_cast<std::size_t>(j);
        if (!joint.bone.empty() || joint.parent < 0) {
            sides[ju] = sideOfBone(joint.bone);
            styles[ju] = styleOf(joint.bone);
        } else {
            const auto pu = static_cast<std::size_t>(joint.parent);
            sides[ju] = sides[pu];
            const float r = std::min(2.0f, 0.7f * styles[pu].endRadius);
            styles[ju] = {r, r};
        }
    }
    for (int j = 0; j < skeleton.jointCount(); ++j) {
        const Joint& joint = skeleton.joints[j];
        const glm::vec3 a = toGlm(fk.jointCm[j]);
        const glm::vec3 b = toGlm(boneEndCm(skeleton, fk, j));
        const BodySide side = sides[static_cast<std::size_t>(j)];
        const BoneStyle style = styles[static_cast<std::size_t>(j)];
        if (joint.bone == "head") {
            // The head as a ball around the head bone with the neck running into it.
            const glm::vec3 dir = glm::length(b - a) > 1e-3f ? glm::normalize(b - a) : glm::vec3(0, 1, 0);
            fig.joints.push_back({a + dir * 7.0f, 10.0f, side});
            continue;
        }
        if (glm::length(b - a) < 0.5f) continue;
        fig.bones.push_back({a, b, style.startRadius, style.endRadius, side});
        fig.joints.push_back({a, style.startRadius * 1.12f, side});
        // Close the open ends of chains (hands, toes, fingers) with a ball.
        bool hasChild = false;
        for (int k = j + 1; k < skeleton.jointCount() && !hasChild; ++k) hasChild = skeleton.joints[k].parent == j;
        if (!hasChild) fig.joints.push_back({b, style.endRadius, side});
    }
    return fig;
}

void translateFigure(Figure& figure, const glm::vec3& offset) {
    for (BoneSegment& b : figure.bones) {
        b.startCm += offset;
        b.endCm += offset;
    }
    for (JointBall& j : figure.joints) j.centreCm += offset;
}

std::vector<Handle> effectorHandles(const Skeleton& skeleton, const FkState& fk) {
    std::vector<Handle> out;
    for (int e = 0; e < kEffectorCount; ++e) {
        const auto eff = static_cast<Effector>(e);
        if (!skeleton.hasEffector(eff)) continue;
        Handle h;
        h.id = e;
        h.positionCm = toGlm(effectorCm(skeleton, fk, eff));
        h.radiusCm = eff == Effector::kHead ? 5.0f : 4.0f;
        out.push_back(h);
    }
    return out;
}

glm::vec3 characterForward(const Skeleton& skeleton, const FkState& fk) {
    const int l = skeleton.findBone("lfemur"), r = skeleton.findBone("rfemur");
    if (l < 0 || r < 0) return {0.0f, 0.0f, 1.0f};
    glm::vec3 right = toGlm(fk.jointCm[r] - fk.jointCm[l]);
    right.y = 0.0f;
    if (glm::length(right) < 1e-4f) return {0.0f, 0.0f, 1.0f};
    return glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), right));
}

Bounds sceneBounds(const Scene& scene) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    bool any = false;
    auto grow = [&](const glm::vec3& p, float r) {
        lo = glm::min(lo, p - glm::vec3(r));
        hi = glm::max(hi, p + glm::vec3(r));
        any = true;
    };
    for (const Figure& f : scene.figures) {
        for (const BoneSegment& b : f.bones) {
            grow(b.startCm, b.startRadiusCm);
            grow(b.endCm, b.endRadiusCm);
        }
        for (const JointBall& j : f.joints) grow(j.centreCm, j.radiusCm);
    }
    if (!any) return {};
    // Include the floor under the feet so the contact shadow stays in view.
    lo.y = std::min(lo.y, scene.groundHeightCm);
    Bounds b;
    b.centreCm = 0.5f * (lo + hi);
    b.radiusCm = std::max(20.0f, 0.5f * glm::length(hi - lo));
    return b;
}

float clipGroundHeight(const Clip& clip) {
    FkState fk;
    float lowest = std::numeric_limits<float>::max();
    std::vector<int> feet;
    for (int j = 0; j < clip.skeleton.jointCount(); ++j) {
        const std::string& role = clip.skeleton.joints[j].bone;
        if (role == "lfoot" || role == "rfoot" || role == "ltoes" || role == "rtoes") feet.push_back(j);
    }
    if (feet.empty() || clip.frames.empty()) return 0.0f;
    // A converter's rest frame (a T-pose, often below the capture's ground) does not stand on it.
    for (std::size_t t = clip.firstMotionFrame(); t < clip.frames.size(); ++t) {
        forwardKinematics(clip.skeleton, clip.frames[t], fk);
        for (int j : feet) {
            const float r = styleOf(clip.skeleton.joints[j].bone).endRadius;
            lowest = std::min(lowest, static_cast<float>(fk.jointCm[j].y()) - r);
            lowest = std::min(lowest, static_cast<float>(boneEndCm(clip.skeleton, fk, j).y()) - r);
        }
    }
    return lowest;
}

Path effectorPath(const Clip& clip, Effector e, int first, int last, int keyEvery, int current) {
    // The effector's motion trail, drawn as a path: the default thickness, keys instead of ticks.
    Path path = motionTrail(
        clip.skeleton, [&clip](int f) -> const Pose& { return clip.frames[f]; }, clip.frameCount(),
        static_cast<TrailPart>(static_cast<int>(e)), first, last, current, false);
    path.radiusCm = Path{}.radiusCm;
    path.tickRadiusCm = 0.0f;
    if (keyEvery > 0)
        for (std::size_t i = 0; i < path.pointsCm.size(); i += static_cast<std::size_t>(keyEvery))
            path.keysCm.push_back(path.pointsCm[i]);
    return path;
}

Scene buildClipScene(const Clip& clip, const ClipSceneOptions& o) {
    Scene scene;
    if (o.frameIndex < 0 || o.frameIndex >= clip.frameCount())
        throw std::out_of_range("buildClipScene: frame index " + std::to_string(o.frameIndex) + " outside 0.." +
                                std::to_string(clip.frameCount() - 1));
    const Pose& captured = clip.frames[o.frameIndex];
    FkState fk;
    forwardKinematics(clip.skeleton, o.editedPose ? *o.editedPose : captured, fk);
    scene.figures.push_back(makeFigure(clip.skeleton, fk));
    scene.groundHeightCm = clipGroundHeight(clip);
    scene.groundCentreCm = toGlm(fk.jointCm[0]);
    if (o.ghostCaptured) {
        FkState ghostFk;
        forwardKinematics(clip.skeleton, captured, ghostFk);
        Figure ghost = makeFigure(clip.skeleton, ghostFk);
        ghost.ghost = true;
        ghost.castsShadow = false;
        if (!o.editedPose) {
            const glm::vec3 fwd = characterForward(clip.skeleton, fk);
            const glm::vec3 left = glm::cross(fwd, glm::vec3(0.0f, 1.0f, 0.0f)) * -1.0f;
            translateFigure(ghost, left * o.ghostSideOffsetCm);
        }
        scene.figures.push_back(std::move(ghost));
    }
    if (o.handles) {
        scene.handles = effectorHandles(clip.skeleton, fk);
        for (Handle& h : scene.handles) {
            if (o.hovered && h.id == static_cast<int>(*o.hovered)) h.state = HandleState::kHover;
            if (o.selected && h.id == static_cast<int>(*o.selected)) h.state = HandleState::kSelected;
        }
    }
    for (Effector e : o.paths)
        scene.paths.push_back(effectorPath(clip, e, o.frameIndex - o.pathHalfSpan, o.frameIndex + o.pathHalfSpan,
                                           o.pathKeyEvery, o.frameIndex));
    if (o.onion)
        for (const OnionGhostFrame& g : onionFrames(*o.onion, o.frameIndex, clip.frameCount()))
            scene.figures.push_back(onionGhost(clip.skeleton, clip.frames[g.frame], g.step, *o.onion));
    const auto framePose = [&clip](int f) -> const Pose& { return clip.frames[f]; };
    const int half = std::clamp(o.trailHalfSpan, 1, clip.frameCount());  // no overflow for a huge span
    for (TrailPart part : o.trails)
        scene.paths.push_back(motionTrail(clip.skeleton, framePose, clip.frameCount(), part, o.frameIndex - half,
                                          o.frameIndex + half, o.frameIndex, false));
    if (o.gizmoJoint >= 0)
        addRotateGizmo(
            scene,
            rotateGizmo(clip.skeleton, o.editedPose ? *o.editedPose : captured, fk, o.gizmoJoint, o.gizmoRadiusCm), -1);
    if (o.caption)
        scene.caption = clip.name + "  frame " + std::to_string(o.frameIndex + 1) + "/" +
                        std::to_string(clip.frameCount()) + "  grid 1 m";
    return scene;
}

}  // namespace mgp::render
