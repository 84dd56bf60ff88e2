// bench section "admission": does the adaptive update's admission rule agree with model-independent
// naturalness (docs/maths-ik.md §5)? On four CMU clips, a default model is trained on each; on six
// frames a hand, foot or the head is moved 5–40 cm up, forward, sideways and (feet) down, solved
// as `motiongp pose` solves it. Each pose is judged by
//  - the rule (eval/admission.h): reached, not through the floor, and like the capture (the
//    training clip's joint ranges and nearest frame);
//  - the model's score alone (the former rule): L_IK and σ² within the held-out percentiles;
//  - the judge, which the rule never sees: the editing-range protocol's joint-range, nearest-frame
//    and density tests (eval/naturalness.h, docs/maths.md §14) against the subject's OTHER trials
//    of the same motion plus the training clip without the edited frame ±10, and the floor.
// Reported: per clip, agreement (fraction of poses on which a verdict equals the judge's) and
// the confusion counts; also every sample, so the docs' tables can be redone.
#include "bench_registry.h"
#include "eval/admission.h"
#include "eval/naturalness.h"
#include "eval/table2_protocol.h"
#include "gp/train/trainer.h"
#include "ik/constrained_ik.h"
#include "io/clip_loader.h"
#include "motion/captured_pose_request.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"

