// EditorDocument (core/edit): the drag state machine, pins, edits, latent posing, and the
// TrainingJob (background training with cancel). No GL.
#include <doctest/doctest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "document_helpers.h"
#include "edit/editor_document.h"
#include "edit/training_job.h"
#include "io/clip_loader.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/synthetic_clip.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;
using test::dragBy;

namespace {
Eigen::Vector3d footOf(const EditorDocument& doc, Effector e) {
    FkState fk;
    forwardKinematics(doc.clip().skeleton, doc.currentPose(), fk);
    return effectorCm(doc.clip().skeleton, fk, e);
}

}  // namespace

TEST_CASE("editor document: a learned drag reaches the target and becomes the frame's edit") {
    EditorDocument doc;
    const gp::ModelVersionPtr v = test::walkModel35();
    doc.setModel(v, true);
    REQUIRE(doc.hasModel());
    REQUIRE(doc.frameCount() == v->model->clip.frameCount());
    doc.setFrame(99);
    const Eigen::Vector3d start = doc.effectorPosition(Effector::kRFoot);
    dragBy(doc, Effector::kRFoot, {0, 20, 0});
    CHECK(doc.isEdited(99));
    CHECK_FALSE(doc.isEdited(98));
    const Eigen::Vector3d foot = footOf(doc, Effector::kRFoot);
    CHECK((foot - (start + Eigen::Vector3d(0, 20, 0))).norm() <= kReachedToleranceCm);
    CHECK(doc.readout().learned);
    CHECK(doc.readout().reached);
    CHECK(doc.currentLatent().size() == 2);
    CHECK(doc.latentPath().size() >= 2);
    // Another frame shows its captured pose; coming back shows the edit.
    doc.setFrame(10);
    CHECK_FALSE(doc.isEdited(10));
    doc.setFrame(99);
    CHECK((footOf(doc, Effector::kRFoot) - foot).norm() < 1e-9);
    doc.waitIdle();
    CHECK(doc.models().updates() == 1);
}

TEST_CASE("editor document: a pinned foot stays planted while a hand is dragged") {
    EditorDocument doc;
    doc.setModel(test::walkModel35(), true);
    doc.setAdaptiveEnabled(false);
    doc.setFrame(50);
    doc.setPinned(Effector::kLFoot, true);
    const Eigen::Vector3d lfoot = doc.effectorPosition(Effector::kLFoot);
    dragBy(doc, Effector::kRHand, {0, 10, 8});
    CHECK((footOf(doc, Effector::kLFoot) - lfoot).norm() <= kReachedToleranceCm);
    bool sawPin = false;
    for (const auto& c : doc.readout().constraints) sawPin |= c.pin && c.effector == Effector::kLFoot;
    CHECK(sawPin);
}

TEST_CASE("editor document: cancel restores, latent drag poses from the model mean, no model uses plain IK") {
    EditorDocument doc;
    doc.setModel(test::walkModel35(), true);
    doc.setAdaptiveEnabled(false);
    const Pose before = doc.currentPose();
    REQUIRE(doc.beginDrag(Effector::kLHand) == "");
    doc.dragTo(doc.effectorPosition(Effector::kLHand) + Eigen::Vector3d(5, 5, 0));
    doc.cancelDrag();
    CHECK_FALSE(doc.isEdited(0));
    CHECK((doc.currentPose().rootCm - before.rootCm).norm() == 0.0);

    REQUIRE(doc.beginLatentDrag());
    const Eigen::VectorXd x = doc.currentLatent();
    doc.latentDragTo(x + Eigen::Vector2d(0.1, 0.0));
    doc.endLatentDrag();
    CHECK(doc.isEdited(0));
    CHECK((doc.currentLatent() - (x + Eigen::Vector2d(0.1, 0.0))).norm() < 1e-12);

    EditorDocument plain;
    plain.setClip(makeSyntheticWalk(60), true);
    CHECK(plain.trainable());
    const Eigen::Vector3d s = plain.effectorPosition(Effector::kRHand);
    REQUIRE(plain.beginDrag(Effector::kRHand) == "");
    plain.dragTo(s + Eigen::Vector3d(0, 10, 0));
    plain.endDrag();
    CHECK_FALSE(plain.readout().learned);
    CHECK((footOf(plain, Effector::kRHand) - (s + Eigen::Vector3d(0, 10, 0))).norm() <= kReachedToleranceCm);
}

TEST_CASE("training job: trains in the background, can be cancelled, one run at a time") {
    const std::string amc = test::mocap("asf_amc/35_01.amc");
    const Clip clip = loadClip(amc);
    gp::TrainOptions o;
    o.activeSize = 100;
    o.outerIterations = 2;
    TrainingJob job;
    REQUIRE(job.start(clip, o) == "");
    CHECK(job.start(clip, o) != "");  // one at a time
    job.join();
    const gp::ModelVersionPtr v = job.take();
    REQUIRE(v);
    CHECK(v->model->clip.frameCount() == clip.frameCount());
    CHECK(job.take() == nullptr);

    o.outerIterations = 1000;
    REQUIRE(job.start(clip, o) == "");
    job.cancel();
    job.join();
    CHECK(job.take() == nullptr);
    CHECK(job.message().find("cancelled") != std::string::npos);
}
