// Multi-clip models: several clips of one skeleton train one model (core/gp/model.h). The model
// file keeps every clip (version 2; single-clip files stay version 1), the temporal prior and the
// held-out training range never mix clips, the nearest captured frame names its clip, and the CLI
// trains, poses (--clip) and refuses clips of different skeletons. Tiny models only (CI budget).
#include <doctest/doctest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "eval/layout_quality.h"
#include "eval/nearest_pose.h"
#include "gp/model_file.h"
#include "gp/sha256.h"
#include "gp/temporal_prior.h"
#include "gp/train/trainer.h"
#include "gp/training_range.h"
#include "io/clip_loader.h"
#include "skeleton/clip_match.h"
#include "test_support.h"

using namespace mgp;
using namespace mgp::gp;

namespace {

const std::string kMocap = MOTIONGP_TEST_MOCAP;

// Two kicks of subject 10, frames 1..60 every 3rd of each (20 rows each), M = 15, T = 1.
const GpModel& twoKicks() {
    static const GpModel model = [] {
        Clip a = loadClip(kMocap + "/asf_amc/10_02.amc");
        Clip b = loadClip(kMocap + "/asf_amc/10_03.amc");
        unwrapClip(a);
        unwrapClip(b);
        std::vector<int> frames;
        for (int t = 0; t < 60; t += 3) frames.push_back(t);
        TrainOptions o;
        o.activeSize = 15;
        o.outerIterations = 1;
        o.scgIterations = 10;
        o.pointIterations = 10;
        TrainResult r = train(trainingDataFromClips({&a, &b}, {frames, frames}), o);
        r.model.clip = a;
        r.model.sourceFile = "10_02.amc";
        r.model.sourceSha256 = sha256OfFile(kMocap + "/asf_amc/10_02.amc");
        r.model.moreClips.push_back({"10_03.amc", sha256OfFile(kMocap + "/asf_amc/10_03.amc"), b});
        return r.model;
    }();
    return model;
}

}  // namespace

TEST_CASE("multi-clip: two kicks train one model with each row's clip and frame") {
    const GpModel& m = twoKicks();
    REQUIRE(m.clipCount() == 2);
    CHECK(m.N() == 40);
    CHECK(m.clipName(0) == "10_02");
    CHECK(m.clipName(1) == "10_03");
    CHECK(m.findClip("10_03") == 1);
    CHECK(m.findClip("10_06") == -1);
    CHECK(m.clipNames() == "10_02, 10_03");
    REQUIRE(m.trainingClips.size() == 40u);
    for (int r = 0; r < 40; ++r) {
        CHECK(m.rowClip(r) == (r < 20 ? 0 : 1));
        CHECK(m.trainingFrames[static_cast<std::size_t>(r)] == 3 * (r % 20));
    }
    // Row 25 is frame 15 of 10_03: its training pose is that clip's pose, not 10_02's.
    const Eigen::MatrixXd poses = poseMatrix(m.clipAt(1));
    for (int k = 0; k < m.D(); ++k) CHECK(m.Y(25, k) == poses(15, m.keptColumns[static_cast<std::size_t>(k)]));
}

TEST_CASE("multi-clip: a two-clip model file is version 2 and round-trips bit-exactly") {
    const GpModel& m = twoKicks();
    const std::string text = modelToJsonText(m);
    CHECK(nlohmann::json::parse(text)["version"] == 2);
    const GpModel back = modelFromJsonText(text, "two.model");
    CHECK(modelToJsonText(back) == text);
    REQUIRE(back.clipCount() == 2);
    CHECK(back.clipName(1) == "10_03");
    CHECK(back.clipFile(1) == "10_03.amc");
    CHECK(back.clipSha256(1) == m.clipSha256(1));
    CHECK(back.trainingClips == m.trainingClips);
    CHECK(back.trainingFrames == m.trainingFrames);
    CHECK(mgp::test::bitsEqual(back.X, m.X));
    CHECK(mgp::test::bitsEqual(back.Y, m.Y));  // rebuilt from each row's own clip
    // Damage: a row pointing at a clip that is not there is a clear error.
    auto j = nlohmann::json::parse(text);
    j["training_clips"][3] = 2;
    CHECK_THROWS_WITH_AS(modelFromJsonText(j.dump(), "bad.model"), doctest::Contains("training clips in 0..1"),
                         std::exception);
}

