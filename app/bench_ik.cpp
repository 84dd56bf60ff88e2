// bench section "ik": interactive learned-IK drags, adaptive update and span regeneration on a
// real clip with M = 200 (issue 4 §7). All timings are medians/p99 over solves in one run.
#include <cmath>

#include "bench_registry.h"
#include "gp/adaptive_update.h"
#include "gp/trainer.h"
#include "ik/learned_ik.h"
#include "io/clip_loader.h"
#include "motion/motion_edit.h"
#include "skeleton/synthetic_clip.h"

namespace mgp::app {
namespace {

gp::ModelVersionPtr benchModel(const BenchContext& ctx, std::string& name, double& trainSeconds) {
    Clip clip = ctx.mocapDir.empty() ? makeSyntheticWalk(360) : loadClip(ctx.mocapDir + "/asf_amc/35_01.amc");
    name = clip.name;
    gp::TrainOptions options;
    options.activeSize = ctx.quick ? 100 : 200;
    options.outerIterations = ctx.quick ? 1 : 3;
    gp::TrainResult result;
    trainSeconds = secondsOf([&] { result = gp::trainOnClip(std::move(clip), options); });
    return gp::ModelVersion::make(std::move(result.model));
}

double rmsDeg(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return std::sqrt((a - b).squaredNorm() / a.size()); }

nlohmann::json dragBench(const gp::ModelVersionPtr& version, int frame, bool pins, int steps, int cap) {
    const gp::GpModel& m = *version->model;
    const Skeleton& sk = m.clip.skeleton;
    LearnedIkSolver solver(version), reference(version);
    LearnedIkRequest req;
    req.start = m.clip.frames[frame];
    req.startX = latentStartForFrame(*version, frame);
    req.maxIterations = cap;
    FkState fk;
    forwardKinematics(sk, req.start, fk);
    const Eigen::Vector3d hand = effectorCm(sk, fk, Effector::kRHand);
    std::vector<IkConstraint> constraints = {{Effector::kRHand, hand, false}};
    if (pins) {
        constraints.push_back({Effector::kLFoot, effectorCm(sk, fk, Effector::kLFoot), true});
        constraints.push_back({Effector::kRFoot, effectorCm(sk, fk, Effector::kRFoot), true});
    }
    // Settle at the start (not timed), as the UI does when a drag begins.
    req.constraints = constraints;
    req.maxIterations = 2000;
    LearnedIkResult res = solver.solve(req);
    req.maxIterations = cap;
    std::vector<double> seconds, gapF, gapPose, iterations;
    int reached = 0, converged = 0;
    double worstResidual = 0.0;
    LearnedIkResult full;
    for (int s = 1; s <= steps; ++s) {
        req.start = res.pose;
        req.startX = res.x;
        constraints[0].targetCm = hand + Eigen::Vector3d(0.0, 0.25 * s, 0.1 * s);  // up and forward
        req.constraints = constraints;
        seconds.push_back(secondsOf([&] { solver.solve(req, res); }));
        iterations.push_back(res.iterations);
        reached += res.reached;
        converged += res.converged;
        for (const auto& c : res.constraints) worstResidual = std::max(worstResidual, c.residualCm);
        LearnedIkRequest deep = req;
        deep.maxIterations = 5000;
        deep.stallRelative = 1e-12;
        reference.solve(deep, full);
        gapF.push_back(std::abs(res.objective - full.objective) / std::max(1.0, std::abs(full.objective)));
        gapPose.push_back(rmsDeg(res.y, full.y));
    }
    return {{"frame", frame + 1}, {"steps", steps}, {"step_cm", std::hypot(0.25, 0.1)}, {"iteration_cap", cap},
            {"pins", pins ? 2 : 0}, {"solve_seconds", summarizeSeconds(seconds)}, {"iterations", summarizeSeconds(iterations)},
            {"reached_fraction", double(reached) / steps}, {"converged_fraction", double(converged) / steps},
            {"worst_residual_cm", worstResidual},
            {"gap_to_5000_iterations", {{"relative_F", summarizeSeconds(gapF)}, {"pose_rms_deg", summarizeSeconds(gapPose)}}}};
}

const BenchRegistration reg("ik", "Learned IK drag, adaptive update, span regeneration (M = 200)", [](const BenchContext& ctx) {
    std::string clipName;
    double trainSeconds = 0.0;
    const gp::ModelVersionPtr version = benchModel(ctx, clipName, trainSeconds);
    const gp::GpModel& m = *version->model;
    const int steps = ctx.quick ? 20 : 200;
    nlohmann::json out{{"clip", clipName}, {"N", m.N()}, {"M", m.active.size()}, {"D", m.D()},
                       {"model_training_seconds", trainSeconds}};
    out["drag_1_target"] = dragBench(version, 100, false, steps, 50);
    out["drag_1_target_2_pins"] = dragBench(version, 100, true, steps, 50);

    std::vector<double> adaptive;
    for (int r = 0; r < ctx.repeats; ++r) {
        const int row = 10 + 37 * r;
        adaptive.push_back(secondsOf([&] { gp::adaptiveUpdate(*version, m.X.row(row).transpose(), m.Y.row(row).transpose(), row); }));
    }
    out["adaptive_update_seconds"] = summarizeSeconds(adaptive);

    for (int cap : {50, 500}) {
        std::vector<double> regen;
        double residual = 0.0;
        for (int r = 0; r < ctx.repeats; ++r) {
            MotionEditJob job;
            job.version = version;
            job.effector = Effector::kRFoot;
            job.keyFrames = {88, 102, 116, 130};
            job.keyOffsetsCm = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 20, 0), Eigen::Vector3d(0, 20, 0), Eigen::Vector3d::Zero()};
            job.maxIterations = cap;
            regen.push_back(secondsOf([&] { job.run(); }));
            residual = job.maxResidualCm;
        }
        out["regenerate_43_frames_cap_" + std::to_string(cap)] = {{"seconds", summarizeSeconds(regen)}, {"solves", 41},
                                                                 {"max_residual_cm", residual}};
    }
    return out;
});

}  // namespace
}  // namespace mgp::app
