#pragma once
// Picking effector handles with a ray from a pixel (pure maths, no GL context).
#include <vector>

#include "render/camera.h"
#include "render/scene.h"

namespace mgp::render {

// Distance along the ray to the first hit of a sphere, or a negative value for a miss.
float raySphere(const Ray& ray, const glm::vec3& centreCm, float radiusCm);

// Index into `handles` of the nearest handle the ray hits, -1 for none. Each handle's sphere
// is grown by `slackCm` so small handles stay easy to grab.
int pickHandle(const std::vector<Handle>& handles, const Ray& ray, float slackCm = 1.0f);

// Distance (cm) between the ray (t ≥ 0) and the segment [a, b]; `along` gets the ray parameter of
// the closest point.
float raySegmentDistance(const Ray& ray, const glm::vec3& a, const glm::vec3& b, float* along = nullptr);
// Index into `segments` (bones as start/end pairs) of the one the ray passes within radiusCm of
// (a segment's own radiusCm where it has one), the nearest along the ray; -1 for none.
struct Segment {
    glm::vec3 a, b;
    float radiusCm = 0.0f;  // > 0: this segment's pick radius
};
int pickSegment(const std::vector<Segment>& segments, const Ray& ray, float radiusCm);

// Convenience: picks under pixel (x, y) (y down) of a width×height viewport.
int pickHandleAtPixel(const std::vector<Handle>& handles, const OrbitCamera& camera, float x, float y, int width,
                      int height, float slackCm = 1.0f);

}  // namespace mgp::render
