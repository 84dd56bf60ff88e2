// Undo/redo, path editing and regeneration in the EditorDocument (core/edit): each step restores
// its frames and the exact model version it changed; a regenerated span meets its keys.
#include <doctest/doctest.h>

#include "document_helpers.h"
#include "edit/edit_history.h"
#include "edit/editor_document.h"
#include "gp/model_file.h"
#include "skeleton/forward_kinematics.h"
#include "trained_model_fixture.h"

using namespace mgp;
using test::dragBy;

namespace {
std::string modelText(const gp::ModelVersionPtr& v) { return gp::modelToJsonText(*v->model); }
}  // namespace

TEST_CASE("undo restores the previous pose and the exact model version, redo re-applies both") {
    EditorDocument doc;
    const gp::ModelVersionPtr v0 = test::walkModel35();
    doc.setModel(v0, true);
    CHECK_FALSE(doc.canUndo());
    CHECK(doc.undo() == "nothing to undo");

    doc.setFrame(99);
    // Small enough that the solved pose stays within the training range (so it is admitted): with
    // the default locality, 8 cm scores L_IK 308 against the limit 243, 4 cm 121.
    dragBy(doc, Effector::kRFoot, {0, 4, 0});
    const Pose pose99 = doc.currentPose();
    doc.waitIdle();
    doc.pollRegenerate();  // as the editor does every frame: the drag's spread joins its step
    const gp::ModelVersionPtr v1 = doc.model();
    REQUIRE(v1 != v0);  // the drag's adaptive update was accepted
    CHECK(doc.undoLabel() == "drag rfoot on frame 100");

    doc.setFrame(119);
    const Pose before119 = doc.currentPose();  // where the first drag's spread left it
    dragBy(doc, Effector::kLHand, {6, 0, 3});  // undo below waits for this drag's update
    const Pose pose119 = doc.currentPose();
    const long revision = doc.revision();

    REQUIRE(doc.undo() == "");
    CHECK(doc.revision() > revision);
    const gp::ModelVersionPtr v2 = doc.redo() == "" ? doc.model() : nullptr;  // redo then undo again
    REQUIRE(v2 != nullptr);
    CHECK(v2 != v1);
    CHECK(posesIdentical(doc.currentPose(), pose119));
    REQUIRE(doc.undo() == "");
    CHECK(posesIdentical(doc.poseAt(119), before119));
    CHECK(doc.model() == v1);
    CHECK(modelText(doc.model()) == modelText(v1));

    REQUIRE(doc.undo() == "");
    CHECK_FALSE(doc.isEdited(99));
    CHECK(doc.model() == v0);
    CHECK(doc.model()->model->N() == v0->model->N());
    CHECK_FALSE(doc.canUndo());
    CHECK(doc.redoLabel() == "drag rfoot on frame 100");

    REQUIRE(doc.redo() == "");
    CHECK(doc.model() == v1);
    doc.setFrame(99);
    CHECK(posesIdentical(doc.currentPose(), pose99));
    REQUIRE(doc.redo() == "");
    CHECK(doc.model() == v2);
    CHECK(doc.redo() == "nothing to redo");

    SUBCASE("a new step after an undo drops the redo branch and undoes to the right version") {
        REQUIRE(doc.undo() == "");  // back to v1
        REQUIRE(doc.model() == v1);
        doc.setFrame(200);
        dragBy(doc, Effector::kLFoot, {0, 0, 3});  // a move the admission takes (balanced, like the capture)
        CHECK_FALSE(doc.canRedo());
        doc.waitIdle();
        INFO("adaptive: " << doc.models().status());
        CHECK(doc.model() != v1);
        REQUIRE(doc.undo() == "");
        CHECK(doc.model() == v1);
        CHECK_FALSE(doc.isEdited(200));
    }
}

TEST_CASE("undo steps carry ids: two steps with the same label are told apart, and a restored history gets new ones") {
    EditHistory h;
    EditStep a, b;
    a.label = b.label = "drag rfoot on frame 101";
    const long ida = h.push(a);
    CHECK(h.topUndoWithId(ida) != nullptr);
    const long idb = h.push(b);
    CHECK(idb != ida);
    CHECK(h.topUndoWithId(ida) == nullptr);  // superseded by a step with the same label
    REQUIRE(h.topUndoWithId(idb) != nullptr);
    CHECK(h.topUndoWithId(idb)->id == idb);
    h.moveUndoToRedo();
    CHECK(h.topUndoWithId(idb) == nullptr);  // undone
    CHECK(h.topUndoWithId(ida) != nullptr);
    h.restore({a, b}, {});
    CHECK(h.undoSteps()[0].id > idb);
    CHECK(h.undoSteps()[1].id == h.undoSteps()[0].id + 1);
    CHECK(h.push(EditStep{}) == h.undoSteps()[1].id + 1);
}

TEST_CASE("clearing an edit and a latent drag are undo steps, a new model keeps the poses' history") {
    EditorDocument doc;
    doc.setModel(test::walkModel35(), true);
    doc.setFrame(50);
    const Pose captured = doc.currentPose();
    dragBy(doc, Effector::kHead, {5, 0, 0});
    const Pose edited = doc.currentPose();
    doc.waitIdle();
    doc.clearEdit(50);
    CHECK_FALSE(doc.isEdited(50));
    CHECK(doc.undoLabel() == "reset frame 51 to the captured pose");
    REQUIRE(doc.undo() == "");
    CHECK(posesIdentical(doc.currentPose(), edited));

    REQUIRE(doc.beginLatentDrag());
    Eigen::VectorXd x = doc.currentLatent();
    x(0) += 0.3;
    doc.latentDragTo(x);
    doc.endLatentDrag();
    CHECK(doc.undoLabel() == "latent pose on frame 51");
    REQUIRE(doc.undo() == "");
    CHECK(posesIdentical(doc.currentPose(), edited));

    // Installing another model (e.g. a retrained one) keeps the undo steps for the poses, but
    // undoing the drag must not bring back the old model's versions.
    const gp::ModelVersionPtr retrained = gp::ModelVersion::make(*test::walkModel35()->model, 7);
    doc.setModel(retrained, false);
    REQUIRE(doc.canUndo());
    REQUIRE(doc.undo() == "");
    CHECK(posesIdentical(doc.currentPose(), captured));
    CHECK(doc.model() == retrained);
}

