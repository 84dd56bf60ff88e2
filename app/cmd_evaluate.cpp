// `motiongp evaluate MODEL [--heldout] [--every K] [--heldout-iters T] [--no-yardstick] [--json]`
// Layout quality of a trained model (core/eval/layout_quality.h, docs/maths.md §20):
//  - continuity: consecutive-frame latent step p50/p90/p99 over the median pair distance;
//  - yardstick: full-GP log marginal likelihood per value at the model's X and at its PCA start
//    (RBF + bias + white re-fitted; only for N ≤ 2000);
//  - with --heldout: retrains with the model's own settings on its training frames minus every
//    K-th one (default 10), places each left-out frame by L_IK from its pose and reports the RMS
//    reconstruction error (degrees, non-root DOFs) next to the nearest-training-frame baseline.
#include <chrono>
#include <iostream>

#include "cli_common.h"
#include "command_registry.h"
#include "eval/layout_quality.h"
#include "gp/model_file.h"
#include "gp/pca_init.h"
#include "gp/trainer.h"
#include "skeleton/pose_layout.h"

namespace mgp::app {

namespace {

nlohmann::json scoreJson(const eval::FullGpScore& s) {
    if (!s.ok) return nullptr;
    return {{"log_likelihood", s.logLikelihood}, {"per_value", s.perValue}, {"alpha", s.alpha}, {"gamma", s.gamma},
            {"bias", s.bias}, {"noise_variance", s.noiseVariance}};
}

const CommandRegistration reg(
    "evaluate", "Layout quality of a model: latent continuity, full-GP yardstick, held-out reconstruction",
    [](CLI::App& sub) -> CommandRunner {
        struct Opts {
            std::string model;
            bool heldout = false, noYardstick = false, json = false;
            int every = 10, heldoutIters = 0;
        };
        auto o = std::make_shared<Opts>();
        sub.add_option("model", o->model, "Model file")->required();
        sub.add_flag("--heldout", o->heldout,
                     "Also retrain without every K-th frame (the model's own settings) and score the reconstruction");
        sub.add_option("--every", o->every, "Hold out every K-th training frame (default 10)");
        sub.add_option("--heldout-iters", o->heldoutIters, "Outer iterations of the held-out retraining (default: the model's T)");
        sub.add_flag("--no-yardstick", o->noYardstick, "Skip the full-GP yardstick");
        sub.add_flag("--json", o->json, "Print one JSON object");
        return [o]() {
            if (o->every < 2) throw UsageError("expected --every ≥ 2, found " + std::to_string(o->every));
            if (o->heldoutIters < 0) throw UsageError("expected --heldout-iters ≥ 1, found " + std::to_string(o->heldoutIters));
            const gp::GpModel model = gp::loadModel(o->model);
            nlohmann::json j;
            j["model"] = o->model;
            j["kernel"] = gp::kernelKindName(model.kind);
            j["prior"] = gp::latentPriorName(model.settings.prior);
            if (model.settings.prior != gp::LatentPrior::kNone) j["prior_weight"] = model.settings.priorWeight;
            j["N"] = model.N();
            j["M"] = static_cast<int>(model.active.size());
            j["iterations"] = model.iterations;

            // One clip per model file: the continuity list has one entry.
            const eval::ContinuityReport c = eval::latentContinuity(model.X, model.trainingFrames);
            j["continuity"] = nlohmann::json::array({{{"clip", model.clip.name}, {"steps", c.steps},
                                                      {"median_pair_distance", c.medianPairDistance}, {"p50", c.p50},
                                                      {"p90", c.p90}, {"p99", c.p99}, {"max", c.max}}});
            if (o->noYardstick) {
                j["yardstick"] = nullptr;
            } else if (model.N() > eval::kYardstickMaxRows) {
                j["yardstick"] = {{"skipped", "N = " + std::to_string(model.N()) + " > " +
                                                  std::to_string(eval::kYardstickMaxRows)}};
            } else {
                const Eigen::MatrixXd Ybar = model.Y.rowwise() - model.Y.colwise().mean();
                const Eigen::MatrixXd Xpca = gp::whitenedPca(Ybar, model.latentDim()).X;
                const eval::FullGpScore fin = eval::fitFullGp(model.X, model.Y);
                const eval::FullGpScore pca = eval::fitFullGp(Xpca, model.Y);
                j["yardstick"] = {{"final", scoreJson(fin)}, {"pca_start", scoreJson(pca)},
                                  {"gain_per_value", fin.ok && pca.ok ? nlohmann::json(fin.perValue - pca.perValue)
                                                                      : nlohmann::json(nullptr)}};
            }
            if (o->heldout) {
                const eval::HeldOutSplit split = eval::everyNthHeldOut(model.trainingFrames, o->every);
                if (split.trainFrames.size() < 3 || split.heldFrames.empty())
                    throw UsageError("expected at least 3 training and 1 held-out frame with --every " +
                                     std::to_string(o->every) + ", found " + std::to_string(split.trainFrames.size()) +
                                     " and " + std::to_string(split.heldFrames.size()));
                gp::TrainOptions opt = eval::trainOptionsOf(model);
                if (o->heldoutIters > 0) opt.outerIterations = o->heldoutIters;
                const auto t0 = std::chrono::steady_clock::now();
                gp::TrainResult r = gp::train(gp::trainingDataFromClip(model.clip, split.trainFrames), opt);
                r.model.clip = model.clip;
                const double trainSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                const eval::HeldOutReport h = eval::heldOutReconstruction(r.model, split.heldFrames);
                j["heldout"] = {{"every", o->every}, {"held_out", h.heldOut}, {"trained", h.trained},
                                {"outer_iterations", opt.outerIterations}, {"rms_deg", h.rmsDeg},
                                {"nearest_frame_rms_deg", h.nearestRmsDeg}, {"inbetween_rms_deg", h.timeRmsDeg},
                                {"inbetween_frames", h.timeCount}, {"train_seconds", trainSeconds}};
            } else {
                j["heldout"] = nullptr;
            }
            if (o->json) {
                printJson(j);
                return 0;
            }
            std::cout << o->model << ": " << j["kernel"].get<std::string>() << ", prior " << j["prior"].get<std::string>()
                      << ", N = " << model.N() << "\n";
            std::cout << "  continuity (step / median pair distance): p50 " << c.p50 << ", p90 " << c.p90 << ", p99 "
                      << c.p99 << " over " << c.steps << " steps\n";
            if (j["yardstick"].is_object() && j["yardstick"].contains("final"))
                std::cout << "  full-GP yardstick (log-likelihood per value): final " << j["yardstick"]["final"]["per_value"]
                          << ", PCA start " << j["yardstick"]["pca_start"]["per_value"] << "\n";
            if (j["heldout"].is_object())
                std::cout << "  held-out reconstruction (every " << o->every << "th frame): RMS "
                          << j["heldout"]["rms_deg"] << " deg, nearest training frame "
                          << j["heldout"]["nearest_frame_rms_deg"] << " deg, in-betweened from time neighbours "
                          << j["heldout"]["inbetween_rms_deg"] << " deg\n";
            return 0;
        };
    });

}  // namespace
}  // namespace mgp::app