namespace mgp::app {
namespace {

struct AdmissionClip {
    const char* training;
    std::vector<const char*> others;  // the subject's other trials of the same motion (the judge's R)
};

struct Agreement {
    int n = 0, agree = 0, bothYes = 0, bothNo = 0, onlyVerdict = 0, onlyJudge = 0;
    void add(bool verdict, bool judge) {
        ++n;
        agree += verdict == judge;
        bothYes += verdict && judge;
        bothNo += !verdict && !judge;
        onlyVerdict += verdict && !judge;
        onlyJudge += !verdict && judge;
    }
    nlohmann::json json() const {
        return {{"poses", n},
                {"agreement", n ? double(agree) / n : 0.0},
                {"both_admit", bothYes},
                {"both_refuse", bothNo},
                {"admitted_judge_refuses", onlyVerdict},
                {"refused_judge_admits", onlyJudge}};
    }
};

Eigen::Vector3d horizontalForward(const Skeleton& skeleton, const Pose& pose) {
    FkState fk;
    forwardKinematics(skeleton, pose, fk);
    Eigen::Vector3d f = fk.global[0].col(2);
    f.y() = 0.0;
    return f.norm() > 1e-9 ? Eigen::Vector3d(f.normalized()) : Eigen::Vector3d::UnitZ();
}

nlohmann::json runClip(const BenchContext& ctx, const AdmissionClip& spec, nlohmann::json& samples) {
    const std::string dir = ctx.mocapDir + "/asf_amc/";
    Clip clip = loadClip(dir + spec.training + ".amc");
    std::vector<Clip> others;
    for (const char* o : spec.others) {
        others.push_back(loadClip(dir + o + ".amc"));
        unwrapClip(others.back());
    }
    gp::TrainOptions options;
    if (ctx.quick) options.outerIterations = 3;
    const gp::ModelVersionPtr version = gp::ModelVersion::make(gp::trainOnClip(clip, options).model);
    const Clip& trained = version->model->clip;
    const ContactSet contacts = detectFootContacts(trained);
    const PoseLayout layout(trained.skeleton);
    const std::vector<int> deltas = ctx.quick ? std::vector<int>{10, 40} : std::vector<int>{5, 10, 20, 30, 40};
    const int frameCount = ctx.quick ? 2 : 6;
    const std::vector<Effector> effectors{Effector::kRHand, Effector::kLHand, Effector::kHead, Effector::kRFoot,
                                          Effector::kLFoot};
    Agreement rule, score;
    ConstrainedIkSolver solver(version);
    for (int k = 0; k < frameCount; ++k) {
        const int t = (2 * k + 1) * trained.frameCount() / (2 * frameCount);
        const Pose& start = trained.frames[t];
        const Eigen::Vector3d forward = horizontalForward(trained.skeleton, start);
        const Eigen::Vector3d side = Eigen::Vector3d::UnitY().cross(forward);
        for (Effector e : effectors) {
            const NaturalnessTests judge(table2Reference(trained, t, others), e);
            const bool foot = e == Effector::kRFoot || e == Effector::kLFoot;
            std::vector<std::pair<const char*, Eigen::Vector3d>> directions{
                {"up", Eigen::Vector3d::UnitY()}, {"forward", forward}, {"side", side}};
            if (foot) directions.push_back({"down", -Eigen::Vector3d::UnitY()});
            for (const auto& [dirName, u] : directions) {
                for (int delta : deltas) {
                    const Eigen::Vector3d target = effectorCm(trained.skeleton, start, e) + double(delta) * u;
                    const ConstrainedIkRequest request =
                        capturedPoseRequest(*version, t, {{e, target, false}}, contacts, 200);
                    const ConstrainedIkResult r = solver.solve(request);
                    const bool belowFloor = anyBelowFloor(r.constraints);
                    const AdmissionVerdict verdict =
                        admitPose(*version, r.pose, movedEffectors(r.constraints), r.reached, belowFloor, r.sigma2,
                                  r.lik, judgeBalance(trained.skeleton, start, r.pose, contacts, t));
                    const bool ruleAdmits = verdict.admitted;
                    // The former rule: the model's held-out score percentiles.
                    const bool scoreAdmits = r.reached && !belowFloor && r.lik <= version->range.likLimit &&
                                             r.sigma2 <= version->range.sigma2Limit;
                    const NaturalnessVerdict v = judge.judge(trained.skeleton, layout.extract(r.pose), nullptr);
                    const bool judgeAdmits = r.reached && !belowFloor && v.ranges && v.nearest && v.density;
                    rule.add(ruleAdmits, judgeAdmits);
                    score.add(scoreAdmits, judgeAdmits);
                    samples.push_back({{"clip", spec.training},
                                       {"frame", t + 1},
                                       {"effector", effectorName(e)},
                                       {"direction", dirName},
                                       {"delta_cm", delta},
                                       {"reached", r.reached},
                                       {"below_floor", belowFloor},
                                       {"off_balance", verdict.balance.offBalance},
                                       {"lik", r.lik},
                                       {"sigma2", r.sigma2},
                                       {"nearest_cm", verdict.capture.nearestCm},
                                       {"capture_ranges", verdict.capture.ranges},
                                       {"rule", ruleAdmits},
                                       {"score", scoreAdmits},
                                       {"judge", judgeAdmits},
                                       {"judge_ranges", v.ranges},
                                       {"judge_nearest", v.nearest},
                                       {"judge_density", v.density},
                                       {"judge_dnn_cm", v.dNN}});
                }
            }
        }
    }
    return {{"clip", spec.training},
            {"judge_reference", spec.others},
            {"iterations", version->model->iterations},
            {"nearest_limit_cm", version->capture->nearestLimitCm},
            {"nearest_median_cm", version->capture->nearestMedianCm},
            {"lik_limit", version->range.likLimit},
            {"rule", rule.json()},
            {"model_score", score.json()}};
}

const BenchRegistration admissionBench(
    "admission", "Admission against model-independent naturalness (hand, foot, head moves of 5-40 cm)",
    [](const BenchContext& ctx) {
        if (ctx.mocapDir.empty()) return nlohmann::json{{"skipped", "no CMU mocap folder"}};
        const std::vector<AdmissionClip> clips = ctx.quick ? std::vector<AdmissionClip>{{"10_02", {"10_03"}}}
                                                           : std::vector<AdmissionClip>{{"10_02", {"10_01", "10_03"}},
                                                                                        {"16_01", {"16_02", "16_03"}},
                                                                                        {"09_01", {"09_02", "09_03"}},
                                                                                        {"35_01", {}}};
        nlohmann::json out = {{"clips", nlohmann::json::array()}}, samples = nlohmann::json::array();
        for (const AdmissionClip& c : clips) out["clips"].push_back(runClip(ctx, c, samples));
        out["samples"] = samples;
        return out;
    });

}  // namespace
}  // namespace mgp::app
