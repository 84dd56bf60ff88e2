// `motiongp train CLIP [CLIP ...] [--skel ASF] [--model fas|sgplvm] [--active M] [--iters T]
//   [--scg-iters S] [--tol C] [--prior paced|smooth|none] [--prior-weight λ] [--frames A:B] [--step K] [--threads N]
//   --out MODEL [--json]`
// Learns a FASGPLVM (default) or SGPLVM pose model (docs/maths.md §8) and writes the model file
// (core/gp/model_file.h). Several clips train one model when they share one skeleton
// (sameSkeleton, skeleton/clip_match.h); otherwise exit 2 naming the first mismatch. --frames and
// --step apply to each clip on its own (frame numbers count within each clip). Retargeting
// between skeletons is out of scope. Progress goes to stderr; --json prints one object on stdout. Timings
// are printed, never stored in the model. Ctrl-C cancels cleanly (no model is written).
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>

#include "cli_common.h"
#include "command_registry.h"
#include "gp/model_file.h"
#include "gp/train/trainer.h"
#include "gp/train/training_clips.h"
#include "io/clip_loader.h"
#include "io/parse_error.h"
#include "skeleton/pose_layout.h"

namespace mgp::app {

namespace {

std::atomic<bool> gCancel{false};
extern "C" void onSigint(int) { gCancel.store(true); }

// "A:B" → frames A..B; whether B fits each clip is gp::selectFrames' check.
gp::FrameSelection parseFrames(const std::string& s, int step) {
    gp::FrameSelection r;
    r.step = step;
    if (s.empty()) return r;
    const auto colon = s.find(':');
    try {
        if (colon == std::string::npos) throw std::invalid_argument("no colon");
        std::size_t used = 0;
        r.first = std::stoi(s.substr(0, colon), &used);
        if (used != colon) throw std::invalid_argument("junk");
        const std::string tail = s.substr(colon + 1);
        r.last = std::stoi(tail, &used);
        if (used != tail.size()) throw std::invalid_argument("junk");
    } catch (const std::exception&) {
        throw UsageError("expected --frames A:B with integers A ≤ B, found '" + s + "'");
    }
    if (r.first < 1 || r.first > r.last)
        throw UsageError("expected --frames A:B with 1 ≤ A ≤ B (clip frames counted from 1), found '" + s + "'");
    return r;
}

void printBar(int iter, int total, double L, double elapsed, bool tty) {
    const int width = 30;
    const int filled = total > 0 ? iter * width / total : width;
    const double eta = iter > 0 ? elapsed / iter * (total - iter) : 0.0;
    char buf[200];
    std::snprintf(buf, sizeof buf, "[%-*s] iter %d/%d  L_GP %.6g  ETA %.0f s (upper bound)", width,
                  std::string(static_cast<std::size_t>(filled), '#').c_str(), iter, total, L, eta);
    std::cerr << (tty ? "\r" : "") << buf << (tty ? "" : "\n") << std::flush;
}

struct TrainCliOptions {
    std::vector<std::string> clips;
    std::string skel, model = "fas", frames, out, prior = gp::latentPriorName(gp::TrainOptions{}.prior);
    double priorWeight = 0.0;
    CLI::Option* priorWeightOption = nullptr;  // unset: gp::defaultPriorWeight(T)
    int active = 200, iters = gp::TrainOptions{}.outerIterations, scgIters = 100, step = 1, threads = 0;
    double tol = 0.01, timeBudget = 0.0;
    bool json = false, backConstraints = false;
};

void addTrainCliOptions(CLI::App& sub, TrainCliOptions& o) {
    sub.add_option("clip", o.clips,
                   "Clip file(s) of one skeleton: AMC of one ASF subject (10_02.amc 10_03.amc) or BVH of one "
                   "hierarchy (a BVH trains on its own rotation channels; its rest frame is skipped)")
        ->required();
    sub.add_option("--skel", o.skel, "ASF skeleton (default: SS.asf beside SS_TT.amc)");
    sub.add_option("--model", o.model, "fas (FASGPLVM, default) or sgplvm");
    sub.add_option("--active", o.active, "Active set size M (default 200; M ≥ N uses every frame)");
    sub.add_option(
        "--iters", o.iters,
        "Outer iterations T of Steps 5-10 (default " + std::to_string(gp::TrainOptions{}.outerIterations) + ")");
    sub.add_option("--scg-iters", o.scgIters, "SCG iterations per Step 6 (default 100)");
    sub.add_option("--tol", o.tol, "Step-9 threshold C on max |Δparam| (default 0.01)");
    sub.add_option("--prior", o.prior,
                   std::string("Temporal prior on the latent points: paced (second differences over the pose's own "
                               "pace), smooth (second differences over time) or none (the paper's model); default ") +
                       gp::latentPriorName(gp::TrainOptions{}.prior));
    o.priorWeightOption = sub.add_option(
        "--prior-weight", o.priorWeight,
        "Weight λ of the paced or smooth prior (default: 100 for T ≤ 10, 30 for T ≥ 30, log-linear between)");
    sub.add_flag("--back-constraints", o.backConstraints,
                 "Make the latent points a smooth function of the poses (X = K A; Step 8 is skipped)");
    sub.add_option("--frames", o.frames, "Keep frames A..B (from 1, inclusive) of each clip, e.g. 1:180");
    sub.add_option("--step", o.step, "Then keep every K-th frame of each clip (default 1)");
    sub.add_option("--threads", o.threads, "Threads for Step 8 (default: all cores; results do not depend on it)");
    sub.add_option("--time-budget", o.timeBudget,
                   "Write the model as it stands once S seconds from the command's start would pass before "
                   "another outer iteration ends (default: no budget; at least one iteration runs)");
    sub.add_option("--out", o.out, "Model file to write")->required();
    sub.add_flag("--json", o.json, "Print one JSON object");
}

// The options checked (UsageError naming the first bad one) and turned into the trainer's.
gp::TrainOptions trainOptionsFromCli(const TrainCliOptions& o) {
    gp::KernelKind kind;
    if (!gp::parseKernelKind(o.model, kind))
        throw UsageError("expected --model fas or sgplvm, found '" + o.model + "'");
    if (o.active < 1) throw UsageError("expected --active ≥ 1, found " + std::to_string(o.active));
    if (o.iters < 1) throw UsageError("expected --iters ≥ 1, found " + std::to_string(o.iters));
    if (o.scgIters < 1) throw UsageError("expected --scg-iters ≥ 1, found " + std::to_string(o.scgIters));
    if (o.step < 1) throw UsageError("expected --step ≥ 1, found " + std::to_string(o.step));
    if (!(o.tol > 0.0) || !std::isfinite(o.tol)) throw UsageError("expected --tol > 0, found " + std::to_string(o.tol));
    gp::LatentPrior prior;
    if (!gp::parseLatentPrior(o.prior, prior))
        throw UsageError("expected --prior paced, smooth or none, found '" + o.prior + "'");
    const bool weightGiven = o.priorWeightOption->count() > 0;
    if (weightGiven && (!(o.priorWeight >= 0.0) || !std::isfinite(o.priorWeight)))
        throw UsageError("expected --prior-weight ≥ 0, found " + std::to_string(o.priorWeight));
    if (o.threads < 0) throw UsageError("expected --threads ≥ 0, found " + std::to_string(o.threads));
    if (!(o.timeBudget >= 0.0) || !std::isfinite(o.timeBudget))
        throw UsageError("expected --time-budget ≥ 0 seconds, found " + std::to_string(o.timeBudget));

    gp::TrainOptions opt;
    opt.kind = kind;
    opt.activeSize = o.active;
    opt.outerIterations = o.iters;
    opt.scgIterations = o.scgIters;
    opt.tolerance = o.tol;
    opt.threads = o.threads;
    opt.prior = prior;
    if (weightGiven) opt.priorWeight = o.priorWeight;
    opt.backConstraints = o.backConstraints;
    return opt;
}

// The clips as the trainer takes them, with the counts the report needs.
struct TrainInput {
    gp::FrameSelection selection;
    std::vector<gp::TrainingClip> clips;
    std::vector<std::size_t> frameCounts;  // kept frames per clip
    std::size_t rows = 0;
    gp::TrainingData data;
};

TrainInput loadTrainInput(const TrainCliOptions& o) {
    // Every clip is loaded and checked before training starts (gp::prepareTrainingClips, the
    // editor's Train on clips… takes the same path). One range for all clips: each clip's own
    // frame count bounds it.
    TrainInput in;
    in.selection = parseFrames(o.frames, o.step);
    std::vector<Clip> loaded;
    for (const std::string& path : o.clips) loaded.push_back(loadClip(path, o.skel));
    try {
        in.clips = gp::prepareTrainingClips(std::move(loaded), o.clips, in.selection);
    } catch (const gp::TrainingInputError& e) {
        throw UsageError(e.what());
    }
    for (const gp::TrainingClip& c : in.clips) {
        in.frameCounts.push_back(c.frames.size());
        in.rows += c.frames.size();
    }
    try {
        in.data = gp::trainingDataOf(in.clips);
    } catch (const std::invalid_argument& e) {  // degenerate data (NaN, nothing varies): bad input
        std::string names;
        for (const std::string& p : o.clips) names += (names.empty() ? "" : ", ") + p;
        throw ParseError(names + ": " + e.what());
    }
    return in;
}

struct TrainRun {
    gp::TrainResult result;
    std::string clipList;  // "10_02 + 10_03"
    double seconds = 0.0;  // training only, not loading
};

// Trains with a progress bar on stderr; Ctrl-C cancels (result.cancelled).
TrainRun runTraining(const TrainCliOptions& o, const gp::TrainOptions& opt, const TrainInput& in,
                     std::chrono::steady_clock::time_point commandStart) {
    TrainRun run;
    const bool tty = ::isatty(2) != 0;
    const auto t0 = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    for (const gp::TrainingClip& c : in.clips) run.clipList += (run.clipList.empty() ? "" : " + ") + c.clip.name;
    std::cerr << "train: " << gp::kernelKindName(opt.kind) << " on " << run.clipList << ", N = " << in.rows
              << ", D = " << in.data.Y.cols() << ", M = " << std::min<int>(o.active, static_cast<int>(in.rows))
              << ", T = " << o.iters << ", prior " << gp::latentPriorName(opt.prior)
              << (o.backConstraints ? ", back-constrained" : "") << "\n";
    gCancel.store(false);
    auto previous = std::signal(SIGINT, onSigint);
    gp::TrainControl control;
    control.afterIteration = [&](const gp::Trainer& t) {
        printBar(t.log().back().iter, o.iters, t.log().back().L, elapsed(), tty);
    };
    control.cancel = &gCancel;
    if (o.timeBudget > 0.0) {
        const double spent = std::chrono::duration<double>(t0 - commandStart).count();
        control.timeBudgetSeconds = std::max(1e-9, o.timeBudget - spent);
    }
    run.result = gp::train(in.data, opt, control);
    std::signal(SIGINT, previous);
    if (tty) std::cerr << "\n";
    if (!run.result.cancelled) run.seconds = elapsed();
    return run;
}

nlohmann::json trainReportJson(const TrainCliOptions& o, const gp::TrainOptions& opt, const gp::GpModel& model,
                               const TrainRun& run, const std::vector<std::size_t>& frameCounts) {
    const gp::TrainResult& res = run.result;
    const gp::Kernel k = model.kernel();
    nlohmann::json j;
    j["model"] = gp::kernelKindName(opt.kind);
    j["prior"] = gp::latentPriorName(opt.prior);
    if (opt.prior != gp::LatentPrior::kNone) j["prior_weight"] = opt.resolvedPriorWeight();
    j["N"] = model.N();
    nlohmann::json clipsJson = nlohmann::json::array();
    for (int c = 0; c < model.clipCount(); ++c)
        clipsJson.push_back({{"name", model.clipName(c)},
                             {"frames", frameCounts[static_cast<std::size_t>(c)]},
                             {"sha256", model.clipSha256(c)}});
    j["clips"] = clipsJson;
    j["pose_dofs"] = PoseLayout(model.clip.skeleton).size();  // P: 47 for ASF, the channels for BVH
    j["D"] = model.D();
    j["latent_dim"] = model.latentDim();
    j["M"] = static_cast<int>(model.active.size());
    j["iterations"] = model.iterations;
    j["converged"] = res.converged;
    j["stopped"] = res.converged ? "converged" : res.outOfTime ? "time budget" : "iterations";
    j["L_init"] = res.lInit;
    j["params"] = {{"alpha", k.alpha()},
                   {"beta", k.beta()},
                   {"gamma", k.gamma()},
                   {"eta", k.hasEta() ? nlohmann::json(k.eta()) : nlohmann::json(nullptr)}};
    nlohmann::json log = nlohmann::json::array();
    for (const auto& e : res.log)
        log.push_back({{"iter", e.iter},
                       {"L", e.L},
                       {"max_delta_raw", e.maxDeltaRaw},
                       {"max_delta_log", e.maxDeltaLog},
                       {"active_overlap", e.activeOverlap},
                       {"grad_inf", e.gradInf},
                       {"jitter", e.jitter},
                       {"trial_jitter_max", e.trialJitterMax},
                       {"seconds", e.seconds}});
    j["log"] = log;
    j["seconds"] = run.seconds;
    j["out"] = o.out;
    return j;
}

void printTrainSummary(const TrainCliOptions& o, const gp::TrainOptions& opt, const gp::GpModel& model,
                       const TrainRun& run) {
    const gp::TrainResult& res = run.result;
    const gp::Kernel k = model.kernel();
    std::cout << "trained " << gp::kernelKindName(opt.kind) << " on " << run.clipList << ": N = " << model.N()
              << ", D = " << model.D() << ", M = " << model.active.size() << ", " << model.iterations << " iterations ("
              << (res.converged   ? "converged"
                  : res.outOfTime ? "time budget"
                                  : "not converged")
              << "), L_GP " << res.lInit << " -> " << (res.log.empty() ? res.lInit : res.log.back().L) << ", alpha "
              << k.alpha() << " beta " << k.beta() << " gamma " << k.gamma();
    if (k.hasEta()) std::cout << " eta " << k.eta();
    std::cout << ", " << run.seconds << " s -> " << o.out << "\n";
}

int runTrain(const TrainCliOptions& o) {
    const auto commandStart = std::chrono::steady_clock::now();  // the budget counts loading too
    const gp::TrainOptions opt = trainOptionsFromCli(o);
    TrainInput in = loadTrainInput(o);
    TrainRun run = runTraining(o, opt, in, commandStart);
    if (run.result.cancelled) {
        std::cerr << "train: cancelled after " << run.result.log.size() << " iterations; no model written\n";
        return 130;
    }
    gp::GpModel& model = run.result.model;
    gp::attachTrainingClips(model, std::move(in.clips), in.selection);
    gp::saveModel(o.out, model);
    const nlohmann::json j = trainReportJson(o, opt, model, run, in.frameCounts);
    if (o.json)
        printJson(j);
    else
        printTrainSummary(o, opt, model, run);
    return 0;
}

const CommandRegistration trainCommand("train", "Learn a FASGPLVM or SGPLVM pose model from an ASF/AMC clip",
                                       [](CLI::App& sub) -> CommandRunner {
                                           auto o = std::make_shared<TrainCliOptions>();
                                           addTrainCliOptions(sub, *o);
                                           return [o]() { return runTrain(*o); };
                                       });

}  // namespace
}  // namespace mgp::app
