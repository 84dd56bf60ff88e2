// Layout-quality measures (core/eval/layout_quality.h, docs/maths.md §20): percentiles,
// continuity on known layouts, the full-GP yardstick's value and gradient, the held-out split and
// reconstruction, and training with the smooth prior (docs/maths.md §19) on a real clip.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "eval/layout_quality.h"
#include "gp/model_file.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("layout quality: percentile interpolates between order statistics") {
    CHECK(eval::percentile({3.0, 1.0, 2.0, 4.0, 5.0}, 0.5) == 3.0);
    CHECK(eval::percentile({1.0, 2.0, 3.0, 4.0}, 0.5) == doctest::Approx(2.5));
    CHECK(eval::percentile({0.0, 10.0}, 0.9) == doctest::Approx(9.0));
    CHECK(eval::percentile({7.0}, 0.99) == 7.0);
    CHECK(std::isnan(eval::percentile({}, 0.5)));
}

TEST_CASE("layout quality: consecutive pairs follow frames and skip cuts") {
    const auto pairs = eval::timeConsecutivePairs({5, 3, 4, 40, 41});
    REQUIRE(pairs.size() == 3);  // 3→4, 4→5, 40→41; 5→40 is a cut
    CHECK(pairs[0] == std::make_pair(1, 2));
    CHECK(pairs[1] == std::make_pair(2, 0));
    CHECK(pairs[2] == std::make_pair(3, 4));
}

TEST_CASE("layout quality: continuity of a known layout") {
    // Four points on a unit square visited in order: steps 1, 1, 1; pair distances 1,1,1,1,√2,√2.
    Eigen::MatrixXd X(4, 2);
    X << 0, 0, 1, 0, 1, 1, 0, 1;
    eval::ContinuityReport c = eval::latentContinuity(X, {0, 1, 2, 3});
    CHECK(c.steps == 3);
    CHECK(c.medianPairDistance == doctest::Approx(1.0));
    CHECK(c.p50 == doctest::Approx(1.0));
    CHECK(c.p90 == doctest::Approx(1.0));
    // The same points visited 0, 2, 1, 3: steps √2, 1, √2 → p50 √2, p90 √2.
    c = eval::latentContinuity(X, {0, 2, 1, 3});
    CHECK(c.p50 == doctest::Approx(std::sqrt(2.0)));
    CHECK(c.max == doctest::Approx(std::sqrt(2.0)));
    CHECK_THROWS(eval::latentContinuity(X, {0, 1}));
}

TEST_CASE("layout quality: full-GP negative log-likelihood, known value for one point") {
    // N = 1: K = α + b + 1/β, −ln p = (D/2) ln K + ½ Σ y²/K + (D/2) ln 2π.
    Eigen::MatrixXd X(1, 2), Y(1, 3);
    X << 0.3, -0.2;
    Y << 0.5, -1.0, 2.0;
    const Eigen::Vector4d psi(std::log(2.0), std::log(3.0), std::log(0.5), std::log(4.0));
    const double K = 2.0 + 0.5 + 0.25;
    const double expected = 1.5 * std::log(K) + 0.5 * (0.25 + 1.0 + 4.0) / K + 1.5 * std::log(2 * M_PI);
    CHECK(eval::fullGpNegLogLikelihood(X, Y, psi, nullptr) == doctest::Approx(expected).epsilon(1e-13));
}

TEST_CASE("layout quality: full-GP gradient in (ln α, ln γ, ln b, ln β) by central differences") {
    const int n = 9;
    Eigen::MatrixXd X(n, 2), Y(n, 4);
    for (int i = 0; i < n; ++i) {
        X.row(i) << std::sin(0.9 * i), 0.3 * i - 1.0;
        Y.row(i) << std::cos(0.4 * i), 0.2 * i, std::sin(1.7 * i) - 0.1, 0.05 * i * i;
    }
    const Eigen::Vector4d psi(std::log(1.3), std::log(0.7), std::log(0.2), std::log(8.0));
    Eigen::Vector4d g;
    eval::fullGpNegLogLikelihood(X, Y, psi, &g);
    const double h = 1e-6;
    for (int p = 0; p < 4; ++p) {
        Eigen::Vector4d a = psi, b = psi;
        a[p] += h;
        b[p] -= h;
        const double fd =
            (eval::fullGpNegLogLikelihood(X, Y, a, nullptr) - eval::fullGpNegLogLikelihood(X, Y, b, nullptr)) / (2 * h);
        CHECK(g[p] == doctest::Approx(fd).epsilon(1e-6));
    }
}

