#include "picking.h"

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

int pickHandleAtPixel(const std::vector<Handle>& handles, const OrbitCamera& camera, float x, float y, int width,
                      int height, float slackCm) {
    return pickHandle(handles, camera.rayFromPixel(x, y, width, height), slackCm);
}

}  // namespace mgp::render
