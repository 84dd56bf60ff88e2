// `motiongp pose MODEL --frame T --target EFF=dx,dy,dz[@STRENGTH] ... [--pin EFF ...]
//  [--release EFF ...] [--solver learned|lbfgs|plain] [--adaptive --out-model MODEL2] [--out
//  F.bvh|.glb|.gltf|.fbx]
//  [--json]`:
// one IK solve on a frame of one of the model's source clips (--clip NAME, default the first;
// --frame counts within it). Offsets are cm from the effector's position in that frame. An
// unreachable target is a result (reached: false, exit 0), not an error; so is an adaptive update
// the admission rule refuses (adaptive.refused: true, with the reason).
//
// Solvers: learned (default) is the constrained learned IK (core/ik/constrained_ik.h: hard pins,
// per-target strength); lbfgs is the paper's λ-penalty L-BFGS (core/ik/learned_ik.h), kept for
// comparison; plain has no prior.
#include <chrono>
#include <iostream>

#include "cli_common.h"
#include "command_registry.h"
#include "eval/admission.h"
#include "eval/nearest_pose.h"
#include "gp/model_file.h"
#include "gp/train/adaptive_update.h"
#include "ik/constrained_ik.h"
#include "ik/learned_ik.h"
#include "ik/plain_ik.h"
#include "ik_cli.h"
#include "motion/foot_contacts.h"
#include "motion/support_polygon.h"
#include "skeleton/centre_of_mass.h"

