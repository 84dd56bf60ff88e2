#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>

namespace mgp::render {

bool parseCameraPreset(const char* name, CameraPreset& out) {
    if (std::strcmp(name, "front") == 0)
        out = CameraPreset::kFront;
    else if (std::strcmp(name, "side") == 0)
        out = CameraPreset::kSide;
    else if (std::strcmp(name, "three-quarter") == 0)
        out = CameraPreset::kThreeQuarter;
    else
        return false;
    return true;
}

const char* cameraPresetName(CameraPreset p) {
    switch (p) {
        case CameraPreset::kFront: return "front";
        case CameraPreset::kSide: return "side";
        case CameraPreset::kThreeQuarter: return "three-quarter";
    }
    return "?";
}

glm::vec3 OrbitCamera::eye() const {
    const float yaw = glm::radians(yawDeg), pitch = glm::radians(pitchDeg);
    const glm::vec3 dir(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
    return targetCm + distanceCm * dir;
}

glm::mat4 OrbitCamera::view() const { return glm::lookAt(eye(), targetCm, glm::vec3(0.0f, 1.0f, 0.0f)); }

glm::mat4 OrbitCamera::projection(float aspect) const {
    const float nearCm = std::max(1.0f, distanceCm * 0.02f);
    const float farCm = distanceCm * 20.0f + 2000.0f;
    return glm::perspective(glm::radians(fovYDeg), aspect, nearCm, farCm);
}

void OrbitCamera::orbit(float dYawDeg, float dPitchDeg) {
    yawDeg = std::fmod(yawDeg + dYawDeg, 360.0f);
    pitchDeg = std::clamp(pitchDeg + dPitchDeg, -89.0f, 89.0f);
}

float OrbitCamera::cmPerPixel(const glm::vec3& atCm, int viewportHeight) const {
    const float depth = glm::dot(atCm - eye(), glm::normalize(targetCm - eye()));
    return 2.0f * depth * std::tan(glm::radians(fovYDeg) * 0.5f) / static_cast<float>(std::max(1, viewportHeight));
}

void OrbitCamera::pan(float dxPixels, float dyPixels, int viewportHeight) {
    const float cmPerPixel = this->cmPerPixel(targetCm, viewportHeight);  // at the target's depth
    const glm::mat4 v = view();
    const glm::vec3 right(v[0][0], v[1][0], v[2][0]);
    const glm::vec3 up(v[0][1], v[1][1], v[2][1]);
    // Dragging right moves the scene right, i.e. the camera left.
    targetCm += (-dxPixels * right + dyPixels * up) * cmPerPixel;
}

void OrbitCamera::zoom(float factor) { distanceCm = std::clamp(distanceCm * factor, 10.0f, 1e5f); }

void OrbitCamera::frame(const glm::vec3& centreCm, float radiusCm, float aspect, float margin) {
    targetCm = centreCm;
    const float halfY = glm::radians(fovYDeg) * 0.5f;
    const float halfX = std::atan(std::tan(halfY) * aspect);
    const float half = std::min(halfY, halfX);
    distanceCm = std::max(10.0f, margin * radiusCm / std::sin(half));
}

Ray OrbitCamera::rayFromPixel(float x, float y, int width, int height) const {
    const float aspect = static_cast<float>(width) / static_cast<float>(std::max(1, height));
    const glm::mat4 inv = glm::inverse(viewProjection(aspect));
    const float ndcX = 2.0f * x / static_cast<float>(width) - 1.0f;
    const float ndcY = 1.0f - 2.0f * y / static_cast<float>(height);
    glm::vec4 nearP = inv * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
    glm::vec4 farP = inv * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    nearP /= nearP.w;
    farP /= farP.w;
    return {glm::vec3(nearP), glm::normalize(glm::vec3(farP - nearP))};
}

bool OrbitCamera::project(const glm::vec3& worldCm, int width, int height, glm::vec3& out) const {
    const float aspect = static_cast<float>(width) / static_cast<float>(std::max(1, height));
    const glm::vec4 clip = viewProjection(aspect) * glm::vec4(worldCm, 1.0f);
    if (clip.w <= 0.0f) return false;
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    out = {(ndc.x + 1.0f) * 0.5f * static_cast<float>(width), (1.0f - ndc.y) * 0.5f * static_cast<float>(height),
           (ndc.z + 1.0f) * 0.5f};
    return true;
}

OrbitCamera presetCamera(CameraPreset preset, const glm::vec3& forward, const glm::vec3& centreCm, float radiusCm,
                         float aspect) {
    glm::vec3 f(forward.x, 0.0f, forward.z);
    if (glm::length(f) < 1e-6f) f = glm::vec3(0.0f, 0.0f, 1.0f);
    f = glm::normalize(f);
    const float faceYaw = glm::degrees(std::atan2(f.x, f.z));  // eye on the character's front
    OrbitCamera cam;
    switch (preset) {
        case CameraPreset::kFront:
            cam.yawDeg = faceYaw;
            cam.pitchDeg = 8.0f;
            break;
        case CameraPreset::kSide:  // the character's right side, so its right limbs are nearest
            cam.yawDeg = faceYaw - 90.0f;
            cam.pitchDeg = 8.0f;
            break;
        case CameraPreset::kThreeQuarter:
            cam.yawDeg = faceYaw - 40.0f;
            cam.pitchDeg = 20.0f;
            break;
    }
    cam.yawDeg = std::fmod(cam.yawDeg + 360.0f, 360.0f);
    cam.frame(centreCm, radiusCm, aspect);
    return cam;
}

}  // namespace mgp::render
