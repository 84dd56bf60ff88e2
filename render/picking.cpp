#include "render/picking.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mgp::render {

float raySphere(const Ray& ray, const glm::vec3& c, float r) {
    const glm::vec3 oc = ray.origin - c;
    const float b = glm::dot(oc, ray.direction);
    const float cc = glm::dot(oc, oc) - r * r;
    const float disc = b * b - cc;
    if (disc < 0.0f) return -1.0f;
    const float s = std::sqrt(disc);
    const float t0 = -b - s;
    if (t0 >= 0.0f) return t0;
    const float t1 = -b + s;  // origin inside the sphere
    return t1 >= 0.0f ? 0.0f : -1.0f;
}

int pickHandle(const std::vector<Handle>& handles, const Ray& ray, float slackCm) {
    int best = -1;
    float bestT = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < handles.size(); ++i) {
        const float t = raySphere(ray, handles[i].positionCm, handles[i].radiusCm + slackCm);
        if (t >= 0.0f && t < bestT) {
            bestT = t;
            best = static_cast<int>(i);
        }
    }
    return best;
}

float raySegmentDistance(const Ray& ray, const glm::vec3& a, const glm::vec3& b, float* along) {
    // Closest points of the lines, then clamped to the segment (s in [0, 1]) and the ray (t ≥ 0).
    const glm::vec3 u = b - a, v = ray.direction, w = a - ray.origin;
    const float uu = glm::dot(u, u), uv = glm::dot(u, v), vv = glm::dot(v, v), uw = glm::dot(u, w), vw = glm::dot(v, w);
    const float den = uu * vv - uv * uv;
    float s = den > 1e-9f * uu * vv ? (uv * vw - vv * uw) / den : 0.0f;
    s = glm::clamp(s, 0.0f, 1.0f);
    float t = std::max(0.0f, (uv * s + vw) / vv);
    if (uu > 0.0f) s = glm::clamp((t * uv - uw) / uu, 0.0f, 1.0f);
    t = std::max(0.0f, (uv * s + vw) / vv);
    if (along) *along = t;
    return glm::length((a + s * u) - (ray.origin + t * v));
}

int pickSegment(const std::vector<Segment>& segments, const Ray& ray, float radiusCm) {
    int best = -1;
    float bestT = 0.0f;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        float t = 0.0f;
        const float r = segments[i].radiusCm > 0.0f ? segments[i].radiusCm : radiusCm;
        if (raySegmentDistance(ray, segments[i].a, segments[i].b, &t) > r) continue;
        if (best < 0 || t < bestT) {
            best = static_cast<int>(i);
            bestT = t;
        }
    }
    return best;
}

int pickHandleAtPixel(const std::vector<Handle>& handles, const OrbitCamera& camera, float x, float y, int width,
                      int height, float slackCm) {
    return pickHandle(handles, camera.rayFromPixel(x, y, width, height), slackCm);
}

}  // namespace mgp::render
