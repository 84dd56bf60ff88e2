#pragma once
// Orbit camera (pure maths, no GL context needed): a target point, yaw/pitch about it and a
// distance. World is Y up, right-handed, centimetres (docs/maths.md, conventions). Pixels: x to the right,
// y DOWN from the top-left corner of the viewport (as windows and PNG rows report them).
#include <glm/glm.hpp>

namespace mgp::render {

struct Ray {
    glm::vec3 origin;     // cm
    glm::vec3 direction;  // unit
};

enum class CameraPreset { kFront, kSide, kThreeQuarter };
// "front" | "side" | "three-quarter"; false if unknown.
bool parseCameraPreset(const char* name, CameraPreset& out);
const char* cameraPresetName(CameraPreset p);

struct OrbitCamera {
    glm::vec3 targetCm{0.0f, 90.0f, 0.0f};
    // Yaw: rotation about +Y of the eye around the target; yaw 0 puts the eye on +Z looking
    // towards -Z. Pitch: elevation of the eye above the target's horizontal plane (degrees).
    float yawDeg = 0.0f;
    float pitchDeg = 10.0f;
    float distanceCm = 400.0f;
    float fovYDeg = 35.0f;

    glm::vec3 eye() const;
    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;  // near/far follow the distance
    glm::mat4 viewProjection(float aspect) const { return projection(aspect) * view(); }

    // Interaction (what the viewport maps mouse drags and the wheel to).
    void orbit(float dYawDeg, float dPitchDeg);  // pitch clamped to ±89°
    // Moves target and eye together so the scene follows the mouse: pixels at the target's depth.
    void pan(float dxPixels, float dyPixels, int viewportHeight);
    void zoom(float factor);  // distance *= factor (factor < 1 zooms in), clamped to [10, 1e5] cm

    // Centres on a bounding sphere and sets the distance so it fits the viewport with a margin.
    void frame(const glm::vec3& centreCm, float radiusCm, float aspect, float margin = 1.1f);

    // How many cm one pixel spans at the depth of world point `atCm` (its distance along the view
    // direction) in a viewport `viewportHeight` pixels high.
    float cmPerPixel(const glm::vec3& atCm, int viewportHeight) const;
    // The ray through pixel (x, y) (pixel centres at +0.5) of a width×height viewport.
    Ray rayFromPixel(float x, float y, int width, int height) const;
    // World point -> pixel (x right, y down) and depth in [0,1]; false if behind the eye.
    bool project(const glm::vec3& worldCm, int width, int height, glm::vec3& pixelAndDepth) const;
};

// The camera of a preset, placed relative to a character that faces `forward` (a horizontal
// direction; the front camera looks at the character's face), framing the given sphere.
OrbitCamera presetCamera(CameraPreset preset, const glm::vec3& forward, const glm::vec3& centreCm, float radiusCm,
                         float aspect);

}  // namespace mgp::render
