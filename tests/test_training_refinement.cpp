// A model at once, a better one in the background (docs/maths.md §23): the
// trainer's time budget and snapshots, the training job's published models, and the document
// that installs them and keeps the poses accepted meanwhile for the final model.
#include <doctest/doctest.h>

#include "document_helpers.h"
#include "edit/editor_document.h"
#include "edit/training_job.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "test_paths.h"
#include "trained_model_fixture.h"

using namespace mgp;

namespace {

const std::string kRefineClip = std::string(MOTIONGP_TEST_MOCAP) + "/asf_amc/16_35.amc";

// 54 rows, M = 25 < N (Steps 7 and 8 run), a fixed λ so that T does not change the objective.
gp::TrainOptions refinementRun(int outerIterations) {
    gp::TrainOptions o;
    o.activeSize = 25;
    o.outerIterations = outerIterations;
    o.scgIterations = 25;
    o.pointIterations = 25;
    o.priorWeight = 30.0;
    o.stopOnConvergence = false;
    return o;
}

gp::TrainingData refinementData(const Clip& clip) {
    std::vector<int> frames;
    for (int t = 0; t < clip.frameCount(); t += 3) frames.push_back(t);
    return gp::trainingDataFromClip(clip, frames);
}

}  // namespace

TEST_CASE("trainer: a time budget stops before an iteration that would end after it, and the first always runs") {
    const gp::TrainingData data = refinementData(loadClip(kRefineClip));
    gp::TrainControl control;
    int calls = 0;
    control.afterIteration = [&](const gp::Trainer&) { ++calls; };
    control.timeBudgetSeconds = 1e-9;
    const gp::TrainResult r = gp::train(data, refinementRun(5), control);
    CHECK(r.outOfTime);
    CHECK_FALSE(r.cancelled);
    CHECK(r.log.size() == 1);
    CHECK(r.model.iterations == 1);
    CHECK(calls == 1);
    // No budget: all T iterations.
    control.timeBudgetSeconds = 0.0;
    const gp::TrainResult all = gp::train(data, refinementRun(3), control);
    CHECK_FALSE(all.outOfTime);
    CHECK(all.log.size() == 3);
    CHECK(calls == 4);
}

TEST_CASE("trainer: the model as it stands after k iterations is the model a run of T = k writes") {
    const gp::TrainingData data = refinementData(loadClip(kRefineClip));
    std::optional<gp::GpModel> atTwo;
    gp::TrainControl control;
    control.afterIteration = [&](const gp::Trainer& t) {
        if (t.log().size() == 2) atTwo = gp::snapshotModel(t);
    };
    gp::train(data, refinementRun(4), control);
    REQUIRE(atTwo.has_value());
    const gp::TrainResult two = gp::train(data, refinementRun(2));
    CHECK(atTwo->iterations == 2);
    CHECK(atTwo->X == two.model.X);
    CHECK(atTwo->logParams == two.model.logParams);
    CHECK(atTwo->active == two.model.active);
    CHECK(atTwo->w == two.model.w);
    CHECK(atTwo->objectiveHistory == two.model.objectiveHistory);
}

TEST_CASE("training job: publishes the model while the run goes on, and the final model supersedes it") {
    const Clip clip = loadClip(kRefineClip);
    TrainingJob job;
    job.setPublishPolicy({1, 0.0, true});  // after every iteration but the last
    gp::TrainOptions o = refinementRun(3);
    REQUIRE(job.start(clip, o) == "");
    job.join();
    CHECK(job.progress().published == 2);
    CHECK(job.progress().publishedIteration == 2);
    const gp::ModelVersionPtr interim = job.takeRefinement();
    REQUIRE(interim);
    CHECK(interim->model->iterations == 2);
    CHECK(interim->model->clip.frameCount() == clip.frameCount());  // a model the editor can install
    CHECK(job.takeRefinement() == nullptr);                         // taken once
    const gp::ModelVersionPtr final = job.take();
    REQUIRE(final);
    CHECK(final->model->iterations == 3);

    // The final model supersedes a published one that was never taken.
    REQUIRE(job.start(clip, o) == "");
    job.join();
    REQUIRE(job.take());
    CHECK(job.takeRefinement() == nullptr);

    // Not before `firstIterations`.
    job.setPublishPolicy({3, 0.0, true});
    REQUIRE(job.start(clip, o) == "");
    job.join();
    CHECK(job.progress().published == 0);
    CHECK(job.takeRefinement() == nullptr);
}

TEST_CASE(
    "editor: poses accepted while a model refines wait, and the final model is taught those still on their frames") {
    EditorDocument doc;
    const gp::ModelVersionPtr v0 = test::walkModel35();
    doc.installRefinement(v0, true);
    REQUIRE(doc.refining());
    doc.setFrame(99);
    test::dragBy(doc, Effector::kRHand, {5, 0, 0});  // a small move the model admits
    doc.waitIdle();
    CHECK(doc.models().updates() == 0);  // not taught to a model the next refinement replaces
    CHECK(doc.model() == v0);
    CHECK(doc.waitingPoses() == 1);
    const Pose taught = doc.currentPose();

    // A refinement keeps the waiting pose.
    doc.installRefinement(gp::ModelVersion::make(*v0->model), false);
    CHECK(doc.waitingPoses() == 1);

    // A second accepted pose, then undone: it waits too, but its frame no longer has it.
    doc.setFrame(60);
    test::dragBy(doc, Effector::kRHand, {5, 0, 0});
    doc.waitIdle();
    REQUIRE(doc.waitingPoses() == 2);
    REQUIRE(doc.undo() == "");
    doc.waitIdle();

    const int posted = doc.finishRefinement(gp::ModelVersion::make(*v0->model), false);
    CHECK(posted == 1);
    CHECK_FALSE(doc.refining());
    CHECK(doc.waitingPoses() == 0);
    doc.waitIdle();
    REQUIRE(doc.models().updates() == 1);
    const std::vector<AdaptiveHistoryEntry> history = doc.models().history();
    REQUIRE(history.size() == 1);
    CHECK(history.back().frame == 99);
    CHECK(history.back().accepted);
    doc.setFrame(99);
    CHECK(posesIdentical(doc.currentPose(), taught));  // teaching changes the model, not the edit

    // Once refining has ended, a drag is taught at once again.
    doc.setFrame(120);
    test::dragBy(doc, Effector::kLHand, {0, 0, 5});
    doc.waitIdle();
    CHECK(doc.models().history().size() == 2);
}
