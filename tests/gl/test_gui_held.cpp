// Held effectors through the editor with real mouse input (edit/held_effectors.h): a foot dragged
// up on one frame stays there on its neighbours through a later hand drag's falloff; a hand pinned
// with P does not jump during a drag of the other hand, and the head an earlier drag placed stays;
// the viewport rings what is held; Alt+click on the handle releases it, as one undo step that moves
// nothing.
#include <doctest/doctest.h>

#include <string>

#include "editor_harness.h"
#include "skeleton/forward_kinematics.h"
#include "test_support.h"
#include "ui/input/gui_script.h"
#include "ui/shell/editor_app.h"

using namespace mgp;
using test::makeHarness;

namespace {

// A left-button drag of `effector`'s handle by `steps` × (dx, dy) pixels, then the falloff waited for.
void heldGuiDrag(test::Harness& h, const char* effector, int steps, int dx, int dy) {
    std::string script = std::string("0 hover ") + effector + "\n2 down left\n";
    for (int k = 0; k < steps; ++k)
        script += std::to_string(4 + 2 * k) + " moveby " + std::to_string(dx) + " " + std::to_string(dy) + "\n";
    script += std::to_string(6 + 2 * steps) + " up left\n";
    REQUIRE(h.play(ui::GuiScript::parse(script)).empty());
    h.app->waitIdle();
    h.frame(2);
}

Eigen::Vector3d heldGuiEffector(EditorDocument& doc, int frame, Effector e) {
    return effectorCm(doc.clip().skeleton, doc.poseAt(frame), e);
}

}  // namespace

TEST_CASE(
    "gui held: a foot drag then a hand drag keeps the foot on the neighbouring frames, and Alt+click releases it") {
    auto h = makeHarness(false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    doc.setDragFalloff(10);
    const int t = 140;
    doc.setFrame(t);
    h->frame(2);
    CHECK(h->app->viewport().lastScene().heldMarks.empty());
    // The right foot is planted here: its footprint is drawn, until the drag lifts it off.
    REQUIRE(doc.inContact(Effector::kRFoot));
    const std::size_t printsBefore = h->app->viewport().lastScene().footprints.size();

    const Eigen::Vector3d capturedFoot = heldGuiEffector(doc, t, Effector::kRFoot);
    heldGuiDrag(*h, "rfoot", 6, 0, -6);
    CHECK(h->app->viewport().lastScene().footprints.size() + 1 == printsBefore);  // its held mark instead
    REQUIRE(doc.isEdited(t));
    const Eigen::Vector3d foot[3] = {heldGuiEffector(doc, t - 1, Effector::kRFoot),
                                     heldGuiEffector(doc, t, Effector::kRFoot),
                                     heldGuiEffector(doc, t + 1, Effector::kRFoot)};
    MESSAGE("the mouse raised the foot " << (foot[1] - capturedFoot).y() << " cm on frame " << t + 1);
    REQUIRE((foot[1] - capturedFoot).y() > 5.0);
    CHECK(doc.held(Effector::kRFoot));
    REQUIRE(h->app->viewport().lastScene().heldMarks.size() == 1);
    CHECK(glm::length(h->app->viewport().lastScene().heldMarks[0].positionCm - render::toGlm(foot[1])) < 1e-3f);

    heldGuiDrag(*h, "rhand", 6, 0, -6);
    CHECK(doc.held(Effector::kRHand));
    CHECK(h->app->viewport().lastScene().heldMarks.size() == 2);
    for (int k = 0; k < 3; ++k) {
        const double moved = (heldGuiEffector(doc, t - 1 + k, Effector::kRFoot) - foot[k]).norm();
        MESSAGE("frame " << t + k << ": the foot moved " << moved << " cm during the hand drag");
        CHECK(moved <= 1.0);
    }

    // Alt+click on the foot's handle lets go of it on this frame and its neighbours (one step).
    const int steps = doc.history().undoCount();
    const Pose poseBefore = doc.poseAt(t);
    REQUIRE(
        h->play(ui::GuiScript::parse("0 keydown ALT\n1 hover rfoot\n3 down left\n5 up left\n7 keyup ALT\n")).empty());
    h->frame(2);
    CHECK_FALSE(doc.held(Effector::kRFoot));
    CHECK(doc.held(Effector::kRHand));
    CHECK(doc.history().undoCount() == steps + 1);
    CHECK(doc.undoLabel().rfind("release rfoot on frames", 0) == 0);
    const Pose poseAfter = doc.poseAt(t);  // a release moves nothing
    CHECK(poseAfter.rootCm == poseBefore.rootCm);
    for (std::size_t j = 0; j < poseAfter.anglesDeg.size(); ++j)
        CHECK(poseAfter.anglesDeg[j] == poseBefore.anglesDeg[j]);
    CHECK(h->app->viewport().lastScene().heldMarks.size() == 1);
    REQUIRE(doc.undo().empty());
    CHECK(doc.held(Effector::kRFoot));
}

TEST_CASE("gui held: a hand pinned with P after a head drag does not jump during a drag of the other hand") {
    auto h = makeHarness(false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    doc.setDragFalloff(10);
    const int t = 100;
    doc.setFrame(t);
    h->frame(2);
    heldGuiDrag(*h, "head", 4, 4, 6);
    REQUIRE(doc.isEdited(t));
    CHECK(doc.held(Effector::kHead));  // placed: the hand drag below holds it too
    const Eigen::Vector3d head = heldGuiEffector(doc, t, Effector::kHead);
    REQUIRE(h->play(ui::GuiScript::parse("0 hover lhand\n2 key P\n")).empty());
    REQUIRE(doc.pinned(Effector::kLHand));
    heldGuiDrag(*h, "rhand", 6, 0, -6);
    const Clip& clip = doc.clip();
    const double edited =
        test::positionSecondDifferenceCm([&](int s) { return heldGuiEffector(doc, s, Effector::kLHand); }, t);
    const double captured = test::positionSecondDifferenceCm(
        [&](int s) { return effectorCm(clip.skeleton, clip.frames[static_cast<std::size_t>(s)], Effector::kLHand); },
        t);
    MESSAGE("the pinned hand's second difference at the dragged frame: " << edited << " cm (capture " << captured
                                                                         << " cm)");
    CHECK(edited <= captured + 0.5);
    CHECK(doc.isEdited(t + 5));  // the hand drag did spread
    CHECK((heldGuiEffector(doc, t, Effector::kHead) - head).norm() < 0.01);
}
