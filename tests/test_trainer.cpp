// The outer loop (docs/maths.md §8): a small real clip trains deterministically (byte-identical
// model files across runs and thread counts), lowers L_GP below L_init, and can be cancelled.
#include <doctest/doctest.h>

#include "test_support.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "gp/model_file.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"

using namespace mgp::gp;

namespace {

const std::string kClip = std::string(MOTIONGP_TEST_MOCAP) + "/asf_amc/16_35.amc";

TrainingData smallData(const mgp::Clip& clip, int step) {
    std::vector<int> frames;
    for (int t = 0; t < clip.frameCount(); t += step) frames.push_back(t);
    return trainingDataFromClip(clip, frames);
}

TrainOptions smallOptions(KernelKind kind, int threads) {
    TrainOptions o;
    o.kind = kind;
    o.activeSize = 25;
    o.outerIterations = 3;
    o.scgIterations = 25;
    o.pointIterations = 25;
    o.threads = threads;
    return o;
}

std::string trainAndSave(const mgp::Clip& clip, const TrainingData& data, KernelKind kind, int threads,
                         const std::string& path, TrainResult* out = nullptr) {
    TrainResult r = train(data, smallOptions(kind, threads));
    r.model.clip = clip;
    r.model.sourceFile = "16_35.amc";
    saveModel(path, r.model);
    if (out) *out = r;
    return mgp::test::readText(path);
}

}  // namespace

TEST_CASE("trainer: two runs give byte-identical model files, with any thread count") {
    const mgp::Clip clip = mgp::loadClip(kClip);
    const TrainingData data = smallData(clip, 3);  // 54 frames, M = 25 < N: Steps 7-8 active
    const std::string dir = mgp::test::scratchDir("trainer");
    std::filesystem::create_directories(dir);
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm}) {
        TrainResult r;
        const std::string a = trainAndSave(clip, data, kind, 1, dir + "/a.json", &r);
        const std::string b = trainAndSave(clip, data, kind, 2, dir + "/b.json");
        const std::string c = trainAndSave(clip, data, kind, 2, dir + "/c.json");
        CHECK(!a.empty());
        CHECK(a == b);
        CHECK(b == c);
        REQUIRE(r.log.size() == 3);
        // Iteration 1 optimises on the same active set L_init was computed on.
        CHECK(r.log[0].L < r.lInit);
        CHECK(r.log[0].L_before == doctest::Approx(r.lInit).epsilon(1e-12));
        for (const auto& e : r.log) {
            CHECK(std::isfinite(e.L));
            CHECK(e.L <= e.L_before);
            CHECK(e.activeOverlap >= 0.0);
            CHECK(e.activeOverlap <= 1.0);
            CHECK(e.maxDeltaRaw > 0.0);
        }
        CHECK(r.model.active.size() == 25);
        CHECK(std::abs(r.model.w.array().log().sum()) < 1e-9);
    }
}

TEST_CASE("trainer: with M ≥ N every frame is active and the final L_GP is below L_init") {
    const mgp::Clip clip = mgp::loadClip(kClip);
    const TrainingData data = smallData(clip, 4);  // 41 frames
    TrainOptions o = smallOptions(KernelKind::kFas, 0);
    o.activeSize = 200;
    const TrainResult r = train(data, o);
    CHECK(r.model.active.size() == static_cast<std::size_t>(data.Y.rows()));
    for (std::size_t i = 1; i < r.log.size(); ++i) {
        CHECK(r.log[i].activeOverlap == 1.0);
        CHECK(r.log[i].L <= r.log[i - 1].L);
    }
    CHECK(r.log.back().L < r.lInit);
}

TEST_CASE("trainer: a cancel flag set from another thread stops the loop") {
    const mgp::Clip clip = mgp::loadClip(kClip);
    const TrainingData data = smallData(clip, 3);
    std::atomic<bool> cancel{false};
    int calls = 0;
    TrainOptions o = smallOptions(KernelKind::kFas, 1);
    o.outerIterations = 50;
    const TrainResult r = train(
        data, o,
        [&](const IterationLog&) {
            if (++calls == 2) cancel.store(true);
        },
        &cancel);
    CHECK(r.cancelled);
    CHECK(r.log.size() == 2);
}

TEST_CASE("trainer: cancelling from another thread interrupts a long run") {
    const mgp::Clip clip = mgp::loadClip(kClip);
    const TrainingData data = smallData(clip, 3);
    std::atomic<bool> cancel{false};
    TrainOptions o = smallOptions(KernelKind::kFas, 2);
    o.outerIterations = 1000000;  // would run for hours without the cancel
    o.stopOnConvergence = false;
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        cancel.store(true);
    });
    const TrainResult r = train(data, o, nullptr, &cancel);
    canceller.join();
    CHECK(r.cancelled);
    CHECK(r.log.size() < 1000000);
}

