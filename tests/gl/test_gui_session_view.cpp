// Reopening a session shows what was saved (label `gl`, offscreen): the camera framing exactly
// (target included, even when the editor was following the character on another frame), and a
// ticked "Before ghost" on an edited frame shows a pose although the undo history is not saved.
#include <doctest/doctest.h>

#include <filesystem>

#include "editor_harness.h"
#include "test_paths.h"
#include "ui/panels/viewport_panel.h"
#include "ui/shell/editor_app.h"

using namespace mgp;
namespace fs = std::filesystem;

TEST_CASE("gui session: reopening restores the camera framing and the before ghost") {
    auto h = test::makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    const std::string dir = std::string(MOTIONGP_GL_OUT_DIR) + "/session_view";
    fs::create_directories(dir);
    const std::string file = dir + "/view.mgsession";

    doc.setFrame(50);
    h->frame(2);
    REQUIRE(doc.beginDrag(Effector::kRHand) == "");
    doc.dragTo(doc.effectorPosition(Effector::kRHand) + Eigen::Vector3d(0, 12, 4), 200);
    doc.endDrag();
    h->app->waitIdle();
    s.showBeforeGhost = true;
    s.camera.yawDeg += 35.0f;
    s.camera.pitchDeg = 12.0f;
    h->frame(3);
    REQUIRE(ui::beforeGhostPose(s).has_value());
    const render::OrbitCamera saved = s.camera;
    REQUIRE(h->app->saveSession(file) == "");

    // Elsewhere in the clip (the camera follows the root), then back through the session.
    doc.setFrame(5);
    h->frame(3);
    REQUIRE(h->app->openSession(file) == "");
    h->frame(3);
    CHECK(doc.frame() == 50);
    CHECK(s.camera.yawDeg == doctest::Approx(saved.yawDeg));
    CHECK(s.camera.pitchDeg == doctest::Approx(saved.pitchDeg));
    CHECK(s.camera.distanceCm == doctest::Approx(saved.distanceCm));
    CHECK(s.camera.targetCm.x == doctest::Approx(saved.targetCm.x).epsilon(1e-5));
    CHECK(s.camera.targetCm.y == doctest::Approx(saved.targetCm.y).epsilon(1e-5));
    CHECK(s.camera.targetCm.z == doctest::Approx(saved.targetCm.z).epsilon(1e-5));

    CHECK(s.showBeforeGhost);
    // The undo history came back with the session (frames only): the drag is still undoable.
    REQUIRE(doc.canUndo());
    CHECK(doc.undoLabel() == "drag rhand on frame 51");
    const std::optional<Pose> ghost = ui::beforeGhostPose(s);
    REQUIRE(ghost.has_value());
    CHECK(ghost->anglesDeg != doc.currentPose().anglesDeg);  // it shows the pose before the edit
    REQUIRE(doc.undo() == "");
    CHECK(ghost->anglesDeg == doc.currentPose().anglesDeg);  // undo goes back to exactly that pose
}