TEST_CASE("layout quality: the yardstick prefers latent points that explain the data") {
    // Y is a smooth function of a 1-D time t; X = (t, 0) explains it, shuffled X does not.
    const int n = 60;
    Eigen::MatrixXd Xgood(n, 2), Xbad(n, 2), Y(n, 3);
    for (int i = 0; i < n; ++i) {
        const double t = i / 10.0;
        Xgood.row(i) << t, 0.0;
        Xbad.row(i) << ((i * 37) % n) / 10.0, 0.0;
        Y.row(i) << std::sin(t), std::cos(1.5 * t), 0.2 * t;
    }
    const eval::FullGpScore good = eval::fitFullGp(Xgood, Y), bad = eval::fitFullGp(Xbad, Y);
    REQUIRE(good.ok);
    REQUIRE(bad.ok);
    CHECK(good.perValue > bad.perValue + 0.5);
}

TEST_CASE("layout quality: every 10th frame is held out") {
    std::vector<int> frames;
    for (int f = 0; f < 35; ++f) frames.push_back(f);
    const eval::HeldOutSplit s = eval::everyNthHeldOut(frames, 10);
    CHECK(s.heldFrames == std::vector<int>{9, 19, 29});
    CHECK(s.trainFrames.size() == 32);
    CHECK_THROWS(eval::everyNthHeldOut(frames, 1));
}

TEST_CASE("layout quality: held-out reconstruction of a training frame is close, baseline exact") {
    // A frame the model was trained on: the nearest training pose is itself (baseline 0°), and
    // L_IK from its own pose reconstructs it to within a few degrees.
    const gp::GpModel& m = *mgp::test::walkModel35()->model;
    const eval::HeldOutReport r = eval::heldOutReconstruction(m, {100, 200});
    CHECK(r.heldOut == 2);
    CHECK(r.nearestRmsDeg < 1e-9);  // the frame's own row (fullPose rounding only)
    CHECK(r.rmsDeg < 5.0);
    // The split's RMS is the root mean of the two frames' squares, so the worst frame is at or
    // above it and the median (of two: their mean) at or below the worst.
    CHECK((r.worstFrame == 100 || r.worstFrame == 200));
    CHECK(r.worstFrameRmsDeg >= r.rmsDeg);
    CHECK(r.medianFrameRmsDeg <= r.worstFrameRmsDeg);
    const eval::HeldOutReport one = eval::heldOutReconstruction(m, {r.worstFrame});
    CHECK(one.rmsDeg == doctest::Approx(r.worstFrameRmsDeg).epsilon(1e-12));
    CHECK(one.worstFrameRmsDeg == one.rmsDeg);
    CHECK(one.medianFrameRmsDeg == one.rmsDeg);
}

TEST_CASE("layout quality: a frame left out of the model is placed, reconstructed and in-betweened") {
    // The committed model minus one inactive row: that frame is then held out, with training
    // frames just before and after it.
    gp::GpModel m = *mgp::test::walkModel35()->model;
    int r = 150;
    while (std::find(m.active.begin(), m.active.end(), r) != m.active.end()) ++r;
    const int frame = m.trainingFrames[static_cast<std::size_t>(r)];
    auto dropRow = [r](Eigen::MatrixXd& A) {
        Eigen::MatrixXd B(A.rows() - 1, A.cols());
        B << A.topRows(r), A.bottomRows(A.rows() - r - 1);
        A = B;
    };
    dropRow(m.X);
    dropRow(m.Y);
    m.trainingFrames.erase(m.trainingFrames.begin() + r);
    for (int& i : m.active)
        if (i > r) --i;
    const eval::HeldOutReport h = eval::heldOutReconstruction(m, {frame});
    CHECK(h.heldOut == 1);
    CHECK(h.timeCount == 1);
    CHECK(h.nearestRmsDeg > 0.0);
    CHECK(h.rmsDeg < 5.0);
    CHECK(std::isfinite(h.timeRmsDeg));
    CHECK(h.timeRmsDeg < 10.0);
}

