// bench section "ik": interactive learned-IK drags, adaptive update and span regeneration on
// real clips with M = 200. All timings are medians/p99 over solves in one run.
//
// Drags: the right hand moves 0.27 cm per event (0.25 up, 0.1 forward) for 200 events from a
// settled start, alone or with both feet pinned, 50-iteration cap per event, each event warm
// started from the previous one. Per drag: converged_fraction, worst pin residual, worst
// residual of reachable targets (those a fully converged solve reaches within 0.05 cm), ms per
// event (each event's time is the median of --repeats solves of that same event from the same
// warm start: the solve is deterministic, so the median is its cost without the shared machine's
// one-off scheduling stalls, which otherwise decided the p99 over events), the p99 over events of
// the largest DOF change between successive events (continuity),
// and the gap to a fully converged solve of the same event from the same warm start (objective,
// and the largest effector distance in cm). "constrained" is the editor's solver
// (core/ik/constrained_ik.h); "lbfgs" is the paper's λ-penalty L-BFGS (core/ik/learned_ik.h).
//
// Cold starts ("cold_start", constrained solver): what `motiongp pose --iterations 50` does, from
// the captured pose and the frame's latent point with the feet in ground contact held as pins:
// right hand, left hand and right foot moved by six offsets of 20–50 cm on frames 30, 90 and 150.
// A move counts as reachable when a 500-iteration solve meets its target to 0.05 cm.
#include <algorithm>
#include <cmath>

#include "bench_registry.h"
#include "gp/train/adaptive_update.h"
#include "gp/train/trainer.h"
#include "ik/constrained_ik.h"
#include "ik/learned_ik.h"
#include "ik_cli.h"
#include "io/clip_loader.h"
#include "motion/captured_pose_request.h"
#include "motion/foot_contacts.h"
#include "motion/motion_edit.h"
#include "skeleton/synthetic_clip.h"

namespace mgp::app {
namespace {

constexpr int kDragFrame = 100;
constexpr int kEventCap = 50;

gp::ModelVersionPtr benchModel(const BenchContext& ctx, const std::string& file, std::string& name,
                               double& trainSeconds) {
    Clip clip = ctx.mocapDir.empty() ? makeSyntheticWalk(360) : loadClip(ctx.mocapDir + "/asf_amc/" + file);
    name = clip.name;
    gp::TrainOptions options;
    options.activeSize = ctx.quick ? 100 : 200;
    options.outerIterations = ctx.quick ? 1 : 3;
    gp::TrainResult result;
    trainSeconds = secondsOf([&] { result = gp::trainOnClip(std::move(clip), options); });
    return gp::ModelVersion::make(std::move(result.model));
}

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, static_cast<std::size_t>(q * (v.size() - 1) + 0.5))];
}

double effectorGapCm(const Skeleton& sk, const Pose& a, const Pose& b) {
    FkState fa, fb;
    forwardKinematics(sk, a, fa);
    forwardKinematics(sk, b, fb);
    double worst = 0.0;
    for (int e = 0; e < kEffectorCount; ++e)
        if (sk.hasEffector(static_cast<Effector>(e)))
            worst = std::max(
                worst,
                (effectorCm(sk, fa, static_cast<Effector>(e)) - effectorCm(sk, fb, static_cast<Effector>(e))).norm());
    return worst;
}

// What both solvers report per event, in one shape.
struct EventOutcome {
    Pose pose;
    Eigen::VectorXd x, y;
    double objective = 0.0;
    bool converged = false;
    int iterations = 0;
    std::vector<IkConstraintResult> constraints;
};

struct DragStats {
    std::vector<double> ms, iterations, dofChange, gapF, gapCm;
    int converged = 0, reachable = 0, events = 0;
    double worstPin = 0.0, worstReachableTarget = 0.0, worstTarget = 0.0;

    nlohmann::json json() const {
        auto msSummary = summarizeSeconds(ms);
        return {
            {"events", events},
            {"converged_fraction", double(converged) / std::max(1, events)},
            {"worst_pin_residual_cm", worstPin},
            {"reachable_events", reachable},
            {"worst_reachable_target_residual_cm", worstReachableTarget},
            {"worst_target_residual_cm", worstTarget},
            {"ms_per_event", msSummary},
            {"iterations", summarizeSeconds(iterations)},
            {"p99_max_dof_change_deg", quantile(dofChange, 0.99)},
            {"max_dof_change_deg", dofChange.empty() ? 0.0 : *std::max_element(dofChange.begin(), dofChange.end())},
            {"gap_to_converged", {{"objective", summarizeSeconds(gapF)}, {"effector_cm", summarizeSeconds(gapCm)}}}};
    }
};

