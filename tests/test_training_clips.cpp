// The one multi-clip training path (core/gp/train/training_clips.h) that `motiongp train` and the
// editor's TrainingJob share: frame selection per clip, the refusals (BVH, two skeletons, a range
// outside a clip, too few rows), and the job's model equal to gp::train on the same clips with
// every clip attached. Tiny models only (CI budget).
#include <doctest/doctest.h>

#include "edit/training_job.h"
#include "gp/sha256.h"
#include "gp/train/training_clips.h"
#include "io/clip_loader.h"
#include "test_support.h"

using namespace mgp;
using namespace mgp::gp;

TEST_CASE("training clips: a frame selection keeps frames A..B of each clip, then every K-th") {
    CHECK(selectFrames(10, {1, 0, 1}, "x") == std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
    CHECK(selectFrames(362, {1, 10, 3}, "x") == std::vector<int>{0, 3, 6, 9});
    CHECK(selectFrames(362, {5, 5, 1}, "x") == std::vector<int>{4});
    CHECK(selectFrames(60, {1, 60, 3}, "x").size() == 20u);
    CHECK_THROWS_WITH_AS(selectFrames(362, {100, 5000, 1}, "10_03"),
                         "expected --frames A:B with 1 ≤ A ≤ B ≤ 362 (10_03's frames counted from 1), found '100:5000'",
                         TrainingInputError);
    CHECK_THROWS_AS(selectFrames(10, {0, 5, 1}, "x"), TrainingInputError);
    CHECK_THROWS_AS(selectFrames(10, {6, 5, 1}, "x"), TrainingInputError);
    CHECK_THROWS_WITH_AS(selectFrames(10, {1, 0, 0}, "x"), "expected --step ≥ 1, found 0", TrainingInputError);
}

TEST_CASE("training clips: two skeletons, repeated names and too few rows are refused with one line") {
    const std::string kick = test::mocap("asf_amc/10_02.amc"), kick2 = test::mocap("asf_amc/10_03.amc");
    const std::string jump = test::mocap("asf_amc/16_01.amc"), bvh = test::mocap("bvh/49_04.bvh");
    // A BVH trains on its own, never with an AMC (another skeleton); its rest frame is no row.
    const std::vector<TrainingClip> alone = prepareTrainingClips({loadClip(bvh)}, {bvh}, {});
    REQUIRE(alone.size() == 1u);
    CHECK(alone[0].clip.restFrame);
    CHECK(alone[0].frames.front() == 1);
    CHECK(static_cast<int>(alone[0].frames.size()) == alone[0].clip.frameCount() - 1);
    CHECK_THROWS_AS(prepareTrainingClips({loadClip(kick), loadClip(bvh)}, {kick, bvh}, {}), TrainingInputError);
    try {
        prepareTrainingClips({loadClip(kick), loadClip(jump)}, {kick, jump}, {});
        FAIL("clips of two skeletons were accepted");
    } catch (const TrainingInputError& e) {
        const std::string what = e.what();
        CHECK(what.rfind("expected clips of one skeleton (retargeting is not supported), found " + jump + " against " +
                             kick + ": joint ",
                         0) == 0);
    }
    CHECK_THROWS_WITH_AS(prepareTrainingClips({loadClip(kick), loadClip(kick)}, {kick, kick}, {}),
                         "expected clips with distinct names (file stems), found 10_02 twice", TrainingInputError);
    CHECK_THROWS_WITH_AS(prepareTrainingClips({loadClip(kick2)}, {kick2}, {1, 2, 1}),
                         "expected at least 3 training frames after --frames/--step, found 2", TrainingInputError);
    // 10_03 has 362 frames, 10_02 more: a range past 362 fits the first clip only.
    CHECK_THROWS_WITH_AS(prepareTrainingClips({loadClip(kick), loadClip(kick2)}, {kick, kick2}, {1, 400, 1}),
                         "expected --frames A:B with 1 ≤ A ≤ B ≤ 362 (10_03's frames counted from 1), found '1:400'",
                         TrainingInputError);
}

TEST_CASE("training clips: the editor's TrainingJob on two kicks gives gp::train's model with both clips attached") {
    const std::string kick = test::mocap("asf_amc/10_02.amc"), kick2 = test::mocap("asf_amc/10_03.amc");
    const FrameSelection sel{1, 60, 3};
    TrainOptions o;
    o.activeSize = 15;
    o.outerIterations = 1;
    o.scgIterations = 10;
    o.pointIterations = 10;
    // The open clip first (10_03): it becomes the primary clip.
    std::vector<TrainingClip> clips = prepareTrainingClips({loadClip(kick2), loadClip(kick)}, {kick2, kick}, sel);
    REQUIRE(clips.size() == 2u);
    CHECK(clips[0].frames.size() == 20u);
    CHECK(clips[1].frames[19] == 57);
    CHECK(clips[0].sha256 == sha256OfFile(kick2));
    const TrainResult direct = train(trainingDataOf(clips), o);

    TrainingJob job;
    REQUIRE(job.start(clips, sel, o) == "");
    job.join();
    const ModelVersionPtr v = job.take();
    REQUIRE(v);
    const GpModel& m = *v->model;
    CHECK(m.clipCount() == 2);
    CHECK(m.clip.name == "10_03");
    CHECK(m.clipName(1) == "10_02");
    CHECK(m.sourceFile == "10_03.amc");
    CHECK(m.clipFile(1) == "10_02.amc");
    CHECK(m.clipSha256(1) == sha256OfFile(kick));
    CHECK(m.N() == 40);
    CHECK(m.rowClip(19) == 0);
    CHECK(m.rowClip(20) == 1);
    CHECK(m.trainingFrames[21] == 3);
    CHECK(m.settings.frameFirst == 1);
    CHECK(m.settings.frameLast == 60);
    CHECK(m.settings.frameStep == 3);
    REQUIRE(m.X.rows() == direct.model.X.rows());
    CHECK(test::bitsEqual(m.X, direct.model.X));
}