TEST_CASE("multi-clip: a single-clip model stays version 1, and the committed version-1 fixtures load") {
    GpModel one = twoKicks();
    one.moreClips.clear();
    one.trainingClips.clear();
    // (Rows 20..39 now read clip 0's frames: the writer keeps their poses as edited rows.)
    CHECK(nlohmann::json::parse(modelToJsonText(one))["version"] == 1);
    for (const char* f : {"kick10_03_fas_m100_t3.model", "walk35_fas_m100_t3.model"}) {
        const std::string path = std::string(MOTIONGP_TEST_FIXTURES) + "/" + f;
        const GpModel fx = loadModel(path);
        CHECK(fx.clipCount() == 1);
        CHECK(fx.trainingClips.empty());
        CHECK(modelToJsonText(fx) == test::readText(path));  // re-saved byte for byte
    }
}

TEST_CASE("multi-clip: withPrimaryClip swaps clips and relabels rows, and is its own inverse") {
    const GpModel& m = twoKicks();
    const GpModel s = withPrimaryClip(m, 1);
    CHECK(s.clip.name == "10_03");
    CHECK(s.sourceFile == "10_03.amc");
    CHECK(s.clipName(1) == "10_02");
    CHECK(s.rowClip(0) == 1);
    CHECK(s.rowClip(39) == 0);
    CHECK(mgp::test::bitsEqual(s.Y, m.Y));
    CHECK(modelToJsonText(withPrimaryClip(s, 1)) == modelToJsonText(m));
    CHECK_THROWS_AS(withPrimaryClip(m, 2), std::out_of_range);
    // The open clip is found among the model's clips.
    CHECK(findCapture(m, m.clipAt(1)) == 1);
    CHECK(findCapture(m, m.clipAt(0)) == 0);
}

TEST_CASE("multi-clip: the temporal prior never joins rows of different clips") {
    // Frames 0..5 of clip 0 and 6..8 of clip 1: as one clip they would chain into 7 triples.
    const std::vector<int> frames{0, 1, 2, 3, 4, 5, 6, 7, 8};
    const std::vector<int> clips{0, 0, 0, 0, 0, 0, 1, 1, 1};
    CHECK(TemporalPrior::secondDifference(frames, 1.0).triples().size() == 7u);
    const TemporalPrior p = TemporalPrior::secondDifference(frames, 1.0, clips);
    CHECK(p.triples().size() == 5u);  // 4 in clip 0, 1 in clip 1
    for (const auto& t : p.triples()) {
        CHECK(clips[t.row[0]] == clips[t.row[1]]);
        CHECK(clips[t.row[1]] == clips[t.row[2]]);
    }
    // Interleaved rows with the same frame numbers: still one chain per clip, in frame order.
    const std::vector<int> f2{0, 0, 1, 1, 2, 2, 3, 3};
    const std::vector<int> c2{0, 1, 0, 1, 0, 1, 0, 1};
    const TemporalPrior q = TemporalPrior::secondDifference(f2, 1.0, c2);
    REQUIRE(q.triples().size() == 4u);
    for (const auto& t : q.triples()) {
        CHECK(c2[t.row[0]] == c2[t.row[2]]);
        CHECK(c2[t.row[1]] == c2[t.row[2]]);
        CHECK(t.coef[0] == 1.0);
        CHECK(t.coef[1] == -2.0);
    }
    const Eigen::MatrixXd Y = Eigen::MatrixXd::Random(8, 3);
    const TemporalPrior paced = TemporalPrior::posePaced(f2, Y, 1.0, c2);
    CHECK(paced.triples().size() == 4u);
    for (const auto& t : paced.triples()) CHECK(c2[t.row[0]] == c2[t.row[2]]);
    CHECK_THROWS_AS(TemporalPrior::secondDifference(f2, 1.0, {0, 1}), std::invalid_argument);
}

