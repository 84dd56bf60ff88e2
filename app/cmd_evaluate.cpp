// `motiongp evaluate MODEL [--heldout] [--every K] [--heldout-offsets O1,O2,...] [--heldout-iters T]
//   [--threads N] [--no-yardstick] [--json]`
// Layout quality of a trained model (core/eval/layout_quality.h, docs/maths.md §20):
//  - continuity: consecutive-frame latent step p50/p90/p99 over the median pair distance;
//  - yardstick: full-GP log marginal likelihood per value at the model's X and at its PCA start
//    (RBF + bias + white re-fitted; only for N ≤ 2000);
//  - with --heldout: retrains with the model's own settings on its training frames minus one in
//    K (default 10), places each left-out frame by L_IK from its pose and reports the RMS
//    reconstruction error (degrees, non-root DOFs) next to the nearest-training-frame baseline.
//    --heldout-offsets (implies --heldout) repeats that for several disjoint splits (positions
//    ≡ offset mod K) and reports each one and the mean, sd, min and max: one split alone moves
//    the RMS by more than the gap between training options.
#include <algorithm>
#include <iostream>

#include "cli_common.h"
#include "command_registry.h"
#include "eval/layout_quality.h"
#include "gp/model_file.h"
#include "gp/train/pca_init.h"
#include "gp/train/trainer.h"
#include "io/text_reader.h"
#include "skeleton/pose_layout.h"