TEST_CASE("trainer: the raw Step-9 test stops the loop once max |Δ| < C") {
    const mgp::Clip clip = mgp::loadClip(kClip);
    const TrainingData data = smallData(clip, 4);
    TrainOptions o = smallOptions(KernelKind::kSgplvm, 1);
    o.activeSize = 200;  // no churn
    o.outerIterations = 40;
    o.tolerance = 1e9;  // any finite change passes
    const TrainResult r = train(data, o);
    CHECK(r.converged);
    CHECK(r.log.size() == 1);
}

TEST_CASE("trainer: the objective history is L_init then L_GP after each iteration's Step 6") {
    const mgp::Clip clip = mgp::loadClip(kClip);
    const TrainResult r = train(smallData(clip, 4), smallOptions(KernelKind::kFas, 1));
    const std::vector<double>& h = r.model.objectiveHistory;
    REQUIRE(h.size() == static_cast<std::size_t>(r.model.iterations) + 1);
    REQUIRE(r.model.iterations == static_cast<int>(r.log.size()));
    CHECK(h.front() == r.lInit);
    for (std::size_t t = 0; t < r.log.size(); ++t) CHECK(h[t + 1] == r.log[t].L);
    CHECK(h.back() == r.log.back().L);
    CHECK(h.back() < h.front());
}

TEST_CASE("trainer: the default prior weight follows the budget T (100 up to T = 10, 30 from the default T = 30)") {
    CHECK(defaultPriorWeight(1) == kQuickPriorWeight);
    CHECK(defaultPriorWeight(10) == kQuickPriorWeight);
    CHECK(defaultPriorWeight(30) == doctest::Approx(kFullPriorWeight).epsilon(1e-12));
    CHECK(defaultPriorWeight(100) == doctest::Approx(kFullPriorWeight).epsilon(1e-12));
    CHECK(defaultPriorWeight(1000) == doctest::Approx(kFullPriorWeight).epsilon(1e-12));
    // Log-linear in T between: T = 20 gives 100 · 0.3^(ln 2 / ln 3).
    CHECK(defaultPriorWeight(20) > defaultPriorWeight(25));
    const double mid = 100.0 * std::pow(0.3, std::log(2.0) / std::log(3.0));  // 46.78…
    CHECK(defaultPriorWeight(20) == doctest::Approx(mid).epsilon(1e-12));
    CHECK(mid == doctest::Approx(46.7843).epsilon(1e-5));

    TrainOptions o;
    CHECK(o.outerIterations == 30);
    CHECK(o.resolvedPriorWeight() == doctest::Approx(kFullPriorWeight).epsilon(1e-12));  // the default T
    o.outerIterations = 3;
    CHECK(o.resolvedPriorWeight() == kQuickPriorWeight);
    o.priorWeight = 7.0;  // given: used whatever T
    CHECK(o.resolvedPriorWeight() == 7.0);
    o.prior = LatentPrior::kNone;
    CHECK(o.resolvedPriorWeight() == 0.0);
    o.prior = LatentPrior::kSmooth;
    o.priorWeight = -1.0;
    CHECK_THROWS_AS(o.validate(), std::invalid_argument);

    // A run without a given weight records the λ it used, so a retraining reproduces it.
    const mgp::Clip clip = mgp::loadClip(kClip);
    TrainOptions small = smallOptions(KernelKind::kFas, 1);
    small.outerIterations = 1;
    const TrainResult r = train(smallData(clip, 8), small);
    CHECK(r.model.settings.prior == LatentPrior::kSmooth);
    CHECK(r.model.settings.priorWeight == kQuickPriorWeight);
}

TEST_CASE("trainer: the start noise moves the PCA start by N(0, σ²) per coordinate, repeatably per seed") {
    const mgp::Clip clip = mgp::loadClip(kClip);
    const TrainingData data = smallData(clip, 1);
    TrainOptions o = smallOptions(KernelKind::kFas, 1);
    const Eigen::MatrixXd x0 = Trainer(data, o).latent();
    o.startNoise = 0.05;
    o.startSeed = 3;
    const Eigen::MatrixXd x3 = Trainer(data, o).latent();
    CHECK(Trainer(data, o).latent() == x3);  // the seed fixes the draw
    o.startSeed = 4;
    CHECK(Trainer(data, o).latent() != x3);
    // The draws, divided by σ, look standard normal over the clip's 2N coordinates.
    const Eigen::MatrixXd moved = (x3 - x0) / 0.05;
    const Eigen::ArrayXd z = Eigen::Map<const Eigen::VectorXd>(moved.data(), moved.size()).array();
    const double mean = z.mean();
    const double sd = std::sqrt((z - mean).square().sum() / (z.size() - 1));
    INFO(z.size() << " draws: mean " << mean << ", sd " << sd);
    REQUIRE(z.size() > 200);
    CHECK(std::abs(mean) < 4.0 / std::sqrt(static_cast<double>(z.size())));  // 4 standard errors
    CHECK(sd == doctest::Approx(1.0).epsilon(0.15));
    o.startNoise = -1.0;
    CHECK_THROWS_AS(o.validate(), std::invalid_argument);
}
