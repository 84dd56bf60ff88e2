// bench section "model": layout quality of a quick model (T = 10, the paper's other settings) for
// each latent prior, and back-constraints without a prior, on two real clips (walk 35_01, jump
// 16_01): the numbers `motiongp evaluate`
// reports (docs/maths.md §20) and how long each measure takes. Continuity and the yardstick are
// timed over ctx.repeats (medians); training and the held-out protocol (a retraining) once.
// --quick: M = 60, T = 2 (a smoke test; the numbers then mean little).
#include "bench_registry.h"
#include "command_registry.h"
#include "eval/layout_quality.h"
#include "gp/train/pca_init.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "io/data_paths.h"

namespace mgp::app {
namespace {

nlohmann::json benchClip(const Clip& clip, gp::LatentPrior prior, bool backConstraints, const BenchContext& ctx) {
    gp::TrainOptions o;
    o.prior = prior;
    o.backConstraints = backConstraints;
    o.outerIterations = ctx.quick ? 2 : 10;
    if (ctx.quick) o.activeSize = 60;
    gp::TrainResult r;
    const double trainSeconds = secondsOf([&] { r = gp::trainOnClip(clip, o); });
    const gp::GpModel& m = r.model;
    eval::ContinuityReport c;
    std::vector<double> cs, ys;
    for (int k = 0; k < ctx.repeats; ++k)
        cs.push_back(secondsOf([&] { c = eval::latentContinuity(m.X, m.trainingFrames); }));
    eval::FullGpScore fin, pca;
    const int yRepeats = std::max(1, std::min(ctx.repeats, 3));
    for (int k = 0; k < yRepeats; ++k) ys.push_back(secondsOf([&] { fin = eval::fitFullGp(m.X, m.Y); }));
    const Eigen::MatrixXd Ybar = m.Y.rowwise() - m.Y.colwise().mean();
    pca = eval::fitFullGp(gp::whitenedPca(Ybar, m.latentDim()).X, m.Y);
    const eval::HeldOutSplit split = eval::everyNthHeldOut(m.trainingFrames, 10);
    eval::HeldOutReport h;
    const double heldSeconds = secondsOf([&] {
        gp::TrainResult hr = gp::train(gp::trainingDataFromClip(m.clip, split.trainFrames), o);
        hr.model.clip = m.clip;
        h = eval::heldOutReconstruction(hr.model, split.heldFrames);
    });
    return {
        {"prior", gp::latentPriorName(prior)},
        {"back_constraints", backConstraints},
        {"N", m.N()},
        {"M", static_cast<int>(m.active.size())},
        {"T", o.outerIterations},
        {"train_seconds", trainSeconds},
        {"continuity", {{"p50", c.p50}, {"p90", c.p90}, {"p99", c.p99}, {"seconds", summarizeSeconds(cs)}}},
        {"yardstick",
         {{"final_per_value", fin.perValue}, {"pca_start_per_value", pca.perValue}, {"seconds", summarizeSeconds(ys)}}},
        {"heldout",
         {{"rms_deg", h.rmsDeg},
          {"nearest_frame_rms_deg", h.nearestRmsDeg},
          {"inbetween_rms_deg", h.timeRmsDeg},
          {"seconds", heldSeconds},
          {"measured_once", true}}}};
}

const BenchRegistration modelBench(
    "model",
    "Layout quality (continuity, full-GP yardstick, held-out) per prior and with back-constraints on two clips",
    [](const BenchContext& ctx) {
        const std::string dir =
            !ctx.mocapDir.empty() ? ctx.mocapDir : findShippedMocapFolder(globalOptions().exeDir).value_or("");
        if (dir.empty()) return nlohmann::json{{"skipped", "no mocap folder (full CMU set or the shipped clips)"}};
        nlohmann::json out;
        for (const char* trial : {"35_01", "16_01"}) {
            const Clip clip = loadClip(dir + "/asf_amc/" + trial + ".amc");
            nlohmann::json rows = nlohmann::json::array();
            for (gp::LatentPrior p : {gp::LatentPrior::kNone, gp::LatentPrior::kSmooth, gp::LatentPrior::kPaced})
                rows.push_back(benchClip(clip, p, false, ctx));
            rows.push_back(benchClip(clip, gp::LatentPrior::kNone, true, ctx));
            out[trial] = rows;
        }
        return out;
    });

}  // namespace
}  // namespace mgp::app
