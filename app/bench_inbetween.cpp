// bench section "inbetween": transitions of 20, 60, 120 and 180 frames (1/6, 1/2, 1 and 1.5 s at
// 120 fps) generated on shipped clips by models trained on OTHER clips of the same subject, in
// windows whose first key is every 160 frames from frame 41; L2P, L2Q and NPSS
// (eval/inbetween_metrics.h) of the two baselines (hold, interpolate) and of MotionGP (retrieve,
// prior) computed in the same run, with the seconds per transition, the worst key error and the
// worst held-foot residual (docs/maths-inbetween.md §3).
#include <chrono>
#include <map>

#include "bench_registry.h"
#include "eval/inbetween_metrics.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "motion/inbetween.h"

namespace mgp::app {
namespace {

struct InbetweenPair {
    const char* clip;     // generated on
    const char* trained;  // the model learns from this one only (same subject, another take)
};

const InbetweenPair kPairs[] = {
    {"asf_amc/10_03.amc", "asf_amc/10_02.amc"},  // kick from another kick
    {"asf_amc/10_02.amc", "asf_amc/10_03.amc"},
    {"asf_amc/16_35.amc", "asf_amc/16_36.amc"},  // run from another run
    {"asf_amc/16_36.amc", "asf_amc/16_35.amc"},
};
constexpr int kContextFrames = 40;  // 1/3 s before the first key, as LaFAN1's 10 frames at 30 fps
constexpr int kWindowStride = 160;
constexpr int kStatsStride = 20;  // training windows for the position spread
constexpr InbetweenMethod kMethods[] = {InbetweenMethod::kHold, InbetweenMethod::kInterpolate,
                                        InbetweenMethod::kRetrieve, InbetweenMethod::kPrior};

std::vector<Pose> windowOf(const std::vector<Pose>& frames, int a, int b) {
    return std::vector<Pose>(frames.begin() + a, frames.begin() + b + 1);
}

struct MethodTally {
    InbetweenScore score;
    std::vector<double> seconds;
    double worstKeyCm = 0.0, worstHeldCm = 0.0;
};

nlohmann::json tallyJson(const MethodTally& t) {
    return {{"l2p", t.score.l2p()},
            {"l2q", t.score.l2q()},
            {"npss", t.score.npss()},
            {"seconds", summarizeSeconds(t.seconds)},
            {"worst_key_error_cm", t.worstKeyCm},
            {"worst_held_foot_cm", t.worstHeldCm}};
}

const BenchRegistration inbetweenBench(
    "inbetween", "Transitions between keys on clips the model never saw: L2P/L2Q/NPSS against the baselines",
    [](const BenchContext& ctx) {
        if (ctx.mocapDir.empty()) return nlohmann::json{{"skipped", "no CMU mocap folder"}};
        gp::TrainOptions options;  // the defaults a user trains with
        if (ctx.quick) {
            options.activeSize = 50;
            options.outerIterations = 2;
        }
        const std::vector<int> lengths = ctx.quick ? std::vector<int>{20} : std::vector<int>{20, 60, 120, 180};
        const std::size_t pairs = ctx.quick ? 1 : std::size(kPairs);
        // Per length and method, pooled over every pair's windows.
        std::map<int, std::map<InbetweenMethod, MethodTally>> pooled;
        std::map<int, int> windows;
        nlohmann::json perPair = nlohmann::json::array();
        for (std::size_t p = 0; p < pairs; ++p) {
            const Clip clip = loadClip(ctx.mocapDir + "/" + kPairs[p].clip);
            const auto t0 = std::chrono::steady_clock::now();
            const gp::ModelVersionPtr version = gp::ModelVersion::make(
                gp::trainOnClip(loadClip(ctx.mocapDir + "/" + kPairs[p].trained), options).model);
            const double trainSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            const Clip& trained = version->model->clip;
            nlohmann::json row = {{"clip", clip.name},
                                  {"trained_on", trained.name},
                                  {"clip_frames", clip.frameCount()},
                                  {"train_seconds", trainSeconds},
                                  {"lengths", nlohmann::json::array()}};
            for (int L : lengths) {
                std::vector<WindowGlobals> stats;
                for (int a = 0; a + L + 1 < trained.frameCount(); a += kStatsStride)
                    stats.push_back(windowGlobals(trained.skeleton, windowOf(trained.frames, a, a + L + 1)));
                if (stats.empty()) continue;
                const Eigen::VectorXd sd = positionSpread(stats);
                std::map<InbetweenMethod, MethodTally> mine;
                int count = 0;
                for (int a = kContextFrames; a + L + 1 <= clip.frameCount() - 1; a += kWindowStride) {
                    const int b = a + L + 1;
                    const WindowGlobals truth = windowGlobals(clip.skeleton, windowOf(clip.frames, a, b));
                    ++count;
                    for (InbetweenMethod method : kMethods) {
                        InbetweenJob job;
                        job.version = version;
                        job.clip = clip;
                        job.gaps = {{a, b}};
                        job.method = method;
                        job.run();
                        const InbetweenJob::GapReport& r = job.reports.front();
                        const WindowGlobals predicted = windowGlobals(clip.skeleton, windowOf(job.frames, a, b));
                        for (MethodTally* t : {&mine[method], &pooled[L][method]}) {
                            t->score.add(truth, predicted, sd);
                            t->seconds.push_back(r.seconds);
                            t->worstKeyCm = std::max(t->worstKeyCm, r.keyErrorCm);
                            t->worstHeldCm = std::max(t->worstHeldCm, r.maxHeldResidualCm);
                        }
                    }
                }
                if (count == 0) continue;
                windows[L] += count;
                nlohmann::json methods;
                for (const auto& [method, tally] : mine) methods[inbetweenMethodName(method)] = tallyJson(tally);
                row["lengths"].push_back({{"frames", L}, {"windows", count}, {"methods", methods}});
            }
            perPair.push_back(row);
        }
        nlohmann::json summary = nlohmann::json::array();
        for (const auto& [L, tallies] : pooled) {
            nlohmann::json methods;
            for (const auto& [method, tally] : tallies) methods[inbetweenMethodName(method)] = tallyJson(tally);
            const double interp = tallies.at(InbetweenMethod::kInterpolate).score.l2p();
            const double prior = tallies.at(InbetweenMethod::kPrior).score.l2p();
            summary.push_back({{"frames", L},
                               {"seconds_at_120fps", L / 120.0},
                               {"windows", windows[L]},
                               {"methods", methods},
                               {"prior_l2p_below_interpolate", interp > 0.0 ? 1.0 - prior / interp : 0.0}});
        }
        return nlohmann::json{{"model", {{"M", options.activeSize}, {"T", options.outerIterations}}},
                              {"pooled", summary},
                              {"pairs", perPair}};
    });

}  // namespace
}  // namespace mgp::app