TEST_CASE("default path keys follow the paper's pattern and fit the clip") {
    CHECK(defaultPathKeys(109, 358) == std::vector<int>{88, 102, 116, 130});  // 89, 103, 117, 131 (1-based)
    CHECK(defaultPathKeys(0, 358) == std::vector<int>{0, 14, 28, 42});
    CHECK(defaultPathKeys(357, 358) == std::vector<int>{315, 329, 343, 357});
    CHECK(defaultPathKeys(5, 10) == std::vector<int>{0, 3, 6, 9});
    CHECK(defaultPathKeys(1, 3) == std::vector<int>{0, 1, 2});
    CHECK(defaultPathKeys(0, 2).empty());
    CHECK(validatePathKeys({3, 3}, 10) == "expected strictly increasing key frames, found 4 then 4");
    CHECK(validatePathKeys({3, 4}, 10) == "expected at least one frame between the first and last key, found none");
    CHECK(validatePathKeys({3, 12}, 10) == "expected key frames in 1..10, found 13");
    CHECK(validatePathKeys({3}, 10) == "expected at least 2 key frames, found 1");
}

TEST_CASE("regenerating an edited path meets the moved keys, leaves other frames alone, and undoes as one step") {
    EditorDocument doc;
    const gp::ModelVersionPtr v0 = test::walkModel35();
    doc.setModel(v0, true);
    doc.setFrame(109);
    CHECK(doc.startRegenerate() == "no path is being edited");
    REQUIRE(doc.beginPathEdit(Effector::kRFoot) == "");
    REQUIRE(doc.paths().edit()->keyFrames == std::vector<int>{88, 102, 116, 130});
    const Eigen::Vector3d lifted = doc.paths().keyPosition(1) + Eigen::Vector3d(0, 12, 4);
    REQUIRE(doc.paths().setKeyPosition(1, lifted) == "");
    CHECK((doc.paths().edit()->keyOffsetsCm[1] - Eigen::Vector3d(0, 12, 4)).norm() < 1e-9);
    REQUIRE(doc.paths().setKeyOffset(2, {0, 12, 4}) == "");
    CHECK(doc.paths().setKeyOffset(7, {0, 0, 0}) == "expected a key in 1..4, found 8");
    CHECK(doc.paths().setKeyOffset(2, {0, NAN, 0}) == "expected a finite offset, found NaN or Inf");

    // The drawn curve passes through every key; the captured curve is the unedited path.
    const std::vector<Eigen::Vector3d> curve = doc.paths().targets(), captured = doc.paths().captured();
    REQUIRE(curve.size() == 43);
    REQUIRE(captured.size() == 43);
    for (int k = 0; k < 4; ++k)
        CHECK((curve[doc.paths().edit()->keyFrames[k] - 88] - doc.paths().keyPosition(k)).norm() < 1e-9);
    CHECK((curve.front() - captured.front()).norm() < 1e-9);

    REQUIRE(doc.startRegenerate(200) == "");
    CHECK(doc.startRegenerate(200) == "a regeneration is already running");
    doc.waitIdle();
    CHECK(doc.regenerateDone() == 41);
    const std::string summary = doc.pollRegenerate();
    CHECK(summary.rfind("regenerated 41 frames", 0) == 0);
    CHECK(doc.undoLabel() == "regenerate rfoot, frames 90-130");
    for (int t = 0; t < doc.frameCount(); ++t) CHECK(doc.isEdited(t) == (t > 88 && t < 130));
    for (int k : {1, 2}) {
        doc.setFrame(doc.paths().edit()->keyFrames[k]);
        CHECK((doc.effectorPosition(Effector::kRFoot) - doc.paths().keyPosition(k)).norm() <= kReachedToleranceCm);
    }
    doc.waitIdle();
    CHECK(doc.models().updates() == 2);  // the two moved keys joined the model
    const gp::ModelVersionPtr v2 = doc.model();
    CHECK(v2->model->N() == v0->model->N() + 2);

    // The before/after ghost of a regenerated frame is its captured pose.
    doc.setFrame(100);
    REQUIRE(doc.beforeGhost().has_value());
    CHECK(posesIdentical(*doc.beforeGhost(), doc.clip().frames[100]));

    REQUIRE(doc.undo() == "");
    CHECK(doc.edits().empty());
    CHECK(doc.model() == v0);
    REQUIRE(doc.redo() == "");
    CHECK(doc.edits().size() == 41);
    CHECK(doc.model() == v2);
}

TEST_CASE("a cancelled regeneration changes nothing") {
    EditorDocument doc;
    doc.setModel(test::walkModel35(), true);
    doc.setFrame(200);
    REQUIRE(doc.beginPathEdit(Effector::kLHand) == "");
    REQUIRE(doc.paths().setKeyOffset(1, {0, 0, 20}) == "");
    REQUIRE(doc.startRegenerate(5000) == "");
    doc.cancelRegenerate();
    doc.waitIdle();
    std::string error;
    CHECK(doc.pollRegenerate(&error) == "");
    CHECK(error == "regeneration cancelled");
    CHECK(doc.edits().empty());
    CHECK_FALSE(doc.canUndo());
}