template <class SolveEvent, class SolveReference>
nlohmann::json runDrag(const gp::ModelVersionPtr& version, bool pins, int steps, int repeats, SolveEvent solveEvent,
                       SolveReference solveReference) {
    const gp::GpModel& m = *version->model;
    const Skeleton& sk = m.clip.skeleton;
    const int frame = std::min(kDragFrame, m.clip.frameCount() - 1);
    Pose pose = m.clip.frames[frame];
    Eigen::VectorXd x = latentStartForFrame(*version, frame);
    FkState fk;
    forwardKinematics(sk, pose, fk);
    const Eigen::Vector3d hand = effectorCm(sk, fk, Effector::kRHand);
    std::vector<IkConstraint> constraints = {{Effector::kRHand, hand, false}};
    if (pins) {
        constraints.push_back({Effector::kLFoot, effectorCm(sk, fk, Effector::kLFoot), true});
        constraints.push_back({Effector::kRFoot, effectorCm(sk, fk, Effector::kRFoot), true});
    }
    // Settle at the start (not timed), as the UI does when a drag begins.
    EventOutcome prev = solveReference(pose, x, constraints);
    DragStats st;
    for (int s = 1; s <= steps; ++s) {
        constraints[0].targetCm = hand + Eigen::Vector3d(0.0, 0.25 * s, 0.1 * s);
        EventOutcome out;
        std::vector<double> repeatMs;
        for (int r = 0; r < repeats; ++r)
            repeatMs.push_back(1e3 * secondsOf([&] { out = solveEvent(prev.pose, prev.x, constraints); }));
        st.ms.push_back(quantile(repeatMs, 0.5));
        ++st.events;
        st.iterations.push_back(out.iterations);
        st.converged += out.converged;
        const EventOutcome ref = solveReference(prev.pose, prev.x, constraints);
        const bool reachable = ref.constraints[0].residualCm <= 0.05;
        st.reachable += reachable;
        for (const auto& c : out.constraints) {
            if (c.pin)
                st.worstPin = std::max(st.worstPin, c.residualCm);
            else {
                st.worstTarget = std::max(st.worstTarget, c.residualCm);
                if (reachable) st.worstReachableTarget = std::max(st.worstReachableTarget, c.residualCm);
            }
        }
        st.dofChange.push_back((out.y - prev.y).cwiseAbs().maxCoeff());
        st.gapF.push_back(std::abs(out.objective - ref.objective));
        st.gapCm.push_back(effectorGapCm(sk, out.pose, ref.pose));
        prev = std::move(out);
    }
    nlohmann::json j = st.json();
    j["frame"] = frame + 1;
    j["steps"] = steps;
    j["step_cm"] = std::hypot(0.25, 0.1);
    j["iteration_cap"] = kEventCap;
    j["repeats_per_event"] = repeats;
    j["pins"] = pins ? 2 : 0;
    return j;
}

nlohmann::json constrainedDrag(const gp::ModelVersionPtr& version, bool pins, int steps, int repeats) {
    ConstrainedIkSolver solver(version), reference(version);
    ConstrainedIkRequest req;
    ConstrainedIkResult res;
    auto run = [&](ConstrainedIkSolver& s, const Pose& pose, const Eigen::VectorXd& x,
                   const std::vector<IkConstraint>& cs, int cap, double tolAbs, double tolRel) {
        req.start = pose;
        req.startX = x;
        req.constraints = cs;
        req.maxIterations = cap;
        req.stationarityAbsolute = tolAbs;
        req.stationarityRelative = tolRel;
        req.rootReferenceDeg =
            version->model->clip.frames[std::min(kDragFrame, version->model->clip.frameCount() - 1)].anglesDeg[0];
        s.solve(req, res);
        return EventOutcome{res.pose, res.x, res.y, res.objective, res.converged, res.iterations, res.constraints};
    };
    return runDrag(
        version, pins, steps, repeats,
        [&](const Pose& p, const Eigen::VectorXd& x, const std::vector<IkConstraint>& cs) {
            return run(solver, p, x, cs, kEventCap, 1e-6, 1e-10);
        },
        [&](const Pose& p, const Eigen::VectorXd& x, const std::vector<IkConstraint>& cs) {
            return run(reference, p, x, cs, 1000, 1e-10, 1e-14);
        });
}

nlohmann::json lbfgsDrag(const gp::ModelVersionPtr& version, bool pins, int steps, int repeats) {
    LearnedIkSolver solver(version), reference(version);
    LearnedIkRequest req;
    LearnedIkResult res;
    auto run = [&](LearnedIkSolver& s, const Pose& pose, const Eigen::VectorXd& x, const std::vector<IkConstraint>& cs,
                   int cap, double stall) {
        req.start = pose;
        req.startX = x;
        req.constraints = cs;
        req.maxIterations = cap;
        req.stallRelative = stall;
        s.solve(req, res);
        return EventOutcome{res.pose, res.x, res.y, res.objective, res.converged, res.iterations, res.constraints};
    };
    return runDrag(
        version, pins, steps, repeats,
        [&](const Pose& p, const Eigen::VectorXd& x, const std::vector<IkConstraint>& cs) {
            return run(solver, p, x, cs, kEventCap, 1e-7);
        },
        [&](const Pose& p, const Eigen::VectorXd& x, const std::vector<IkConstraint>& cs) {
            return run(reference, p, x, cs, 2000, 1e-12);
        });
}

