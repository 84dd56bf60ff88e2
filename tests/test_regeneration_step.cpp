// regeneration_step (core/edit/regeneration_step.h): what a finished regeneration or drag
// falloff changes in the document, on a hand-made finished job (no solve needed).
#include <doctest/doctest.h>

#include "edit/regeneration_step.h"
#include "skeleton/synthetic_clip.h"

using namespace mgp;

namespace {
// A finished job on the synthetic walk: keys 10, 13, 16 with the middle key moved 5 cm up;
// frames 11..15 solved, each pose's root lifted by its frame number so it is recognisable.
MotionEditJob finishedJob(const Clip& clip) {
    MotionEditJob job;
    job.effector = Effector::kRFoot;
    job.keyFrames = {10, 13, 16};
    job.keyOffsetsCm = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 5, 0), Eigen::Vector3d::Zero()};
    job.frames = clip.frames;
    for (int t = 11; t <= 15; ++t) {
        job.solvedFrames.push_back(t);
        job.frames[t].rootCm.y() += t;
        LearnedIkResult r;
        r.x = Eigen::Vector2d(t, -t);
        r.y = Eigen::VectorXd::Constant(3, t);
        job.results.push_back(r);
    }
    job.maxResidualCm = 0.0126;
    job.quality.edited.p95Deg = 1.26;
    job.quality.edited.maxDeg = 3.5;
    job.quality.captured.p95Deg = 1.0;
    job.quality.captured.maxDeg = 3.0;
    job.held.resize(2);
    return job;
}
}  // namespace

TEST_CASE("regeneration step: the solved frames become one step whose before is the edits they replace") {
    ClipEdits store;
    store.reset(makeSyntheticWalk(), true);
    EditRecord earlier;
    earlier.pose = store.clip().frames[12];
    earlier.pose.rootCm.x() = -7.0;
    store.set(12, earlier);
    const MotionEditJob job = finishedJob(store.clip());

    const EditStep step = regenerationStep(job, store);
    CHECK(step.label == "regenerate rfoot, frames 12-16");  // the inner frames, 1-based as on the timeline
    REQUIRE(step.after.size() == 5);
    REQUIRE(step.before.size() == 5);
    CHECK(step.after.at(11)->pose.rootCm.y() == job.frames[11].rootCm.y());
    CHECK(step.after.at(15)->x == Eigen::Vector2d(15, -15));
    CHECK_FALSE(step.before.at(11));
    CHECK(step.before.at(12)->pose.rootCm.x() == -7.0);
    CHECK(step.samples.empty());
}

TEST_CASE("regeneration step: a falloff joins the drag's step and keeps what the drag step already knew") {
    ClipEdits store;
    store.reset(makeSyntheticWalk(), true);
    const MotionEditJob job = finishedJob(store.clip());
    EditStep drag;
    drag.label = "drag rfoot on frame 14";
    drag.before[13] = std::nullopt;  // the dragged frame was captured before the drag
    EditRecord dragged;
    dragged.pose = store.clip().frames[13];
    drag.after[13] = dragged;
    store.set(13, dragged);  // the drag's own edit is already applied

    mergeFalloff(job, store, drag);
    CHECK(drag.label == "drag rfoot on frame 14");
    REQUIRE(drag.before.size() == 5);
    CHECK_FALSE(drag.before.at(13));  // not the drag's edit: what was there before the drag
    CHECK(drag.after.at(13)->pose.rootCm.y() == job.frames[13].rootCm.y());
    CHECK(falloffSummary(job, 3, 3, drag.label) ==
          "drag rfoot on frame 14: spread over frames 12-16 (falloff 3 frames)");
    CHECK(
        falloffSummary(job, 2, 3, drag.label) ==
        "drag rfoot on frame 14: spread over frames 12-16 (falloff 2 frames, widened to 3 to keep the motion smooth)");

    // A falloff that held the dragged frame leaves the drag's own record there.
    MotionEditJob held = finishedJob(store.clip());
    held.heldPose = MotionEditJob::HeldPose{13, dragged.pose, Eigen::VectorXd()};
    EditStep drag2;
    drag2.label = drag.label;
    drag2.before[13] = std::nullopt;
    drag2.after[13] = dragged;
    mergeFalloff(held, store, drag2);
    REQUIRE(drag2.after.size() == 5);
    CHECK(drag2.after.at(13)->x.size() == 0);  // the drag's record, not the job's (x = (13, −13))
    CHECK(drag2.after.at(12)->pose.rootCm.y() == held.frames[12].rootCm.y());
}

TEST_CASE("regeneration step: only the moved inner keys are taught to the model, and the summary states the numbers") {
    const Clip clip = makeSyntheticWalk();
    MotionEditJob job = finishedJob(clip);
    std::vector<AdaptiveSample> samples = movedKeySamples(job);
    REQUIRE(samples.size() == 1);
    CHECK(samples[0].clipFrame == 13);
    CHECK(samples[0].x == Eigen::Vector2d(13, -13));
    CHECK(samples[0].yKept == Eigen::VectorXd::Constant(3, 13));
    job.results[2].y(0) = std::nan("");  // a key whose solve is not finite is left out
    CHECK(movedKeySamples(job).empty());
    MotionEditJob unmoved = finishedJob(clip);
    unmoved.keyOffsetsCm[1].setZero();  // a key left where it was teaches nothing new
    CHECK(movedKeySamples(unmoved).empty());
    CHECK(regenerationSummary(finishedJob(clip), true) ==
          "regenerated 5 frames, max residual 0.013 cm; angle 2nd difference p95 1.3° (captured 1.0°), max 3.5° "
          "(captured 3.0°); 2 contact(s) held (adaptive update queued)");
    MotionEditJob missed = finishedJob(clip);
    missed.keys = {{13, 17.31, false}, {14, 0.01, true}};
    CHECK(regenerationSummary(missed, false) ==
          "regenerated 5 frames, max residual 0.013 cm; angle 2nd difference p95 1.3° (captured 1.0°), max 3.5° "
          "(captured 3.0°); 2 contact(s) held; the key on frame 14 missed its target by 17.3 cm");
}