namespace mgp::app {

namespace {

nlohmann::json scoreJson(const eval::FullGpScore& s) {
    if (!s.ok) return nullptr;
    return {{"log_likelihood", s.logLikelihood},
            {"per_value", s.perValue},
            {"alpha", s.alpha},
            {"gamma", s.gamma},
            {"bias", s.bias},
            {"noise_variance", s.noiseVariance}};
}

nlohmann::json spreadJson(const eval::Spread& s) {
    return {{"mean", s.mean}, {"sd", s.sd}, {"min", s.min}, {"max", s.max}, {"count", s.count}};
}

// "0,3,6" → {0, 3, 6}: integers in [0, every), no repeats.
std::vector<int> parseOffsets(const std::string& text, int every) {
    std::vector<long long> values;
    if (!parseIntList(text, 0, every - 1, values))
        throw UsageError("expected --heldout-offsets as integers in [0, " + std::to_string(every) +
                         ") separated by commas, found '" + text + "'");
    std::vector<int> out;
    for (long long v : values) {
        if (std::find(out.begin(), out.end(), v) != out.end())
            throw UsageError("expected distinct --heldout-offsets, found " + std::to_string(v) + " twice in '" + text +
                             "'");
        out.push_back(static_cast<int>(v));
    }
    return out;
}

struct EvaluateCliOptions {
    std::string model;
    bool heldout = false, noYardstick = false, json = false;
    int every = 10, heldoutIters = 0, threads = 0;
    std::string offsets;
};

void addEvaluateCliOptions(CLI::App& sub, EvaluateCliOptions& o) {
    sub.add_option("model", o.model, "Model file")->required();
    sub.add_flag("--heldout", o.heldout,
                 "Also retrain without every K-th frame (the model's own settings) and score the reconstruction");
    sub.add_option("--every", o.every, "Hold out every K-th training frame (default 10)");
    sub.add_option(
        "--heldout-offsets", o.offsets,
        "Held-out splits to average, e.g. 0,3,6: positions ≡ offset mod K (0 = every K-th; implies --heldout)");
    sub.add_option("--threads", o.threads, "Threads for Step 8 of the held-out retraining (default: all cores)");
    sub.add_option("--heldout-iters", o.heldoutIters,
                   "Outer iterations of the held-out retraining (default: the model's T)");
    sub.add_flag("--no-yardstick", o.noYardstick, "Skip the full-GP yardstick");
    sub.add_flag("--json", o.json, "Print one JSON object");
}

// Checks the options and returns the held-out offsets; --heldout-offsets turns --heldout on.
std::vector<int> evaluateOffsetsFromCli(EvaluateCliOptions& o) {
    if (o.every < 2) throw UsageError("expected --every ≥ 2, found " + std::to_string(o.every));
    if (o.heldoutIters < 0) throw UsageError("expected --heldout-iters ≥ 1, found " + std::to_string(o.heldoutIters));
    if (o.threads < 0) throw UsageError("expected --threads ≥ 0, found " + std::to_string(o.threads));
    const std::vector<int> offsets = o.offsets.empty() ? std::vector<int>{0} : parseOffsets(o.offsets, o.every);
    if (!o.offsets.empty()) o.heldout = true;
    return offsets;
}

// One entry per source clip, each over its own rows.
std::vector<eval::ContinuityReport> addContinuityJson(const gp::GpModel& model, nlohmann::json& j) {
    std::vector<eval::ContinuityReport> perClip = eval::latentContinuityPerClip(model);
    j["continuity"] = nlohmann::json::array();
    for (int k = 0; k < model.clipCount(); ++k) {
        const eval::ContinuityReport& c = perClip[static_cast<std::size_t>(k)];
        j["continuity"].push_back({{"clip", model.clipName(k)},
                                   {"steps", c.steps},
                                   {"median_pair_distance", c.medianPairDistance},
                                   {"p50", c.p50},
                                   {"p90", c.p90},
                                   {"p99", c.p99},
                                   {"max", c.max}});
    }
    return perClip;
}

nlohmann::json yardstickJson(const EvaluateCliOptions& o, const gp::GpModel& model) {
    if (o.noYardstick) return nullptr;
    if (model.N() > eval::kYardstickMaxRows)
        return {{"skipped", "N = " + std::to_string(model.N()) + " > " + std::to_string(eval::kYardstickMaxRows)}};
    const Eigen::MatrixXd Ybar = model.Y.rowwise() - model.Y.colwise().mean();
    const Eigen::MatrixXd Xpca = gp::whitenedPca(Ybar, model.latentDim()).X;
    const eval::FullGpScore fin = eval::fitFullGp(model.X, model.Y);
    const eval::FullGpScore pca = eval::fitFullGp(Xpca, model.Y);
    return {
        {"final", scoreJson(fin)},
        {"pca_start", scoreJson(pca)},
        {"gain_per_value", fin.ok && pca.ok ? nlohmann::json(fin.perValue - pca.perValue) : nlohmann::json(nullptr)}};
}

// Retrains without one frame in K for each offset and scores the reconstruction.
nlohmann::json heldOutJson(const EvaluateCliOptions& o, const gp::GpModel& model, const std::vector<int>& offsets) {
    gp::TrainOptions opt = eval::trainOptionsOf(model);
    if (o.heldoutIters > 0) opt.outerIterations = o.heldoutIters;
    opt.threads = o.threads;
    eval::HeldOutOffsetsReport h;
    try {
        h = eval::heldOutOverOffsets(model, opt, o.every, offsets);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("with --every ") + std::to_string(o.every) + ": " + e.what());
    }
    nlohmann::json per = nlohmann::json::array();
    double trainSeconds = 0.0;
    for (std::size_t k = 0; k < h.perOffset.size(); ++k) {
        const eval::HeldOutReport& r = h.perOffset[k];
        per.push_back({{"offset", h.offsets[k]},
                       {"held_out", r.heldOut},
                       {"trained", r.trained},
                       {"rms_deg", r.rmsDeg},
                       {"nearest_frame_rms_deg", r.nearestRmsDeg},
                       {"inbetween_rms_deg", r.timeRmsDeg},
                       {"inbetween_frames", r.timeCount},
                       {"median_frame_rms_deg", r.medianFrameRmsDeg},
                       {"worst_frame", {{"frame", r.worstFrame + 1}, {"rms_deg", r.worstFrameRmsDeg}}},
                       {"train_seconds", h.trainSeconds[k]}});
        trainSeconds += h.trainSeconds[k];
    }
    // The top-level RMS values are the means over the offsets (one offset: its values);
    // the counts are the first offset's, every offset's are in per_offset.
    return {{"every", o.every},
            {"offsets", h.offsets},
            {"held_out", h.perOffset[0].heldOut},
            {"trained", h.perOffset[0].trained},
            {"outer_iterations", opt.outerIterations},
            {"rms_deg", h.rmsDeg.mean},
            {"nearest_frame_rms_deg", h.nearestRmsDeg.mean},
            {"inbetween_rms_deg", h.timeRmsDeg.mean},
            {"inbetween_frames", h.perOffset[0].timeCount},
            {"train_seconds", trainSeconds},
            {"spread",
             {{"rms_deg", spreadJson(h.rmsDeg)},
              {"nearest_frame_rms_deg", spreadJson(h.nearestRmsDeg)},
              {"inbetween_rms_deg", spreadJson(h.timeRmsDeg)}}},
            {"per_offset", per}};
}

void printEvaluateText(const EvaluateCliOptions& o, const gp::GpModel& model,
                       const std::vector<eval::ContinuityReport>& perClip, const nlohmann::json& j) {
    std::cout << o.model << ": " << j["kernel"].get<std::string>() << ", prior " << j["prior"].get<std::string>()
              << (model.settings.backConstraints ? ", back-constrained" : "") << ", N = " << model.N() << "\n";
    for (int k = 0; k < model.clipCount(); ++k) {
        const eval::ContinuityReport& c = perClip[static_cast<std::size_t>(k)];
        std::cout << "  continuity of " << model.clipName(k) << " (step / median pair distance): p50 " << c.p50
                  << ", p90 " << c.p90 << ", p99 " << c.p99 << " over " << c.steps << " steps\n";
    }
    if (j["yardstick"].is_object() && j["yardstick"].contains("final"))
        std::cout << "  full-GP yardstick (log-likelihood per value): final " << j["yardstick"]["final"]["per_value"]
                  << ", PCA start " << j["yardstick"]["pca_start"]["per_value"] << "\n";
    if (j["heldout"].is_object()) {
        const auto& h = j["heldout"];
        std::cout << "  held-out reconstruction (one frame in " << o.every << ", offsets " << h["offsets"].dump()
                  << "): RMS " << h["rms_deg"] << " deg (sd " << h["spread"]["rms_deg"]["sd"]
                  << "), nearest training frame " << h["nearest_frame_rms_deg"]
                  << " deg, in-betweened from time neighbours " << h["inbetween_rms_deg"] << " deg\n";
        for (const auto& r : h["per_offset"])
            std::cout << "    offset " << r["offset"] << ": RMS " << r["rms_deg"] << " (median frame "
                      << r["median_frame_rms_deg"] << ", worst frame " << r["worst_frame"]["frame"] << " at "
                      << r["worst_frame"]["rms_deg"] << "), nearest " << r["nearest_frame_rms_deg"] << ", in-between "
                      << r["inbetween_rms_deg"] << " deg\n";
    }
}

int runEvaluate(EvaluateCliOptions& o) {
    const std::vector<int> offsets = evaluateOffsetsFromCli(o);
    const gp::GpModel model = gp::loadModel(o.model);
    // The held-out retraining reads one clip's frame numbers (continuity is measured per clip).
    if (model.clipCount() > 1 && o.heldout)
        throw UsageError(
            "expected a single-clip model for --heldout (the held-out retraining does not handle "
            "multi-clip models yet), found " +
            std::to_string(model.clipCount()) + " clips (" + model.clipNames() + ") in " + o.model);
    nlohmann::json j;
    j["model"] = o.model;
    j["kernel"] = gp::kernelKindName(model.kind);
    j["prior"] = gp::latentPriorName(model.settings.prior);
    if (model.settings.prior != gp::LatentPrior::kNone) j["prior_weight"] = model.settings.priorWeight;
    j["back_constraints"] = model.settings.backConstraints;
    j["N"] = model.N();
    j["M"] = static_cast<int>(model.active.size());
    j["iterations"] = model.iterations;
    const std::vector<eval::ContinuityReport> perClip = addContinuityJson(model, j);
    j["yardstick"] = yardstickJson(o, model);
    j["heldout"] = o.heldout ? heldOutJson(o, model, offsets) : nlohmann::json(nullptr);
    if (o.json) {
        printJson(j);
        return 0;
    }
    printEvaluateText(o, model, perClip, j);
    return 0;
}

const CommandRegistration evaluateCommand(
    "evaluate", "Layout quality of a model: latent continuity, full-GP yardstick, held-out reconstruction",
    [](CLI::App& sub) -> CommandRunner {
        auto o = std::make_shared<EvaluateCliOptions>();
        addEvaluateCliOptions(sub, *o);
        return [o]() { return runEvaluate(*o); };
    });

}  // namespace
}  // namespace mgp::app
