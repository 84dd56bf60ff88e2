// Camera maths: no GL context needed.
#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>

#include "render/camera.h"

using namespace mgp::render;

namespace {
float dist(const glm::vec3& a, const glm::vec3& b) { return glm::length(a - b); }
}  // namespace

TEST_CASE("camera: eye sits at the distance, yaw 0 looks down -Z") {
    OrbitCamera c;
    c.targetCm = {10, 90, -5};
    c.yawDeg = 0;
    c.pitchDeg = 0;
    c.distanceCm = 300;
    CHECK(dist(c.eye(), {10, 90, 295}) < 1e-3f);
    c.pitchDeg = 30;
    CHECK(dist(c.eye(), c.targetCm) == doctest::Approx(300).epsilon(1e-5));
    CHECK(c.eye().y == doctest::Approx(90 + 150).epsilon(1e-5));
}

TEST_CASE("camera: the centre pixel's ray passes through the target") {
    OrbitCamera c;
    c.yawDeg = 37;
    c.pitchDeg = 21;
    c.distanceCm = 420;
    const Ray r = c.rayFromPixel(320, 240, 640, 480);
    CHECK(glm::length(r.direction) == doctest::Approx(1.0f).epsilon(1e-5));
    const glm::vec3 toTarget = c.targetCm - r.origin;
    const glm::vec3 closest = r.origin + glm::dot(toTarget, r.direction) * r.direction;
    CHECK(dist(closest, c.targetCm) < 1e-2f);
}

TEST_CASE("camera: project and rayFromPixel are inverse") {
    OrbitCamera c;
    c.yawDeg = -60;
    c.pitchDeg = 15;
    const glm::vec3 p(35, 140, 20);
    glm::vec3 px;
    REQUIRE(c.project(p, 800, 600, px));
    CHECK(px.z > 0.0f);
    CHECK(px.z < 1.0f);
    const Ray r = c.rayFromPixel(px.x, px.y, 800, 600);
    const glm::vec3 closest = r.origin + glm::dot(p - r.origin, r.direction) * r.direction;
    CHECK(dist(closest, p) < 0.05f);
    // A point above the target appears above the centre (pixel y grows downwards).
    glm::vec3 above;
    REQUIRE(c.project(c.targetCm + glm::vec3(0, 50, 0), 800, 600, above));
    CHECK(above.y < 300.0f);
    // A point behind the eye does not project.
    glm::vec3 behind;
    CHECK_FALSE(c.project(c.eye() + (c.eye() - c.targetCm), 800, 600, behind));
}

TEST_CASE("camera: orbit clamps pitch, zoom clamps distance, pan keeps the view direction") {
    OrbitCamera c;
    c.orbit(10, 200);
    CHECK(c.pitchDeg == doctest::Approx(89));
    c.orbit(0, -500);
    CHECK(c.pitchDeg == doctest::Approx(-89));
    c.pitchDeg = 10;
    c.distanceCm = 400;
    c.zoom(0.5f);
    CHECK(c.distanceCm == doctest::Approx(200));
    c.zoom(1e-6f);
    CHECK(c.distanceCm == doctest::Approx(10));
    c.distanceCm = 400;
    const glm::vec3 before = c.targetCm;
    const glm::vec3 dirBefore = glm::normalize(c.targetCm - c.eye());
    // Dragging right by 100 px: the point that was under the cursor follows it.
    glm::vec3 px0;
    REQUIRE(c.project(before, 800, 600, px0));
    c.pan(100, 0, 600);
    glm::vec3 px1;
    REQUIRE(c.project(before, 800, 600, px1));
    CHECK(px1.x - px0.x == doctest::Approx(100).epsilon(1e-3));
    CHECK(px1.y - px0.y == doctest::Approx(0).epsilon(1e-3));
    CHECK(dist(glm::normalize(c.targetCm - c.eye()), dirBefore) < 1e-5f);
}

TEST_CASE("camera: framing fits the sphere in the narrower field of view") {
    for (float aspect : {0.5f, 1.0f, 16.0f / 9.0f}) {
        OrbitCamera c;
        c.yawDeg = 25;
        c.frame({0, 90, 0}, 100, aspect, 1.0f);
        const int h = 600, w = static_cast<int>(600 * aspect);
        // The sphere's extreme points along the camera's right and up axes land in the image.
        const glm::mat4 v = c.view();
        const glm::vec3 right(v[0][0], v[1][0], v[2][0]), up(v[0][1], v[1][1], v[2][1]);
        for (const glm::vec3& p : {c.targetCm + 100.0f * right, c.targetCm - 100.0f * right, c.targetCm + 100.0f * up,
                                   c.targetCm - 100.0f * up}) {
            glm::vec3 px;
            REQUIRE(c.project(p, w, h, px));
            CHECK(px.x >= -1.0f);
            CHECK(px.x <= w + 1.0f);
            CHECK(px.y >= -1.0f);
            CHECK(px.y <= h + 1.0f);
        }
    }
}

TEST_CASE("camera: presets are placed relative to where the character faces") {
    const glm::vec3 forward = glm::normalize(glm::vec3(1, 0, 1));
    const OrbitCamera front = presetCamera(CameraPreset::kFront, forward, {0, 90, 0}, 100, 4.0f / 3.0f);
    glm::vec3 toEye = front.eye() - front.targetCm;
    toEye.y = 0;
    CHECK(glm::dot(glm::normalize(toEye), forward) > 0.99f);
    const OrbitCamera side = presetCamera(CameraPreset::kSide, forward, {0, 90, 0}, 100, 4.0f / 3.0f);
    toEye = side.eye() - side.targetCm;
    toEye.y = 0;
    const glm::vec3 right = glm::cross(forward, glm::vec3(0, 1, 0));  // the character's right
    CHECK(glm::dot(glm::normalize(toEye), right) > 0.99f);
    CameraPreset p{};
    CHECK(parseCameraPreset("three-quarter", p));
    CHECK(p == CameraPreset::kThreeQuarter);
    CHECK_FALSE(parseCameraPreset("top", p));
}
