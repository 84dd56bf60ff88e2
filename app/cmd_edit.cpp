// `motiongp edit MODEL --effector EFF --keys 89,103,117,131 --offset dx,dy,dz
//  [--clip NAME] [--mode direct|displacement] [--solver span|per-frame] [--pin EFF]... [--adaptive --out-model MODEL2]
//  --out OUT.bvh|.glb|.gltf|.fbx [--json]`:
// moves the middle keys (frames of --clip NAME, the model clip's file stem; default the first) by the offset,
// regenerates the span and writes the whole clip as BVH (edited frames replaced). `span` (default) solves the span as
// one problem with smoothness and held contacts (motion/span_solver.h); `per-frame` is the paper's independent
// per-frame IK.
#include <algorithm>
#include <chrono>
#include <iostream>

#include "cli_common.h"
#include "command_registry.h"
#include "gp/model_file.h"
#include "gp/train/adaptive_update.h"
#include "ik/locality.h"
#include "ik_cli.h"
#include "motion/motion_edit.h"
#include "motion_quality_json.h"
#include "skeleton/centre_of_mass.h"

namespace mgp::app {
namespace {

struct EditOptions {
    std::string model, effector, keys, offset, mode = "displacement", solver = "span", out, outModel, clip;
    std::vector<std::string> pins;
    bool adaptive = false, json = false, noContacts = false;
    int iterations = 500;
    double locality = kDefaultSpanLocality;
};

int runEdit(const EditOptions& o) {
    if (o.mode != "direct" && o.mode != "displacement")
        throw UsageError("expected --mode direct or displacement, found '" + o.mode + "'");
    if (o.solver != "span" && o.solver != "per-frame")
        throw UsageError("expected --solver span or per-frame, found '" + o.solver + "'");
    requireExportPath(o.out);
    if (o.adaptive && o.outModel.empty()) throw UsageError("expected --out-model MODEL2 with --adaptive, found none");
    const auto t0 = std::chrono::steady_clock::now();
    MotionEditJob job;
    int clipIndex = 0;
    job.version = loadModelVersion(o.model, o.clip, &clipIndex);
    job.effector = parseEffectorOption(o.effector, "--effector");
    job.keyFrames = parseFrameList(o.keys, "--keys");
    const Eigen::Vector3d offset = parseOffset(o.offset, "--offset");
    job.keyOffsetsCm.assign(job.keyFrames.size(), Eigen::Vector3d::Zero());
    // The offset moves the keys between the first and the last (the paper's two middle keys).
    for (std::size_t i = 1; i + 1 < job.keyFrames.size(); ++i) job.keyOffsetsCm[i] = offset;
    job.mode = o.mode == "direct" ? PathMode::kDirect : PathMode::kDisplacement;
    job.maxIterations = o.iterations;
    job.solver = o.solver == "span" ? EditSolver::kSpan : EditSolver::kPerFrame;
    for (const std::string& p : o.pins) job.pins.push_back(parseEffectorOption(p, "--pin"));
    job.holdContacts = !o.noContacts;
    job.spanWeights.locality = o.locality;
    if (o.locality != kDefaultSpanLocality && job.solver != EditSolver::kSpan)
        throw UsageError("expected --solver span with --locality, found --solver " + o.solver);
    if (const std::string problem = job.validate(); !problem.empty()) throw UsageError(problem);
    job.run();
    Clip edited = job.version->model->clip;
    edited.frames = job.frames;
    exportFromCli(edited, o.out);
    nlohmann::json j{{"frames_solved", job.solvedFrames.size()},
                     {"max_residual_cm", job.maxResidualCm},
                     {"locality", o.locality},
                     {"solver", editSolverName(job.solver)},
                     {"max_held_residual_cm", job.maxHeldResidualCm},
                     {"quality", spanQualityJson(job.quality)}};
    // The largest horizontal move of the whole-body centre of mass from the capture over the span.
    double comShift = 0.0;
    bool comKnown = true;
    for (int t : job.solvedFrames) {
        const std::optional<double> s =
            horizontalComShiftCm(edited.skeleton, job.frames[t], job.version->model->clip.frames[t]);
        if (!s)
            comKnown = false;
        else
            comShift = std::max(comShift, *s);
    }
    j["max_com_shift_cm"] = comKnown ? nlohmann::json(comShift) : nlohmann::json(nullptr);
    // Whether every moved key was met, and by how much each missed (one warning line if not).
    j["reached"] = job.keysReached();
    j["keys"] = nlohmann::json::array();
    for (const MotionEditJob::KeyResult& k : job.keys)
        j["keys"].push_back({{"frame", k.frame + 1}, {"reached", k.reached}, {"error_cm", k.errorCm}});
    for (const MotionEditJob::KeyResult& k : job.keys)
        if (!k.reached) {
            std::cerr << "motiongp: warning: the key on frame " << k.frame + 1 << " was missed by " << k.errorCm
                      << " cm (out of reach with what is held, or below the floor)\n";
            break;
        }
    if (job.solver == EditSolver::kSpan)
        j["span"] = {{"stop", spanStopName(job.spanStop)}, {"iterations", job.spanIterations}};
    if (o.adaptive) {
        // The solved poses of the moved keys join the model's samples (not the in-betweens).
        gp::ModelVersionPtr version = job.version;
        int added = 0;
        for (std::size_t k = 1; k + 1 < job.keyFrames.size(); ++k) {
            const auto it = std::find(job.solvedFrames.begin(), job.solvedFrames.end(), job.keyFrames[k]);
            if (it == job.solvedFrames.end()) continue;
            const LearnedIkResult& r = job.results[static_cast<std::size_t>(it - job.solvedFrames.begin())];
            const gp::AdaptiveUpdateResult u = gp::adaptiveUpdate(*version, r.x, r.y, job.keyFrames[k]);
            if (!u.accepted) throw std::runtime_error("adaptive update: " + u.diagnostic);
            version = u.version;
            ++added;
        }
        gp::saveModel(o.outModel, gp::withPrimaryClip(*version->model, clipIndex));  // the file's clip order
        j["adaptive"] = {{"samples_added", added}, {"rows", version->model->N()}, {"out_model", o.outModel}};
    }
    j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (o.json)
        printJson(j);
    else {
        const SpanQuality& q = job.quality;
        std::cout << "solved " << job.solvedFrames.size() << " frames (" << editSolverName(job.solver)
                  << "), max residual " << job.maxResidualCm << " cm; second difference p95 " << q.edited.p95Deg
                  << "° (captured " << q.captured.p95Deg << "°), max " << q.edited.maxDeg << "° (captured "
                  << q.captured.maxDeg << "°); wrote " << o.out << "\n";
    }
    return 0;
}

const CommandRegistration editCommand(
    "edit", "Edit an effector path (Hermite keys) and regenerate the motion", [](CLI::App& sub) -> CommandRunner {
        auto o = std::make_shared<EditOptions>();
        sub.add_option("model", o->model, "Model file")->required();
        sub.add_option("--effector", o->effector, "lhand, rhand, lfoot, rfoot or head")->required();
        sub.add_option("--clip", o->clip,
                       "NAME: which of the model's clips (file stem, e.g. 10_03; default: the first)");
        sub.add_option("--keys", o->keys, "Key frames of that clip counted from 1, e.g. 89,103,117,131")->required();
        sub.add_option("--offset", o->offset, "dx,dy,dz (cm) applied to the middle keys")->required();
        sub.add_option(
            "--mode", o->mode,
            "displacement (default: the captured path plus a smooth offset through the keys) or direct (the paper's "
            "Hermite path through the moved keys)");
        sub.add_option("--solver", o->solver, "span (default: the span as one problem) or per-frame (the paper's)");
        sub.add_option("--pin", o->pins,
                       "Hold this effector at its captured position on every frame of the span (repeatable)");
        sub.add_option(
            "--locality", o->locality,
            "Span solver: how strongly the body away from the edited limb keeps its captured pose, per degree²");
        sub.add_flag("--no-contacts", o->noContacts, "Do not hold the captured foot contacts (motion/foot_contacts.h)");
        sub.add_option("--iterations", o->iterations, "L-BFGS iteration cap (per frame for per-frame, in all for span)")
            ->check(CLI::Range(1, 100000));
        sub.add_flag("--adaptive", o->adaptive, "Add the moved keys' poses to the model (docs/maths.md §11)");
        sub.add_option("--out-model", o->outModel, "Where --adaptive writes the updated model");
        sub.add_option("--out", o->out, "Output .bvh, .glb, .gltf or .fbx (every clip frame, edited ones replaced)")
            ->required();
        sub.add_flag("--json", o->json, "Print one JSON object");
        return [o]() { return runEdit(*o); };
    });

}  // namespace
}  // namespace mgp::app