TEST_CASE("smooth prior: training on the walk makes the latent path continuous and is saved") {
    const Clip clip = loadClip(mgp::test::mocap("asf_amc/35_01.amc"));
    gp::TrainOptions o;
    o.activeSize = 60;
    o.outerIterations = 3;
    o.scgIterations = 30;
    o.pointIterations = 30;
    o.threads = 2;
    o.prior = gp::LatentPrior::kNone;
    const gp::TrainResult none = gp::trainOnClip(clip, o);
    o.prior = gp::LatentPrior::kSmooth;
    o.priorWeight = 100.0;
    const gp::TrainResult smooth = gp::trainOnClip(clip, o);
    const eval::ContinuityReport cn = eval::latentContinuity(none.model.X, none.model.trainingFrames);
    const eval::ContinuityReport cs = eval::latentContinuity(smooth.model.X, smooth.model.trainingFrames);
    INFO("p90 none " << cn.p90 << ", smooth " << cs.p90);
    CHECK(cs.p90 < 0.5 * cn.p90);
    // The objective (L_GP + prior) still decreases from its start.
    REQUIRE(!smooth.log.empty());
    CHECK(smooth.log.back().L < smooth.lInit);
    // The prior is part of the model's provenance and survives a save/load; the paper's model
    // file has no prior field at all.
    CHECK(smooth.model.settings.prior == gp::LatentPrior::kSmooth);
    const gp::GpModel back = gp::modelFromJsonText(gp::modelToJsonText(smooth.model), "mem");
    CHECK(back.settings.prior == gp::LatentPrior::kSmooth);
    CHECK(back.settings.priorWeight == 100.0);
    CHECK(gp::modelToJsonText(none.model).find("\"prior\"") == std::string::npos);
    CHECK(eval::trainOptionsOf(back).prior == gp::LatentPrior::kSmooth);
}

TEST_CASE("model file: a damaged prior field is one clear error") {
    const gp::GpModel& m = *mgp::test::walkModel35()->model;
    nlohmann::json j = nlohmann::json::parse(gp::modelToJsonText(m));
    j["training"]["prior"] = {{"kind", "gpdm"}, {"weight", 1.0}};
    CHECK_THROWS_WITH(gp::modelFromJsonText(j.dump(), "bad.model"), doctest::Contains("smooth"));
    j["training"]["prior"] = {{"kind", "smooth"}, {"weight", -1.0}};
    CHECK_THROWS_WITH(gp::modelFromJsonText(j.dump(), "bad.model"), doctest::Contains("weight"));
}

TEST_CASE("cmd evaluate: --json contract on the committed model") {
    const mgp::test::CliResult r = mgp::test::runCli("evaluate " + mgp::test::walkModelPath() + " --json");
    REQUIRE(r.exitCode == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["prior"] == "none");
    REQUIRE(j["continuity"].size() == 1);
    CHECK(j["continuity"][0]["steps"] == 357);
    CHECK(j["continuity"][0]["p90"].get<double>() >= j["continuity"][0]["p50"].get<double>());
    CHECK(j["yardstick"]["final"]["per_value"].is_number());
    CHECK(j["yardstick"]["pca_start"]["per_value"].is_number());
    CHECK(j["heldout"].is_null());
    const mgp::test::CliResult bad = mgp::test::runCli("evaluate " + mgp::test::walkModelPath() + " --every 1");
    CHECK(bad.exitCode == 2);
    CHECK(bad.err.find("expected --every") != std::string::npos);
}