nlohmann::json coldStarts(const gp::ModelVersionPtr& version) {
    const Clip& clip = version->model->clip;
    const ContactSet contacts = detectFootContacts(clip);
    const Eigen::Vector3d moves[] = {{0, 20, 0}, {20, 0, 0}, {0, 0, -30}, {0, 40, 10}, {-30, 0, 30}, {0, 50, 0}};
    ConstrainedIkSolver solver(version);
    ConstrainedIkResult res, full;
    std::vector<double> iterations;
    int moveCount = 0, converged = 0, reachable = 0, reachableConverged = 0;
    double worstPin = 0.0, worstReachableTarget = 0.0;
    for (int frame1 : {30, 90, 150}) {
        const int frame = std::min(frame1, clip.frameCount()) - 1;
        FkState fk;
        forwardKinematics(clip.skeleton, clip.frames[frame], fk);
        for (Effector e : {Effector::kRHand, Effector::kLHand, Effector::kRFoot}) {
            for (const Eigen::Vector3d& mv : moves) {
                ConstrainedIkRequest req = capturedPoseRequest(
                    *version, frame, {{e, effectorCm(clip.skeleton, fk, e) + mv, false}}, contacts, kEventCap);
                solver.solve(req, res);
                req.maxIterations = 500;
                solver.solve(req, full);
                ++moveCount;
                converged += res.converged;
                iterations.push_back(res.iterations);
                const bool canReach = full.reached;
                reachable += canReach;
                reachableConverged += canReach && res.converged;
                for (const auto& c : res.constraints) {
                    if (c.pin)
                        worstPin = std::max(worstPin, c.residualCm);
                    else if (canReach)
                        worstReachableTarget = std::max(worstReachableTarget, c.residualCm);
                }
            }
        }
    }
    return {{"moves", moveCount},
            {"iteration_cap", kEventCap},
            {"converged", converged},
            {"reachable", reachable},
            {"reachable_converged", reachableConverged},
            {"iterations", summarizeSeconds(iterations)},
            {"worst_pin_residual_cm", worstPin},
            {"worst_reachable_target_residual_cm", worstReachableTarget}};
}

const BenchRegistration ikBench(
    "ik", "Learned IK drags on two clips, adaptive update, span regeneration (M = 200)", [](const BenchContext& ctx) {
        const int steps = ctx.quick ? 20 : 200;
        nlohmann::json out;
        out["drags"] = nlohmann::json::array();
        gp::ModelVersionPtr first;
        for (const std::string file : {"35_01.amc", "10_02.amc"}) {  // both shipped in assets/mocap
            std::string clipName;
            double trainSeconds = 0.0;
            const gp::ModelVersionPtr version = benchModel(ctx, file, clipName, trainSeconds);
            if (!first) first = version;
            const gp::GpModel& m = *version->model;
            nlohmann::json c{{"clip", clipName},
                             {"N", m.N()},
                             {"M", m.active.size()},
                             {"D", m.D()},
                             {"model_training_seconds", trainSeconds}};
            c["constrained"] = {{"1_target", constrainedDrag(version, false, steps, ctx.repeats)},
                                {"1_target_2_pins", constrainedDrag(version, true, steps, ctx.repeats)}};
            c["cold_start"] = coldStarts(version);
            c["lbfgs"] = {{"1_target", lbfgsDrag(version, false, steps, ctx.repeats)},
                          {"1_target_2_pins", lbfgsDrag(version, true, steps, ctx.repeats)}};
            out["drags"].push_back(std::move(c));
            if (ctx.mocapDir.empty()) break;  // the synthetic walk only once
        }
        const gp::ModelVersionPtr version = first;
        const gp::GpModel& m = *version->model;

        std::vector<double> adaptive;
        for (int r = 0; r < ctx.repeats; ++r) {
            const int row = 10 + 37 * r;
            adaptive.push_back(secondsOf(
                [&] { gp::adaptiveUpdate(*version, m.X.row(row).transpose(), m.Y.row(row).transpose(), row); }));
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
                job.keyOffsetsCm = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 20, 0), Eigen::Vector3d(0, 20, 0),
                                    Eigen::Vector3d::Zero()};
                job.maxIterations = cap;
                job.mode = PathMode::kDirect;
                job.solver = EditSolver::kPerFrame;  // the per-frame IK cost; `bench --only edit` times the span solver
                regen.push_back(secondsOf([&] { job.run(); }));
                residual = job.maxResidualCm;
            }
            out["regenerate_43_frames_cap_" + std::to_string(cap)] = {
                {"seconds", summarizeSeconds(regen)}, {"solves", 41}, {"max_residual_cm", residual}};
        }
        return out;
    });

}  // namespace
}  // namespace mgp::app
