// Onion skins and motion trails (motion_overlays.h).
#include "render/motion_overlays.h"

#include <algorithm>
#include <cstdlib>

#include "render/scene_builder.h"
#include "skeleton/forward_kinematics.h"

namespace mgp::render {

// A hand's, foot's or the head's TrailPart is its Effector (hasTrailPart, motionTrail cast).
static_assert(static_cast<int>(TrailPart::kLHand) == static_cast<int>(Effector::kLHand) &&
              static_cast<int>(TrailPart::kRHand) == static_cast<int>(Effector::kRHand) &&
              static_cast<int>(TrailPart::kLFoot) == static_cast<int>(Effector::kLFoot) &&
              static_cast<int>(TrailPart::kRFoot) == static_cast<int>(Effector::kRFoot) &&
              static_cast<int>(TrailPart::kHead) == static_cast<int>(Effector::kHead));

namespace {

constexpr float kOnionThickness = 0.5f;

OnionSkin clamped(const OnionSkin& o) {
    return {std::clamp(o.before, 0, kMaxOnionGhosts), std::clamp(o.after, 0, kMaxOnionGhosts),
            std::clamp(o.spacing, 1, kMaxOnionSpacing)};
}

// The colour of the trail of `part` (and of a clip's effector path, scene_builder.h): left parts
// blue, right parts magenta, the head green, the root amber.
glm::vec3 trailColour(TrailPart part) {
    switch (part) {
        case TrailPart::kLHand:
        case TrailPart::kLFoot: return {0.25f, 0.55f, 0.95f};
        case TrailPart::kRHand:
        case TrailPart::kRFoot: return {0.85f, 0.25f, 0.55f};
        case TrailPart::kHead: return {0.20f, 0.70f, 0.45f};
        default: return {0.90f, 0.70f, 0.20f};
    }
}

}  // namespace

std::vector<OnionGhostFrame> onionFrames(const OnionSkin& onion, int current, int frameCount) {
    const OnionSkin o = clamped(onion);
    std::vector<OnionGhostFrame> frames;
    for (int k = o.before; k >= 1; --k)
        if (current - k * o.spacing >= 0) frames.push_back({current - k * o.spacing, -k});
    for (int k = o.after; k >= 1; --k)
        if (current + k * o.spacing < frameCount) frames.push_back({current + k * o.spacing, k});
    return frames;
}

Figure onionGhost(const Skeleton& skeleton, const Pose& pose, int step, const OnionSkin& onion) {
    const OnionSkin o = clamped(onion);
    FkState fk;
    forwardKinematics(skeleton, pose, fk);
    Figure ghost = makeFigure(skeleton, fk);
    // Slim: bones at kOnionThickness of the figure's, so that the ghosts show where the limbs are
    // without hiding the figure or each other (and cost llvmpipe a fraction of the pixels).
    for (BoneSegment& b : ghost.bones) {
        b.startRadiusCm *= kOnionThickness;
        b.endRadiusCm *= kOnionThickness;
    }
    ghost.joints.clear();  // a slim bone's ends meet closely enough; llvmpipe pays per instance
    ghost.ghost = true;
    ghost.stillOverlay = true;  // another frame's pose: still while this one is posed
    ghost.castsShadow = false;
    // Green before, blue after, as Blender's onion skins (neither is a bone colour: the right
    // side is orange, the left grey); the nearest ghost 0.45 opaque, the farthest 0.20.
    ghost.ghostTint = step < 0 ? glm::vec3(0.40f, 0.92f, 0.30f) : glm::vec3(0.30f, 0.55f, 1.00f);
    const int n = std::max(1, step < 0 ? o.before : o.after);
    const float far = n > 1 ? static_cast<float>(std::abs(step) - 1) / static_cast<float>(n - 1) : 0.0f;
    ghost.ghostAlpha = 0.45f - 0.25f * far;
    return ghost;
}

const char* trailPartName(TrailPart part) {
    switch (part) {
        case TrailPart::kLHand: return "lhand";
        case TrailPart::kRHand: return "rhand";
        case TrailPart::kLFoot: return "lfoot";
        case TrailPart::kRFoot: return "rfoot";
        case TrailPart::kHead: return "head";
        case TrailPart::kRoot: return "root";
        default: return "?";
    }
}

bool parseTrailPart(const std::string& name, TrailPart& out) {
    for (int i = 0; i < kTrailPartCount; ++i)
        if (name == trailPartName(static_cast<TrailPart>(i))) {
            out = static_cast<TrailPart>(i);
            return true;
        }
    return false;
}

bool hasTrailPart(const Skeleton& skeleton, TrailPart part) {
    if (part == TrailPart::kRoot) return !skeleton.joints.empty();
    return skeleton.hasEffector(static_cast<Effector>(static_cast<int>(part)));
}

Path motionTrail(const Skeleton& skeleton, const std::function<const Pose&(int)>& poseAt, int frameCount,
                 TrailPart part, int first, int last, int current, bool captured) {
    FkState fk;
    const auto fkAt = [&](int f) -> const FkState& {
        forwardKinematics(skeleton, poseAt(f), fk);
        return fk;
    };
    return motionTrailFromFk(skeleton, fkAt, frameCount, part, first, last, current, captured);
}

Path motionTrailFromFk(const Skeleton& skeleton, const std::function<const FkState&(int)>& fkAt, int frameCount,
                       TrailPart part, int first, int last, int current, bool captured) {
    Path path;
    if (frameCount <= 0 || !hasTrailPart(skeleton, part)) return path;
    first = std::clamp(first, 0, frameCount - 1);
    last = std::clamp(last, first, frameCount - 1);
    for (int f = first; f <= last; ++f) {
        const FkState& fk = fkAt(f);
        const Eigen::Vector3d p = part == TrailPart::kRoot
                                      ? fk.jointCm[0]
                                      : effectorCm(skeleton, fk, static_cast<Effector>(static_cast<int>(part)));
        if (f == current) path.currentPoint = static_cast<int>(path.pointsCm.size());
        path.pointsCm.push_back(toGlm(p));
    }
    path.colour = captured ? glm::vec3(0.62f, 0.64f, 0.70f) : trailColour(part);
    // Ticks small enough to stay apart where a point moves 1–2 cm a frame (a walking foot at
    // 120 fps), so that the spacing shows.
    path.radiusCm = captured ? 0.25f : 0.35f;
    path.tickRadiusCm = captured ? 0.0f : 0.7f;
    if (captured) path.currentPoint = -1;
    return path;
}

std::vector<Path> splitForPosing(const Path& trail) {
    const int n = static_cast<int>(trail.pointsCm.size()), c = trail.currentPoint;
    Path still = trail;
    still.stillOverlay = true;
    still.currentPoint = -1;
    if (c < 0 || c >= n) return {still};
    std::vector<Path> pieces;
    auto piece = [&](Path base, int first, int last) {  // points first..last, if any
        if (first > last) return;
        base.pointsCm.assign(trail.pointsCm.begin() + first, trail.pointsCm.begin() + last + 1);
        if (base.currentPoint >= 0) base.currentPoint = c - first;
        pieces.push_back(std::move(base));
    };
    piece(still, 0, c - 1);
    Path live = trail;
    live.stillOverlay = false;
    piece(live, std::max(0, c - 1), std::min(n - 1, c + 1));
    piece(still, c + 1, n - 1);
    return pieces;
}

std::vector<Path> splitEachForPosing(const std::vector<Path>& paths) {
    std::vector<Path> pieces;
    for (const Path& p : paths)
        for (Path& piece : splitForPosing(p)) pieces.push_back(std::move(piece));
    return pieces;
}

std::vector<Path> differingParts(const Path& reference, const Path& other, float toleranceCm) {
    const std::size_t n = reference.pointsCm.size();
    if (other.pointsCm.size() != n) return {reference};
    std::vector<bool> keep(n, false);
    for (std::size_t i = 0; i < n; ++i)
        if (glm::length(reference.pointsCm[i] - other.pointsCm[i]) > toleranceCm)
            for (std::size_t k = i > 0 ? i - 1 : 0; k <= std::min(n - 1, i + 1); ++k) keep[k] = true;
    std::vector<Path> parts;
    for (std::size_t i = 0; i < n; ++i) {
        if (!keep[i]) continue;
        if (i == 0 || !keep[i - 1]) {
            parts.push_back(reference);
            parts.back().pointsCm.clear();
            parts.back().currentPoint = -1;
        }
        parts.back().pointsCm.push_back(reference.pointsCm[i]);
    }
    return parts;
}

}  // namespace mgp::render