TEST_CASE("multi-clip: the training range hides ±10 frames of the row's own clip only") {
    const GpModel& m = twoKicks();
    const ActiveSetPosterior point = m.posterior();
    std::vector<double> s2, lik;
    heldOutMomentScores(m, point, kHeldOutWindowFrames, s2, lik);
    REQUIRE(s2.size() == 40u);
    int differing = 0;
    for (int i = 0; i < m.N(); ++i) {
        std::vector<int> own, byFrameOnly;
        for (std::size_t a = 0; a < m.active.size(); ++a) {
            const int r = m.active[a];
            const bool near = std::abs(m.trainingFrames[static_cast<std::size_t>(r)] -
                                       m.trainingFrames[static_cast<std::size_t>(i)]) <= kHeldOutWindowFrames;
            if (near) byFrameOnly.push_back(static_cast<int>(a));
            if (near && m.rowClip(r) == m.rowClip(i)) own.push_back(static_cast<int>(a));
        }
        differing += own != byFrameOnly;
        double v = 0.0;
        const double l = point.evaluateHoldingOut(m.X.row(i).transpose(), m.Y.row(i).transpose(), own, v);
        CHECK(l == lik[static_cast<std::size_t>(i)]);
        CHECK(v == s2[static_cast<std::size_t>(i)]);
    }
    CHECK(differing > 0);  // the two clips' frame numbers overlap, so the rule matters here
}

TEST_CASE("multi-clip: nearestFrame searches every clip and names clip and frame") {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, kAsfPoseDofs), b = Eigen::MatrixXd::Zero(4, kAsfPoseDofs);
    a.rightCols(kAsfPoseDofs - 3).setConstant(10.0);
    b.row(2).rightCols(kAsfPoseDofs - 3).setConstant(1.0);
    b.row(0).rightCols(kAsfPoseDofs - 3).setConstant(30.0);
    b.row(1).rightCols(kAsfPoseDofs - 3).setConstant(30.0);
    b.row(3).rightCols(kAsfPoseDofs - 3).setConstant(30.0);
    const Eigen::VectorXd pose = Eigen::VectorXd::Zero(kAsfPoseDofs);
    const NearestFrame n = nearestFrame(pose, {a, b});
    CHECK(n.clip == 1);
    CHECK(n.frame == 2);
    CHECK(n.rmsDeg == doctest::Approx(1.0));
    CHECK(nearestFrame(pose, {}).clip == -1);
}

TEST_CASE("multi-clip: sameSkeleton accepts one ASF subject and names the first mismatch of two") {
    const Clip a = loadClip(kMocap + "/asf_amc/10_02.amc");
    const Clip b = loadClip(kMocap + "/asf_amc/10_03.amc");
    const Clip c = loadClip(kMocap + "/asf_amc/35_01.amc");
    std::string why;
    CHECK(sameSkeleton(a.skeleton, b.skeleton, &why));
    CHECK_FALSE(sameSkeleton(a.skeleton, c.skeleton, &why));
    CHECK(why.find("joint ") == 0);
    CHECK(why.find(" cm against ") != std::string::npos);
    Skeleton d = a.skeleton;
    d.joints[2].dof = {true, false, false};
    CHECK_FALSE(sameSkeleton(a.skeleton, d, &why));
    CHECK(why.find("DOF channels") != std::string::npos);
}

