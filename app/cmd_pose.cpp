// `motiongp pose MODEL --frame T --target EFF=dx,dy,dz ... [--pin EFF ...] [--solver learned|plain]
//  [--adaptive --out-model MODEL2] [--json]`: one IK solve on a frame of the model's source clip.
// Offsets are cm from the effector's position in that frame. An unreachable target is a result
// (reached: false, exit 0), not an error.
#include <chrono>
#include <iostream>

#include "cli_common.h"
#include "command_registry.h"
#include "gp/adaptive_update.h"
#include "gp/model_file.h"
#include "ik/learned_ik.h"
#include "ik/plain_ik.h"
#include "ik_cli.h"

namespace mgp::app {
namespace {

struct PoseOptions {
    std::string model, solver = "learned", outModel;
    long long frame = 1;
    std::vector<std::string> targets, pins;
    bool adaptive = false, json = false;
    int iterations = 500;
};

int runPose(const PoseOptions& o) {
    if (o.solver != "learned" && o.solver != "plain")
        throw UsageError("expected --solver learned or plain, found '" + o.solver + "'");
    if (o.adaptive && o.outModel.empty()) throw UsageError("expected --out-model MODEL2 with --adaptive, found none");
    if (o.adaptive && o.solver == "plain") throw UsageError("expected --solver learned with --adaptive, found plain");
    if (o.targets.empty() && o.pins.empty()) throw UsageError("expected at least one --target or --pin, found none");
    const auto t0 = std::chrono::steady_clock::now();
    const gp::ModelVersionPtr version = loadModelVersion(o.model);
    const gp::GpModel& m = *version->model;
    const Clip& clip = m.clip;
    const int frame = frameIndexFromCli(clip, o.frame);
    FkState fk;
    forwardKinematics(clip.skeleton, clip.frames[frame], fk);
    std::vector<IkConstraint> constraints;
    for (const std::string& t : o.targets) {
        const auto [eff, offset] = parseTarget(t);
        constraints.push_back({eff, effectorCm(clip.skeleton, fk, eff) + offset, false});
    }
    for (const std::string& p : o.pins) {
        const Effector eff = parseEffectorOption(p, "--pin");
        constraints.push_back({eff, effectorCm(clip.skeleton, fk, eff), true});
    }
    nlohmann::json j;
    Pose pose;
    std::vector<IkConstraintResult> results;
    bool reached = false;
    if (o.solver == "plain") {
        PlainIkJob job;
        job.skeleton = &clip.skeleton;
        job.start = clip.frames[frame];
        job.constraints = constraints;
        if (const std::string problem = job.validate(); !problem.empty()) throw UsageError(problem);
        job.solve();
        pose = job.pose;
        results = job.results;
        reached = job.reached;
        j["x"] = nullptr;
        j["sigma2"] = nullptr;
        j["L_IK"] = nullptr;
        j["diagnostic"] = job.diagnostic;
    } else {
        LearnedIkSolver solver(version);
        LearnedIkRequest req;
        req.start = clip.frames[frame];
        req.startX = latentStartForFrame(*version, frame);
        req.constraints = constraints;
        req.maxIterations = o.iterations;
        if (const std::string problem = solver.validate(req); !problem.empty()) throw UsageError(problem);
        const LearnedIkResult r = solver.solve(req);
        pose = r.pose;
        results = r.constraints;
        reached = r.reached;
        j["x"] = std::vector<double>(r.x.data(), r.x.data() + r.x.size());
        j["sigma2"] = r.sigma2;
        j["L_IK"] = r.lik;
        j["diagnostic"] = r.diagnostic;
        j["iterations"] = r.iterations;
        if (o.adaptive) {
            const gp::AdaptiveUpdateResult u = gp::adaptiveUpdate(*version, r.x, r.y, frame);
            if (!u.accepted) throw std::runtime_error("adaptive update: " + u.diagnostic);
            gp::saveModel(o.outModel, *u.version->model);
            j["adaptive"] = {{"rows", u.version->model->N()}, {"new_point_active", u.newPointActive},
                             {"active_changed", u.activeChanged}, {"out_model", o.outModel}};
        }
    }
    j["reached"] = reached;
    j["targets"] = constraintsJson(results, false);
    j["pins"] = constraintsJson(results, true);
    const Eigen::VectorXd y47 = PoseLayout(clip.skeleton).extract(pose);
    j["pose_deg"] = std::vector<double>(y47.data(), y47.data() + y47.size());
    Clip solved = clip;
    solved.frames = {pose};
    j["positions_cm"] = effectorPositionsJson(solved, 0);
    j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (o.json) {
        printJson(j);
    } else {
        std::cout << (reached ? "reached" : "NOT reached") << " (" << j["diagnostic"].get<std::string>() << ")\n";
        for (const auto& r : results)
            std::cout << "  " << (r.pin ? "pin    " : "target ") << effectorName(r.effector) << ": residual "
                      << r.residualCm << " cm" << (r.reached ? "" : "  (not reached)") << "\n";
    }
    return 0;
}

const CommandRegistration reg("pose", "Solve IK on one frame of a model's clip (learned or plain)",
                              [](CLI::App& sub) -> CommandRunner {
    auto o = std::make_shared<PoseOptions>();
    sub.add_option("model", o->model, "Model file (motiongp train --out)")->required();
    sub.add_option("--frame", o->frame, "Clip frame, counted from 1")->required();
    sub.add_option("--target", o->targets, "EFF=dx,dy,dz: move an effector by this many cm (repeatable)");
    sub.add_option("--pin", o->pins, "EFF: hold an effector where it is (repeatable)");
    sub.add_option("--solver", o->solver, "learned (default) or plain (no prior)");
    sub.add_option("--iterations", o->iterations, "L-BFGS iteration cap")->check(CLI::Range(1, 100000));
    sub.add_flag("--adaptive", o->adaptive, "Add the solved pose to the model (§5.3) and save it");
    sub.add_option("--out-model", o->outModel, "Where --adaptive writes the updated model");
    sub.add_flag("--json", o->json, "Print one JSON object");
    return [o]() { return runPose(*o); };
});

}  // namespace
}  // namespace mgp::app
