#pragma once
// What the viewport shows, as plain data (no GL): the ui/ layer and the CLI fill a Scene and
// SceneRenderer draws it. World is Y up, right-handed, centimetres (docs/maths.md, conventions).
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace mgp::render {

// Which side of the body a bone belongs to: left bones (ASF roles starting with 'l') are drawn
// grey as in the paper, right bones in a warm colour, the spine and head neutral.
enum class BodySide { kCentre, kLeft, kRight };

struct BoneSegment {
    glm::vec3 startCm{0.0f};
    glm::vec3 endCm{0.0f};
    float startRadiusCm = 3.0f;  // tapered solid: start radius ...
    float endRadiusCm = 2.0f;    // ... to end radius
    BodySide side = BodySide::kCentre;
};

struct JointBall {
    glm::vec3 centreCm{0.0f};
    float radiusCm = 3.0f;
    BodySide side = BodySide::kCentre;
};

// One posed skeleton. A ghost is drawn semi-transparent in one tint (e.g. the captured pose
// beside the edited one, or a second model side by side).
struct Figure {
    std::vector<BoneSegment> bones;
    std::vector<JointBall> joints;
    bool ghost = false;
    glm::vec3 ghostTint{0.45f, 0.62f, 0.95f};
    float ghostAlpha = 0.35f;
    bool castsShadow = true;
    // A solid figure's bones and joints are drawn mix(side colour, tint, tintWeight): how far the
    // pose lies outside the model's training range (render/range_tint.h); 0 = the side colours.
    glm::vec3 tint{0.0f};
    float tintWeight = 0.0f;
    // Part of the still overlays (an onion skin): see Path::stillOverlay.
    bool stillOverlay = false;
};

// The colour a solid figure's bone or joint of side colour `base` is drawn in.
inline glm::vec3 tintedColour(const glm::vec3& base, const Figure& f) {
    if (!(f.tintWeight > 0.0f)) return base;  // exactly the side colour: untinted goldens stay
    if (f.tintWeight >= 1.0f) return f.tint;
    return base + (f.tint - base) * f.tintWeight;
}

enum class HandleState { kIdle, kHover, kSelected };

// A draggable effector handle (hands, feet, head); `id` is the caller's (e.g. the Effector).
struct Handle {
    int id = 0;
    glm::vec3 positionCm{0.0f};
    float radiusCm = 4.5f;
    HandleState state = HandleState::kIdle;
};

// An IK target; when `fromCm` is set a thin line joins the effector to it.
struct Target {
    glm::vec3 positionCm{0.0f};
    bool hasFrom = false;
    glm::vec3 fromCm{0.0f};
    bool reached = false;
};

// A pinned effector (e.g. a planted foot): a pin stands on this point.
struct Pin {
    glm::vec3 positionCm{0.0f};
};

// A hand, foot or head an earlier edit placed on this frame, which later gestures hold there until
// the user releases it: an amber ring around it, level with the ground (a pin stands on its point,
// a footprint lies on the ground).
struct HeldMark {
    glm::vec3 positionCm{0.0f};
};

// A planted foot (a detected ground contact held by the IK and regeneration): a flat green disc
// on the ground under the foot.
struct Footprint {
    glm::vec3 positionCm{0.0f};  // the foot; the disc is drawn at ground height below it
};

// A polyline (an effector trajectory, e.g. a Hermite curve) with optional key points and a
// highlighted current point.
struct Path {
    std::vector<glm::vec3> pointsCm;
    std::vector<glm::vec3> keysCm;
    glm::vec3 colour{0.20f, 0.55f, 0.95f};
    int currentPoint = -1;  // index into pointsCm, -1 for none
    float radiusCm = 0.6f;
    int hoveredKey = -1;        // index into keysCm drawn in the handle hover colour, -1 for none
    int selectedKey = -1;       // index into keysCm drawn in the handle selected colour, -1 for none
    float tickRadiusCm = 0.0f;  // > 0: a tick (a small ball) on every point, e.g. one per frame
    bool onTop = false;         // drawn over everything else (a gizmo), not hidden by the body
    // Key balls are this big (the editor picks keys with the same radius); the editor sets
    // minKeyRadiusCm so that a key stays large enough to grab when the camera is far away.
    float minKeyRadiusCm = 0.0f;
    // Part of the still overlays (a trail's stretch away from the current frame): content that
    // stays put while the current frame is posed. A renderer without MSAA keeps them in a cached
    // layer drawn again only when they or the view change (render/overlay_layer.h); with MSAA
    // (stills) they are drawn as any other path.
    bool stillOverlay = false;
    float keyRadiusCm() const { return radiusCm * 3.2f > minKeyRadiusCm ? radiusCm * 3.2f : minKeyRadiusCm; }
};

struct Scene {
    std::vector<Figure> figures;
    std::vector<Handle> handles;
    std::vector<Target> targets;
    std::vector<Pin> pins;
    std::vector<HeldMark> heldMarks;
    std::vector<Footprint> footprints;
    std::vector<Path> paths;
    float groundHeightCm = 0.0f;
    bool showGround = true;
    glm::vec3 groundCentreCm{0.0f};  // the grid is centred (snapped to 1 m) under this point
    std::string caption;             // drawn at the bottom-left ("" for none)
};

}  // namespace mgp::render
