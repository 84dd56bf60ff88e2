// Picking effector handles with a ray from a pixel: no GL context needed.
#include <doctest/doctest.h>

#include "render/picking.h"

using namespace mgp::render;

TEST_CASE("picking: ray-sphere hits, misses and starts inside") {
    const Ray r{{0, 0, 0}, {0, 0, -1}};
    CHECK(raySphere(r, {0, 0, -10}, 2) == doctest::Approx(8));
    CHECK(raySphere(r, {3, 0, -10}, 2) < 0);
    CHECK(raySphere(r, {0, 0, 10}, 2) < 0);  // behind the origin
    CHECK(raySphere(r, {0, 0, 0}, 2) == doctest::Approx(0));
}

TEST_CASE("picking: the nearest handle under the pixel wins") {
    OrbitCamera cam;
    cam.targetCm = {0, 100, 0};
    cam.yawDeg = 0;
    cam.pitchDeg = 0;
    cam.distanceCm = 300;
    std::vector<Handle> handles(3);
    handles[0].id = 10;
    handles[0].positionCm = {0, 100, -50};  // behind handle 1 on the same line of sight
    handles[1].id = 11;
    handles[1].positionCm = {0, 100, 20};
    handles[2].id = 12;
    handles[2].positionCm = {60, 140, 0};
    const int w = 640, h = 480;
    CHECK(pickHandleAtPixel(handles, cam, w / 2.0f, h / 2.0f, w, h) == 1);
    glm::vec3 px;
    REQUIRE(cam.project(handles[2].positionCm, w, h, px));
    CHECK(pickHandleAtPixel(handles, cam, px.x, px.y, w, h) == 2);
    // Just outside the handle's radius (plus slack) in pixels: nothing.
    CHECK(pickHandleAtPixel(handles, cam, px.x + 40.0f, px.y, w, h) == -1);
    CHECK(pickHandleAtPixel(handles, cam, 5, 5, w, h) == -1);
    CHECK(pickHandle({}, cam.rayFromPixel(1, 1, w, h)) == -1);
}

TEST_CASE("picking: ray to segment distance, and the nearest bone under the ray wins") {
    const Ray ray{glm::vec3(0, 0, 10), glm::vec3(0, 0, -1)};
    // A segment crossing the ray 2 cm to the side, 10 cm ahead.
    float t = -1.0f;
    CHECK(raySegmentDistance(ray, glm::vec3(2, -5, 0), glm::vec3(2, 5, 0), &t) == doctest::Approx(2.0f).epsilon(1e-6));
    CHECK(t == doctest::Approx(10.0f).epsilon(1e-6));
    // Clamped to the segment's end, and to the ray's start (behind the origin does not count).
    CHECK(raySegmentDistance(ray, glm::vec3(3, 4, 0), glm::vec3(3, 10, 0)) == doctest::Approx(5.0f).epsilon(1e-6));
    CHECK(raySegmentDistance(ray, glm::vec3(-5, 0, 20), glm::vec3(5, 0, 20), &t) ==
          doctest::Approx(10.0f).epsilon(1e-6));
    CHECK(t == 0.0f);
    // Parallel to the ray.
    CHECK(raySegmentDistance(ray, glm::vec3(1, 0, 0), glm::vec3(1, 0, -5)) == doctest::Approx(1.0f).epsilon(1e-6));
    const std::vector<Segment> bones{{glm::vec3(1, -5, -20), glm::vec3(1, 5, -20)},  // behind the next one
                                     {glm::vec3(-1, -5, 0), glm::vec3(-1, 5, 0)},
                                     {glm::vec3(8, -5, 5), glm::vec3(8, 5, 5)}};  // too far to the side
    CHECK(pickSegment(bones, ray, 3.0f) == 1);
    CHECK(pickSegment(bones, ray, 0.5f) == -1);
    // A segment's own radius replaces the call's: a thin front bone is missed, the thick one behind it is hit.
    const std::vector<Segment> sized{{glm::vec3(1, -5, -20), glm::vec3(1, 5, -20), 1.5f},
                                     {glm::vec3(-2, -5, 0), glm::vec3(-2, 5, 0), 1.0f}};
    CHECK(pickSegment(sized, ray, 3.0f) == 0);
    CHECK(pickSegment(sized, ray, 0.5f) == 0);
}
