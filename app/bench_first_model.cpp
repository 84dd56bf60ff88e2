// bench section "first_model": how soon the editor has a model to drag against (docs/maths.md §23).
//  - editor: Train on the default clip (10_02, 590 frames) through the editor's TrainingJob with
//    its default publishing; the seconds from start to the first published model (medians over
//    repeats; each run is cancelled once it has published), and that model's outer iterations;
//  - time_budget_5: `train --time-budget 5` on the same clip (the CLI's training call), its
//    seconds and iterations, measured once;
//  - default_run: the default `train` (T = 30) on the same clip, its seconds (measured once);
//  - the first model's use: a 20 cm hand raise with both feet pinned on 10 frames across the
//    clip, solved as `motiongp pose` solves it: how many reach, how many the model admits, and
//    the median solve time.
#include <chrono>
#include <thread>

#include "bench_registry.h"
#include "edit/training_job.h"
#include "eval/admission.h"
#include "gp/train/trainer.h"
#include "ik/constrained_ik.h"
#include "io/clip_loader.h"
#include "motion/captured_pose_request.h"
#include "skeleton/forward_kinematics.h"

namespace mgp::app {
namespace {

// The 20 cm right-hand raise with both feet pinned, on 10 frames spread over the clip.
nlohmann::json handRaises(const gp::ModelVersionPtr& version) {
    const Clip& clip = version->model->clip;
    const ContactSet contacts = detectFootContacts(clip);
    int reached = 0, admitted = 0, frames = 0;
    std::vector<double> seconds;
    for (int k = 0; k < 10; ++k) {
        const int t = (2 * k + 1) * clip.frameCount() / 20;
        const Pose& pose = clip.frames[t];
        const Eigen::Vector3d hand = effectorCm(clip.skeleton, pose, Effector::kRHand);
        std::vector<IkConstraint> constraints{{Effector::kRHand, hand + Eigen::Vector3d(0, 20, 0), false}};
        for (Effector foot : {Effector::kLFoot, Effector::kRFoot})
            constraints.push_back({foot, effectorCm(clip.skeleton, pose, foot), true});
        ConstrainedIkSolver solver(version);
        const ConstrainedIkRequest request = capturedPoseRequest(*version, t, constraints, contacts, 200);
        ConstrainedIkResult r;
        seconds.push_back(secondsOf([&] { r = solver.solve(request); }));
        ++frames;
        reached += r.reached;
        admitted += admitPose(*version, r.pose, movedEffectors(r.constraints), r.reached, anyBelowFloor(r.constraints),
                              r.sigma2, r.lik, judgeBalance(clip.skeleton, pose, r.pose, contacts, t))
                        .admitted;
    }
    return {
        {"frames", frames}, {"reached", reached}, {"admitted", admitted}, {"solve_seconds", summarizeSeconds(seconds)}};
}

const BenchRegistration firstModelBench(
    "first_model", "From Train to a model the viewport drags against (10_02, 590 frames)", [](const BenchContext& ctx) {
        if (ctx.mocapDir.empty()) return nlohmann::json{{"skipped", "no CMU mocap folder"}};
        const Clip clip = loadClip(ctx.mocapDir + "/asf_amc/10_02.amc");
        const gp::TrainOptions defaults;
        const PublishPolicy policy;
        const int repeats = ctx.quick ? 1 : std::min(ctx.repeats, 5);
        std::vector<double> firstSeconds;
        gp::ModelVersionPtr first;
        for (int r = 0; r < repeats; ++r) {
            TrainingJob job;
            const auto start = std::chrono::steady_clock::now();
            if (const std::string err = job.start(clip, defaults); !err.empty()) return nlohmann::json{{"error", err}};
            gp::ModelVersionPtr published;
            while (!(published = job.takeRefinement()) && job.running())
                std::this_thread::sleep_for(std::chrono::milliseconds(2));
            firstSeconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            job.cancel();
            job.join();
            if (!published) return nlohmann::json{{"error", "the training run published no model"}};
            first = published;
        }
        nlohmann::json out;
        out["clip"] = clip.name;
        out["frames"] = clip.frameCount();
        out["policy"] = {{"first_iterations", policy.firstIterations}, {"every_seconds", policy.everySeconds}};
        out["editor"] = {{"seconds_to_first_model", summarizeSeconds(firstSeconds)},
                         {"iterations", first->model->iterations},
                         {"hand_raise_20cm_feet_pinned", handRaises(first)}};
        if (!ctx.quick) {
            gp::TrainResult full;
            const double fullSeconds = secondsOf([&] { full = gp::trainOnClip(clip, defaults); });
            out["default_run"] = {
                {"seconds", fullSeconds}, {"iterations", full.model.iterations}, {"T", defaults.outerIterations}};
            gp::TrainControl control;
            control.timeBudgetSeconds = 5.0;
            gp::TrainResult budget;
            const double seconds = secondsOf([&] { budget = gp::trainOnClip(clip, defaults, control); });
            out["time_budget_5"] = {
                {"seconds", seconds},
                {"iterations", budget.model.iterations},
                {"stopped_by_budget", budget.outOfTime},
                {"hand_raise_20cm_feet_pinned", handRaises(gp::ModelVersion::make(std::move(budget.model)))}};
        }
        return out;
    });

}  // namespace
}  // namespace mgp::app