TEST_CASE("multi-clip: motiongp train on two kicks, pose --clip on the second, clear errors") {
    const std::string dir = test::scratchDir("multi_clip_cli");
    std::filesystem::create_directories(dir);
    const std::string model = dir + "/two.model";
    const test::CliResult t = test::runCli("train " + kMocap + "/asf_amc/10_02.amc " + kMocap +
                                           "/asf_amc/10_03.amc --frames 1:60 --step 3 --active 15 --iters 1 "
                                           "--scg-iters 10 --json --out " +
                                           model);
    REQUIRE_MESSAGE(t.exitCode == 0, t.err);
    const auto j = nlohmann::json::parse(t.out);
    CHECK(j["N"] == 40);
    REQUIRE(j["clips"].size() == 2u);
    CHECK(j["clips"][0]["name"] == "10_02");
    CHECK(j["clips"][1]["name"] == "10_03");
    CHECK(j["clips"][1]["frames"] == 20);
    CHECK(j["clips"][1]["sha256"] == sha256OfFile(kMocap + "/asf_amc/10_03.amc"));

    const test::CliResult p = test::runCli("pose " + model + " --clip 10_03 --frame 10 --target rhand=0,20,0 --json");
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    const auto jp = nlohmann::json::parse(p.out);
    CHECK(jp["clip"] == "10_03");
    CHECK(jp["reached"] == true);
    CHECK(jp["targets"][0]["residual_cm"].get<double>() < 0.1);
    CHECK(jp["nearest"]["clip"] == "10_03");

    // edit --clip: the keys are frames of 10_03, the BVH is 10_03, and the adaptive model keeps
    // the file's clip order with the new rows marked as 10_03's.
    const std::string bvh = dir + "/e.bvh", model2 = dir + "/e.model";
    const test::CliResult e = test::runCli("edit " + model +
                                           " --clip 10_03 --effector rhand --keys 10,14,18,22 --offset 0,5,0 "
                                           "--adaptive --out-model " +
                                           model2 + " --out " + bvh);
    REQUIRE_MESSAGE(e.exitCode == 0, e.err);
    const GpModel edited = loadModel(model2);
    CHECK(edited.clipName(0) == "10_02");
    CHECK(edited.clipName(1) == "10_03");
    REQUIRE(edited.N() == 42);
    CHECK(edited.rowClip(40) == 1);
    CHECK(edited.rowClip(41) == 1);
    CHECK(edited.trainingFrames[40] == 13);  // key 14, counted from 1
    CHECK(loadClip(bvh).frameCount() == edited.clipAt(1).frameCount());

    const test::CliResult u = test::runCli("pose " + model + " --clip 10_06 --frame 31 --target rhand=0,20,0");
    CHECK(u.exitCode == 2);
    CHECK(u.err.find("10_02, 10_03") != std::string::npos);
    CHECK(u.err.find("'10_06'") != std::string::npos);

    const test::CliResult x =
        test::runCli("train " + kMocap + "/asf_amc/10_02.amc " + kMocap +
                     "/asf_amc/35_01.amc --frames 1:30 --active 10 --iters 1 --out " + dir + "/x.model");
    CHECK(x.exitCode == 2);
    CHECK(std::count(x.err.begin(), x.err.end(), '\n') == 1);  // one line
    CHECK(x.err.find("35_01.amc against") != std::string::npos);
    CHECK(x.err.find("joint ") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir + "/x.model"));
}

TEST_CASE("multi-clip: continuity is measured per clip on its own rows, and evaluate lists every clip") {
    const GpModel& m = twoKicks();
    const std::vector<eval::ContinuityReport> per = eval::latentContinuityPerClip(m);
    REQUIRE(per.size() == 2u);
    for (int c = 0; c < 2; ++c) {
        // The same numbers as latentContinuity on that clip's rows alone (rows 0..19, 20..39).
        const Eigen::MatrixXd X = m.X.middleRows(20 * c, 20);
        const std::vector<int> frames(m.trainingFrames.begin() + 20 * c, m.trainingFrames.begin() + 20 * (c + 1));
        const eval::ContinuityReport alone = eval::latentContinuity(X, frames);
        CHECK(per[static_cast<std::size_t>(c)].steps == 19);  // 20 rows every 3rd frame: one segment
        CHECK(per[static_cast<std::size_t>(c)].p90 == alone.p90);
        CHECK(per[static_cast<std::size_t>(c)].medianPairDistance == alone.medianPairDistance);
    }
    // Measured over both clips at once, frames 0..57 of the two clips would be joined as one time
    // line: the per-clip steps must not include such cross-clip pairs.
    CHECK(eval::latentContinuity(m.X, m.trainingFrames).steps != per[0].steps + per[1].steps);

    const std::string dir = test::scratchDir("multi_clip_evaluate");
    std::filesystem::create_directories(dir);
    const std::string path = dir + "/two.model";
    saveModel(path, m);
    const test::CliResult e = test::runCli("evaluate " + path + " --no-yardstick --json");
    REQUIRE_MESSAGE(e.exitCode == 0, e.err);
    const auto j = nlohmann::json::parse(e.out);
    REQUIRE(j["continuity"].size() == 2u);
    CHECK(j["continuity"][0]["clip"] == "10_02");
    CHECK(j["continuity"][1]["clip"] == "10_03");
    CHECK(j["continuity"][1]["p90"].get<double>() == per[1].p90);
    const test::CliResult h = test::runCli("evaluate " + path + " --heldout --no-yardstick");
    CHECK(h.exitCode == 2);
    CHECK(h.err.find("--heldout") != std::string::npos);
}
