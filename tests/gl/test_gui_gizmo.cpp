// The rotate gizmo in the viewport, driven with synthetic mouse input offscreen: a ring turns its
// one Euler channel by the angle the mouse sweeps around the joint on screen (within 0.5°), Ctrl
// snaps the change to 5° steps, Esc cancels, the result is one undo step, and a click on the thigh
// picks the thigh.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "editor_harness.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/rotation.h"
#include "ui/panels/viewport_panel.h"
#include "ui/shell/editor_app.h"
#include "ui/windows/joint_rotation_window.h"

using namespace mgp;
using test::makeHarness;

namespace {

struct RingGrip {
    float x = 0, y = 0;            // a window pixel on the ring, clear of the other rings
    float pivotX = 0, pivotY = 0;  // the joint's window pixel
};

Eigen::Vector3d gizmoEigen(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// Distance from window pixel (x, y) to the projected outline of `ring`.
float pixelsToRing(const ui::EditorState& s, const render::GizmoRing& ring, float x, float y) {
    float best = 1e9f;
    for (std::size_t i = 1; i < ring.pointsCm.size(); ++i) {
        float ax, ay, bx, by;
        if (!ui::viewportWindowPosition(s, gizmoEigen(ring.pointsCm[i - 1]), ax, ay) ||
            !ui::viewportWindowPosition(s, gizmoEigen(ring.pointsCm[i]), bx, by))
            continue;
        const float vx = bx - ax, vy = by - ay, len2 = vx * vx + vy * vy;
        const float t = len2 > 0 ? std::clamp(((x - ax) * vx + (y - ay) * vy) / len2, 0.0f, 1.0f) : 0.0f;
        best = std::min(best, std::hypot(x - (ax + t * vx), y - (ay + t * vy)));
    }
    return best;
}

// A point of ring `axis` at least 15 px from the other rings and 40 px from the pivot.
RingGrip gripOf(const ui::EditorState& s, const render::RotateGizmo& g, int axis) {
    RingGrip grip;
    REQUIRE(ui::viewportWindowPosition(s, gizmoEigen(g.pivotCm), grip.pivotX, grip.pivotY));
    for (const render::GizmoRing& ring : g.rings) {
        if (ring.axis != axis) continue;
        for (const glm::vec3& q : ring.pointsCm) {
            float x, y;
            if (!ui::viewportWindowPosition(s, gizmoEigen(q), x, y)) continue;
            if (std::hypot(x - grip.pivotX, y - grip.pivotY) < 40.0f) continue;
            bool clear = true;
            for (const render::GizmoRing& other : g.rings)
                if (other.axis != axis && pixelsToRing(s, other, x, y) < 15.0f) clear = false;
            if (clear) {
                grip.x = x;
                grip.y = y;
                return grip;
            }
        }
    }
    FAIL("no point of ring " << axis << " lies clear of the others");
    return grip;
}

// The angle (degrees, counter-clockwise on screen) from pixel (x0, y0) to (x1, y1) round the grip's
// pivot, with both pixels floored as ImGui floors the mouse position.
double screenSweepDeg(const RingGrip& g, float x0, float y0, float x1, float y1) {
    const double ax = std::floor(x0) - g.pivotX, ay = g.pivotY - std::floor(y0);
    const double bx = std::floor(x1) - g.pivotX, by = g.pivotY - std::floor(y1);
    return std::atan2(ax * by - ay * bx, ax * bx + ay * by) * 180.0 / 3.14159265358979;
}

// Presses on the grip, sweeps the mouse `degrees` counter-clockwise on screen round the pivot in
// 10 moves (Ctrl held if `ctrl`), and releases unless `release` is false. Returns the sweep the
// editor saw (the mouse positions floored).
double sweep(test::Harness& h, const RingGrip& g, double degrees, bool ctrl, bool release = true) {
    h.input.mouseX = g.x;
    h.input.mouseY = g.y;
    h.frame(2);
    if (ctrl) h.input.setKey(ui::key::kLeftCtrl, true);
    h.input.setButton(0, true);
    h.frame(1);
    const double r = std::hypot(g.x - g.pivotX, g.y - g.pivotY);
    const double start = std::atan2(-(g.y - g.pivotY), g.x - g.pivotX);  // y up: counter-clockwise positive
    for (int k = 1; k <= 10; ++k) {
        const double a = start + degrees * k / 10.0 * 3.14159265358979 / 180.0;
        h.input.mouseX = static_cast<float>(g.pivotX + r * std::cos(a));
        h.input.mouseY = static_cast<float>(g.pivotY - r * std::sin(a));
        h.frame(1);
    }
    const double seen = screenSweepDeg(g, g.x, g.y, h.input.mouseX, h.input.mouseY);
    if (!release) return seen;
    h.input.setButton(0, false);
    h.frame(2);
    if (ctrl) h.input.setKey(ui::key::kLeftCtrl, false);
    h.frame(2);
    return seen;
}

// The knee's screen angle (degrees, counter-clockwise, y up) round the hip as the viewport shows it.
double kneeScreenDeg(const ui::EditorState& s, int femur, const RingGrip& g) {
    const Skeleton& sk = s.doc.clip().skeleton;
    FkState fk;
    forwardKinematics(sk, s.doc.currentPose(), fk);
    float x = 0, y = 0;
    REQUIRE(ui::viewportWindowPosition(s, boneEndCm(sk, fk, femur), x, y));
    return std::atan2(-(y - g.pivotY), x - g.pivotX) * 180.0 / 3.14159265358979;
}

// Frame 60 of the walk with the Rotate joint window on the right thigh: its gizmo is up. Returns
// the thigh's joint.
int gizmoOnRightThigh(test::Harness& h) {
    EditorDocument& doc = h.app->state().doc;
    doc.setFrame(60);
    const int femur = doc.clip().skeleton.findBone("rfemur");
    REQUIRE(femur >= 0);
    h.app->jointWindow().selectJoint(femur);
    h.frame(3);
    REQUIRE(h.app->state().gizmoJoint == femur);
    return femur;
}

}  // namespace

TEST_CASE("gui gizmo: a ring turns its one angle by the mouse's sweep, Ctrl snaps to 5 degrees, one undo step") {
    auto h = makeHarness(false, false);  // no model: the rotation is exactly the joint's angles
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    const int femur = gizmoOnRightThigh(*h);
    const render::RotateGizmo g = ui::viewportGizmo(s);
    REQUIRE(g.rings.size() == 4);  // rfemur animates rx ry rz: three rings and the view ring
    CHECK(g.rings.back().axis == render::kViewRing);
    CHECK(h->app->viewport().lastScene().paths.size() == 5);  // the highlighted bone and four rings

    int kneeChecks = 0;  // rings whose turn moves the knee visibly on screen
    for (int axis = 0; axis < 3; ++axis) {
        CAPTURE(axis);
        const render::GizmoRing& ring = g.rings[static_cast<std::size_t>(axis)];
        const bool towards = glm::dot(ring.axisWorld, s.camera.eye() - g.pivotCm) > 0.0f;
        const Eigen::Vector3d before = doc.currentPose().anglesDeg[femur];
        const int undoBefore = doc.history().undoCount();
        const RingGrip grip = gripOf(s, ui::viewportGizmo(s), axis);
        const double kneeBefore = kneeScreenDeg(s, femur, grip);
        const double seen = sweep(*h, grip, 30.0, false);
        // The limb follows the mouse round the joint on screen (checked on the picture, not with
        // the code's own sign rule): where the knee visibly turns, it turns the way the mouse went.
        const double kneeTurn = wrap180(kneeScreenDeg(s, femur, grip) - kneeBefore);
        INFO("the knee turned " << kneeTurn << " deg on screen for a mouse sweep of " << seen);
        if (std::abs(kneeTurn) > 3.0) {
            CHECK(kneeTurn * seen > 0.0);
            ++kneeChecks;
        }
        CHECK(std::abs(seen - 30.0) < 2.0);  // 30° less what flooring the pixels took off
        const Eigen::Vector3d after = doc.currentPose().anglesDeg[femur];
        // Counter-clockwise on screen is a positive turn about an axis that points at the viewer.
        const double expected = towards ? seen : -seen;
        INFO("the angle changed by " << after[axis] - before[axis] << " deg, expected " << expected);
        CHECK(std::abs(after[axis] - before[axis] - expected) <= 0.5);
        for (int other = 0; other < 3; ++other)
            if (other != axis) CHECK(after[other] == before[other]);
        CHECK(doc.history().undoCount() == undoBefore + 1);
        REQUIRE(h->app->runAction({"undo"}).empty());
        CHECK(doc.currentPose().anglesDeg[femur] == before);
    }

    CHECK(kneeChecks >= 2);

    // Ctrl: a 32° sweep becomes 30° (the change snapped to 5° steps).
    {
        const Eigen::Vector3d before = doc.currentPose().anglesDeg[femur];
        sweep(*h, gripOf(s, ui::viewportGizmo(s), 1), 32.0, true);
        const double change = doc.currentPose().anglesDeg[femur][1] - before[1];
        CHECK(std::abs(std::abs(change) - 30.0) < 1e-9);
        REQUIRE(h->app->runAction({"undo"}).empty());
    }

    // Esc during the drag cancels it: nothing changes and no undo step is added.
    {
        const Eigen::Vector3d before = doc.currentPose().anglesDeg[femur];
        const int undoBefore = doc.history().undoCount();
        sweep(*h, gripOf(s, ui::viewportGizmo(s), 2), 25.0, false, false);
        REQUIRE(s.posePreview.has_value());  // the preview shows the rotation
        test::tapKey(*h, ui::key::kEscape);
        h->input.setButton(0, false);
        h->frame(3);
        CHECK_FALSE(s.posePreview.has_value());
        CHECK(doc.currentPose().anglesDeg[femur] == before);
        CHECK(doc.history().undoCount() == undoBefore);
    }

    // A frame change during the drag cancels it: the old frame's angles are not written anywhere.
    {
        const int undoBefore = doc.history().undoCount();
        sweep(*h, gripOf(s, ui::viewportGizmo(s), 0), 25.0, false, false);
        REQUIRE(s.posePreview.has_value());
        doc.setFrame(61);
        const Eigen::Vector3d next = doc.currentPose().anglesDeg[femur];
        h->frame(2);
        h->input.setButton(0, false);
        h->frame(3);
        CHECK_FALSE(s.posePreview.has_value());
        CHECK(doc.currentPose().anglesDeg[femur] == next);
        CHECK(doc.history().undoCount() == undoBefore);
        CHECK_FALSE(doc.isEdited(61));
    }
}

TEST_CASE("gui gizmo: the view ring turns the joint about the line of sight by the mouse's sweep, one undo step") {
    auto h = makeHarness(false, false);  // no model: the rotation is exactly the joint's
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    const Skeleton& sk = doc.clip().skeleton;
    const int femur = gizmoOnRightThigh(*h);
    const render::RotateGizmo g = ui::viewportGizmo(s);
    REQUIRE(g.rings.back().axis == render::kViewRing);
    const glm::vec3 toEye = glm::normalize(s.camera.eye() - g.pivotCm);
    CHECK(glm::dot(g.rings.back().axisWorld, toEye) > 0.9999f);  // it faces the camera
    FkState before, after;
    forwardKinematics(sk, doc.currentPose(), before);
    const int undoBefore = doc.history().undoCount();
    const RingGrip grip = gripOf(s, g, render::kViewRing);
    const double seen = sweep(*h, grip, 30.0, false);
    CHECK(std::abs(seen - 30.0) < 2.0);
    forwardKinematics(sk, doc.currentPose(), after);
    // The thigh's frame turned about the line of sight by the sweep: counter-clockwise on screen
    // is a right-handed turn about the axis towards the viewer.
    const Eigen::Matrix3d turn = after.global[femur] * before.global[femur].transpose();
    const Eigen::AngleAxisd aa(turn);
    // The same turn written about the axis on the viewer's side of the joint.
    const double side = aa.axis().dot(gizmoEigen(toEye)) < 0 ? -1.0 : 1.0;
    const Eigen::Vector3d axis = side * aa.axis();
    const double degrees = side * aa.angle() * 180.0 / 3.14159265358979;
    INFO("turned " << degrees << " deg about " << axis.transpose() << "; the mouse swept " << seen);
    CHECK(std::abs(degrees - seen) <= 0.5);
    CHECK(axis.dot(gizmoEigen(toEye)) > 0.999);
    CHECK((after.jointCm[0] - before.jointCm[0]).norm() == 0.0);  // the body stays
    CHECK(doc.history().undoCount() == undoBefore + 1);
    REQUIRE(h->app->runAction({"undo"}).empty());
    forwardKinematics(sk, doc.currentPose(), after);
    CHECK((after.global[femur] - before.global[femur]).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("gui gizmo: a drag inside the rings turns the joint freely, half a degree per pixel, one undo step") {
    auto h = makeHarness(false, false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    const Skeleton& sk = doc.clip().skeleton;
    const int femur = gizmoOnRightThigh(*h);
    const render::RotateGizmo g = ui::viewportGizmo(s);
    float px = 0, py = 0;
    REQUIRE(ui::viewportWindowPosition(s, gizmoEigen(g.pivotCm), px, py));
    // A pixel 78 px from the joint: outside the 70 px axis rings (by more than their 7 px pick
    // slack), inside the view ring (87.5 px) by as much, and on no handle.
    bool found = false;
    for (int k = 0; k < 36 && !found; ++k) {
        const double a = k * 10.0 * 3.14159265358979 / 180.0;
        h->input.mouseX = static_cast<float>(px + 78.0 * std::cos(a));
        h->input.mouseY = static_cast<float>(py - 78.0 * std::sin(a));
        h->frame(2);
        found = s.gizmoRing == render::kTrackball;
    }
    REQUIRE(found);
    FkState before, after;
    forwardKinematics(sk, doc.currentPose(), before);
    const int undoBefore = doc.history().undoCount();
    h->input.setButton(0, true);
    h->frame(1);
    for (int k = 0; k < 8; ++k) {  // 40 px to the right
        h->input.mouseX += 5.0f;
        h->frame(1);
    }
    h->input.setButton(0, false);
    h->frame(3);
    forwardKinematics(sk, doc.currentPose(), after);
    // 40 px at half a degree a pixel: 20° about the camera's up axis (the thigh's side facing the
    // viewer moves right with the mouse).
    const Eigen::AngleAxisd aa(Eigen::Matrix3d(after.global[femur] * before.global[femur].transpose()));
    const glm::mat4 view = s.camera.view();
    const Eigen::Vector3d up(view[0][1], view[1][1], view[2][1]);
    INFO("turned " << aa.angle() * 180.0 / 3.14159265358979 << " deg about " << aa.axis().transpose());
    CHECK(std::abs(aa.angle() * 180.0 / 3.14159265358979 - 20.0) <= 0.5);
    CHECK(aa.axis().dot(up.normalized()) > 0.999);
    CHECK(doc.history().undoCount() == undoBefore + 1);
    // A press there that does not move is a click: no rotation, no undo step.
    h->input.setButton(0, true);
    h->frame(2);
    h->input.setButton(0, false);
    h->frame(3);
    CHECK(doc.history().undoCount() == undoBefore + 1);
}

TEST_CASE("gui gizmo: a one-DOF knee shows one ring, and a click on the thigh's surface picks the thigh") {
    auto h = makeHarness(false, false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    doc.setFrame(60);
    const Skeleton& sk = doc.clip().skeleton;
    const int tibia = sk.findBone("ltibia"), femur = sk.findBone("lfemur");
    REQUIRE(tibia >= 0);
    REQUIRE(femur >= 0);
    h->app->jointWindow().selectJoint(tibia);
    h->frame(3);
    CHECK(ui::viewportGizmo(s).rings.size() == 1);

    // A click 4 cm off the thigh's axis (its surface is 4–6 cm from it), across the view.
    FkState fk;
    forwardKinematics(sk, doc.currentPose(), fk);
    const Eigen::Vector3d mid = 0.5 * (fk.jointCm[femur] + boneEndCm(sk, fk, femur));
    const glm::mat4 view = s.camera.view();
    const Eigen::Vector3d right(view[0][0], view[1][0], view[2][0]);
    float x = 0, y = 0;
    REQUIRE(ui::viewportWindowPosition(s, mid + 4.0 * right, x, y));
    test::clickAt(*h, x, y);
    h->frame(2);
    CHECK(h->app->jointWindow().joint() == femur);
    CHECK(s.gizmoJoint == femur);
}