namespace mgp::app {
namespace {

struct PoseOptions {
    std::string model, solver = "learned", outModel, clip, out;
    long long frame = 1;
    std::vector<std::string> targets, pins, releases;
    bool adaptive = false, json = false;
    int iterations = 500;
    double locality = kDefaultLocality;
    double balanceWeight = kBalanceWeight;
    bool localityGiven = false, balanceGiven = false;  // on the command line, whatever the value
};

nlohmann::json verdictJson(const AdmissionVerdict& v, const gp::GpModel& model) {
    return {{"admitted", v.admitted},
            {"judgement", judgementWords(v.judgement)},
            {"reason", v.reason},
            {"reached", v.reached},
            {"below_floor", v.belowFloor},
            {"balance_judged", v.balance.judged},
            {"com_outside_support_cm", v.balance.outsideCm},
            {"nearest_captured_cm", v.capture.nearestCm},
            {"nearest_captured_limit_cm", v.nearestLimitCm},
            {"nearest_captured_median_cm", v.nearestMedianCm},
            {"nearest_captured_frame", v.capture.nearestFrame + 1},
            {"nearest_captured_clip", v.capture.nearestClip >= 0 ? model.clipName(v.capture.nearestClip) : ""},
            {"joint_range_violations", v.capture.rangeViolations},
            {"sigma2", v.sigma2},
            {"sigma2_limit", v.range.sigma2Limit},
            {"sigma2_percentile", v.range.sigma2Percentile},
            {"L_IK", v.lik},
            {"L_IK_limit", v.range.likLimit},
            {"percentile", v.range.percentile},
            {"training_rows", v.range.rows}};
}

void checkPoseOptions(const PoseOptions& o) {
    if (o.solver != "learned" && o.solver != "lbfgs" && o.solver != "plain")
        throw UsageError("expected --solver learned, lbfgs or plain, found '" + o.solver + "'");
    if (o.adaptive && o.outModel.empty()) throw UsageError("expected --out-model MODEL2 with --adaptive, found none");
    if (o.adaptive && o.solver == "plain") throw UsageError("expected --solver learned with --adaptive, found plain");
    if (o.targets.empty() && o.pins.empty()) throw UsageError("expected at least one --target or --pin, found none");
    if (!o.out.empty()) requireExportPath(o.out);
    // The learned solver's validate() judges the value itself; any other solver has no such term,
    // so the option is refused whatever its value (the default's value included).
    if (o.localityGiven && o.solver != "learned")
        throw UsageError("expected --solver learned with --locality, found --solver " + o.solver);
    if (o.balanceGiven && o.solver != "learned")
        throw UsageError("expected --solver learned with --balance, found --solver " + o.solver);
}

// --target and --pin, placed from the effectors' positions in the frame (`fk`).
std::vector<IkConstraint> requestedConstraints(const PoseOptions& o, const Clip& clip, const FkState& fk) {
    std::vector<IkConstraint> constraints;
    for (const std::string& t : o.targets) {
        const TargetSpec spec = parseTargetWithStrength(t);
        constraints.push_back(
            {spec.effector, effectorCm(clip.skeleton, fk, spec.effector) + spec.offsetCm, false, spec.strength});
    }
    for (const std::string& p : o.pins) {
        const Effector eff = parseEffectorOption(p, "--pin");
        constraints.push_back({eff, effectorCm(clip.skeleton, fk, eff), true});
    }
    return constraints;
}

// Feet in ground contact on this frame are held like pins unless released (or already
// constrained): the contact rule of core/motion/foot_contacts.h. Returns the clip's contacts.
ContactSet holdContactFeet(const PoseOptions& o, const Clip& clip, const FkState& fk, int frame,
                           std::vector<IkConstraint>& constraints, nlohmann::json& j) {
    bool released[kEffectorCount] = {};
    for (const std::string& r : o.releases) {
        const Effector eff = parseEffectorOption(r, "--release");
        if (eff != Effector::kLFoot && eff != Effector::kRFoot)
            throw UsageError("expected --release lfoot or rfoot, found '" + r + "'");
        released[static_cast<int>(eff)] = true;
    }
    j["contact_pins"] = nlohmann::json::array();
    ContactSet contacts = detectFootContacts(clip);
    for (const IkConstraint& pin : contactPinsAt(clip, fk, contacts, frame, constraints, released)) {
        constraints.push_back(pin);
        j["contact_pins"].push_back(effectorName(pin.effector));
    }
    return contacts;
}

// What a solve gives, whichever solver ran (x, y, sigma2 and lik: the learned solvers only).
struct PoseSolution {
    Pose pose;
    std::vector<IkConstraintResult> results;
    bool reached = false;
    Eigen::VectorXd x, y;
    double sigma2 = 0.0, lik = 0.0;
};

void solvePlainPose(const Clip& clip, int frame, const std::vector<IkConstraint>& constraints, PoseSolution& s,
                    nlohmann::json& j) {
    PlainIkJob job;
    job.skeleton = &clip.skeleton;
    job.start = clip.frames[frame];
    job.constraints = constraints;
    if (const std::string problem = job.validate(); !problem.empty()) throw UsageError(problem);
    job.solve();
    s.pose = job.pose;
    s.results = job.results;
    s.reached = job.reached;
    j["x"] = nullptr;
    j["sigma2"] = nullptr;
    j["L_IK"] = nullptr;
    j["diagnostic"] = job.diagnostic;
}

// The constrained learned solver (--solver learned) or the paper's penalty L-BFGS (lbfgs).
void solveLearnedPose(const PoseOptions& o, const gp::ModelVersionPtr& version, int frame,
                      const std::vector<IkConstraint>& constraints, const ContactSet& contacts, PoseSolution& s,
                      nlohmann::json& j) {
    const Clip& clip = version->model->clip;
    // Both learned solvers take the same request fields and report the same result fields.
    auto solveWith = [&](auto& solver, auto req) {
        req.start = clip.frames[frame];
        req.startX = latentStartForFrame(*version, frame);
        req.constraints = constraints;
        req.maxIterations = o.iterations;
        if (const std::string problem = solver.validate(req); !problem.empty()) throw UsageError(problem);
        const auto r = solver.solve(req);
        s.pose = r.pose;
        s.results = r.constraints;
        s.reached = r.reached;
        s.x = r.x;
        s.y = r.y;
        s.sigma2 = r.sigma2;
        s.lik = r.lik;
        j["diagnostic"] = r.diagnostic;
        j["converged"] = r.converged;
        j["iterations"] = r.iterations;
        j["evaluations"] = r.evaluations;
        j["objective"] = r.objective;
        return r;
    };
    if (o.solver == "learned") {
        ConstrainedIkSolver solver(version);
        ConstrainedIkRequest request;
        request.locality = o.locality;
        request.floorCm = contacts.floorCm;
        FkState fk;
        forwardKinematics(clip.skeleton, clip.frames[frame], fk);
        if (o.balanceWeight > 0.0)
            request.balance = balanceRegion(clip.skeleton, clip.frames[frame], fk, contacts, frame, constraints);
        request.balanceWeight = o.balanceWeight;
        j["locality"] = o.locality;
        j["balance_asked"] = request.balance.has_value();
        j["stop"] = ikStopName(solveWith(solver, request).stop);
    } else {
        LearnedIkSolver solver(version);
        const LearnedIkResult r = solveWith(solver, LearnedIkRequest{});
        for (auto& c : s.results) c.strength = kStrengthPaper;  // the penalty form is the paper's λ
        j["stop"] = learnedIkStopKey(r.stop);
    }
    j["x"] = std::vector<double>(s.x.data(), s.x.data() + s.x.size());
    j["sigma2"] = s.sigma2;
    j["L_IK"] = s.lik;
}

// The admission verdict on a learned solve and, with --adaptive, the model update it allows.
void judgeLearnedPose(const PoseOptions& o, const gp::ModelVersionPtr& version, int clipIndex, int frame,
                      const ContactSet& contacts, const PoseSolution& s, nlohmann::json& j) {
    const gp::GpModel& m = *version->model;
    const Clip& clip = m.clip;
    const AdmissionVerdict verdict =
        admitPose(*version, s.pose, movedEffectors(s.results), s.reached, anyBelowFloor(s.results), s.sigma2, s.lik,
                  judgeBalance(clip.skeleton, clip.frames[frame], s.pose, contacts, frame));
    j["natural"] = verdictJson(verdict, *version->model);
    if (!o.adaptive) return;
    if (!verdict.admitted) {
        j["adaptive"] = {{"refused", true}, {"reason", verdict.reason}, {"rows", m.N()}};
    } else {
        const gp::AdaptiveUpdateResult u = gp::adaptiveUpdate(*version, s.x, s.y, frame);
        if (!u.accepted) throw std::runtime_error("adaptive update: " + u.diagnostic);
        gp::saveModel(o.outModel, gp::withPrimaryClip(*u.version->model, clipIndex));  // the file's clip order
        j["adaptive"] = {{"refused", false},
                         {"rows", u.version->model->N()},
                         {"new_point_active", u.newPointActive},
                         {"active_changed", u.activeChanged},
                         {"out_model", o.outModel}};
    }
}

// The solved pose's fields of the report (and the --out file); returns the nearest captured frame.
NearestFrame reportSolvedPose(const PoseOptions& o, const gp::GpModel& m, int frame, const ContactSet& contacts,
                              const PoseSolution& s, nlohmann::json& j) {
    const Clip& clip = m.clip;
    j["reached"] = s.reached;
    // Only the learned solver keeps hands and feet above the floor.
    j["floor_cm"] =
        o.solver == "learned" && contacts.floorCm ? nlohmann::json(*contacts.floorCm) : nlohmann::json(nullptr);
    j["targets"] = constraintsJson(s.results, false);
    j["pins"] = constraintsJson(s.results, true);
    const Eigen::VectorXd poseDeg = PoseLayout(clip.skeleton).extract(s.pose);
    j["pose_deg"] = std::vector<double>(poseDeg.data(), poseDeg.data() + poseDeg.size());
    // Where the solved pose is in the data: the nearest captured frame over every source clip.
    const NearestFrame nearest = nearestFrame(poseDeg, m.clipPoseMatrices());
    const std::string nearestClip = m.clipName(nearest.clip);
    j["clip"] = clip.name;
    // How far the whole-body centre of mass moved over the ground from the captured frame.
    const std::optional<double> comShift = horizontalComShiftCm(clip.skeleton, s.pose, clip.frames[frame]);
    j["com_shift_cm"] = comShift ? nlohmann::json(*comShift) : nlohmann::json(nullptr);
    j["nearest"] = {{"clip", nearestClip}, {"frame", nearest.frame + 1}, {"rms_deg", nearest.rmsDeg}};
    Clip solved = clip;
    solved.frames = {s.pose};
    j["positions_cm"] = effectorPositionsJson(solved, 0);
    if (!o.out.empty()) {
        // The whole clip with the solved frame in place, so any tool can check the pose in context.
        Clip withPose = clip;
        withPose.frames[frame] = s.pose;
        exportFromCli(withPose, o.out);
        j["out"] = o.out;
    }
    return nearest;
}

void printPoseText(const PoseOptions& o, const nlohmann::json& j, const PoseSolution& s, const std::string& nearestClip,
                   const NearestFrame& nearest) {
    std::cout << (s.reached ? "reached" : "NOT reached") << " (" << j["diagnostic"].get<std::string>() << ")\n";
    for (const auto& r : s.results)
        std::cout << "  " << (r.pin ? "pin    " : "target ") << effectorName(r.effector) << ": residual "
                  << r.residualCm << " cm"
                  << (r.belowFloor ? "  (below the floor: held on it)"
                      : r.reached  ? ""
                                   : "  (not reached)")
                  << "\n";
    std::cout << "nearest captured frame: " << nearestClip << " frame " << nearest.frame + 1 << " (" << nearest.rmsDeg
              << "° RMS over the non-root DOFs)\n";
    if (!o.out.empty()) std::cout << "wrote " << o.out << "\n";
    if (j.contains("adaptive")) {
        if (j["adaptive"]["refused"].get<bool>())
            std::cout << "adaptive update refused: " << j["adaptive"]["reason"].get<std::string>()
                      << " (the model file was not written)\n";
        else
            std::cout << "adaptive update: " << j["adaptive"]["rows"].get<int>() << " rows, written to " << o.outModel
                      << "\n";
    }
}

int runPose(const PoseOptions& o) {
    checkPoseOptions(o);
    const auto t0 = std::chrono::steady_clock::now();
    int clipIndex = 0;
    const gp::ModelVersionPtr version = loadModelVersion(o.model, o.clip, &clipIndex);
    const gp::GpModel& m = *version->model;
    const Clip& clip = m.clip;
    const int frame = frameIndexFromCli(clip, o.frame);
    FkState fk;
    forwardKinematics(clip.skeleton, clip.frames[frame], fk);
    std::vector<IkConstraint> constraints = requestedConstraints(o, clip, fk);
    nlohmann::json j;
    const ContactSet contacts = holdContactFeet(o, clip, fk, frame, constraints, j);
    PoseSolution s;
    if (o.solver == "plain") {
        solvePlainPose(clip, frame, constraints, s, j);
    } else {
        solveLearnedPose(o, version, frame, constraints, contacts, s, j);
        judgeLearnedPose(o, version, clipIndex, frame, contacts, s, j);
    }
    const NearestFrame nearest = reportSolvedPose(o, m, frame, contacts, s, j);
    j["seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (o.json)
        printJson(j);
    else
        printPoseText(o, j, s, m.clipName(nearest.clip), nearest);
    return 0;
}

const CommandRegistration poseCommand(
    "pose", "Solve IK on one frame of a model's clip (learned or plain)", [](CLI::App& sub) -> CommandRunner {
        auto o = std::make_shared<PoseOptions>();
        sub.add_option("model", o->model, "Model file (motiongp train --out)")->required();
        sub.add_option("--clip", o->clip,
                       "NAME: which of the model's clips (file stem, e.g. 10_03; default: the first)");
        sub.add_option("--frame", o->frame, "Frame of that clip, counted from 1")->required();
        sub.add_option("--target", o->targets,
                       "EFF=dx,dy,dz[@STRENGTH]: move an effector by this many cm; STRENGTH exact "
                       "(default), paper "
                       "(0.999) or a number in (0, 1] (repeatable)");
        sub.add_option("--pin", o->pins, "EFF: hold an effector exactly where it is (repeatable)");
        sub.add_option("--release", o->releases,
                       "EFF: do not hold this foot although it is in ground contact (repeatable)");
        sub.add_option("--solver", o->solver,
                       "learned (default: constrained, hard pins), lbfgs (the paper's penalty) or "
                       "plain (no prior)");
        sub.add_option("--iterations", o->iterations, "Iteration cap")->check(CLI::Range(1, 100000));
        sub.add_option("--locality", o->locality,
                       "Learned solver: how strongly the body away from the dragged limbs keeps "
                       "its pose, per degree² "
                       "(0 = off; default " +
                           std::to_string(static_cast<int>(kDefaultLocality)) + ")");
        sub.add_option("--balance", o->balanceWeight,
                       "Learned solver: the weight per cm² that keeps the centre of mass over the planted feet "
                       "where the captured frame stands balanced on them (0 = off; default " +
                           std::to_string(static_cast<int>(kBalanceWeight)) + ")");
        sub.add_flag("--adaptive", o->adaptive,
                     "Add the solved pose to the model (docs/maths.md §11) and save it, if every "
                     "constraint is reached "
                     "and L_IK is within the "
                     "99th percentile (σ²: twice it) of the captured frames scored as new poses");
        sub.add_option("--out-model", o->outModel, "Where --adaptive writes the updated model");
        sub.add_option("--out", o->out, "Write the clip with the solved frame in place: .bvh, .glb, .gltf or .fbx");
        sub.add_flag("--json", o->json, "Print one JSON object");
        const CLI::Option* locality = sub.get_option("--locality");
        const CLI::Option* balance = sub.get_option("--balance");
        return [o, locality, balance]() {
            o->localityGiven = locality->count() > 0;
            o->balanceGiven = balance->count() > 0;
            return runPose(*o);
        };
    });

}  // namespace
}  // namespace mgp::app
