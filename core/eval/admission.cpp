#include "eval/admission.h"

#include <algorithm>
#include <cstdio>

#include "skeleton/pose_layout.h"

namespace mgp {

const char* judgementWords(PoseJudgement j) {
    switch (j) {
        case PoseJudgement::kNatural: return "natural";
        case PoseJudgement::kUnusual: return "unusual";
        case PoseJudgement::kUnlikeCapture: return "unlike the captured data";
        case PoseJudgement::kOutOfReach: return "out of reach";
        case PoseJudgement::kThroughFloor: return "through the floor";
        case PoseJudgement::kOffBalance: return "off balance";
    }
    return "?";
}

AdmissionVerdict admitPose(const gp::ModelVersion& version, const Pose& pose, const std::vector<Effector>& moved,
                           bool reached, bool belowFloor, double sigma2, double lik, const Balance& balance) {
    AdmissionVerdict v;
    v.reached = reached;
    v.balance = balance;
    v.belowFloor = belowFloor;
    v.sigma2 = sigma2;
    v.lik = lik;
    v.range = version.range;
    const gp::CaptureRange& capture = *version.capture;
    const Skeleton& skeleton = version.model->clip.skeleton;
    v.capture = gp::judgeAgainstCapture(capture, skeleton, pose, moved);
    v.nearestLimitCm = capture.nearestLimitCm;
    v.nearestMedianCm = capture.nearestMedianCm;
    const double ramp = capture.nearestLimitCm - capture.nearestMedianCm;
    v.unusual = ramp > 0.0 ? std::clamp((v.capture.nearestCm - capture.nearestMedianCm) / ramp, 0.0, 1.0) : 0.0;
    char buf[240];
    if (belowFloor) {
        v.judgement = PoseJudgement::kThroughFloor;
        v.reason = "a target is below the floor: the effector was held on it";
    } else if (!reached) {
        v.judgement = PoseJudgement::kOutOfReach;
        v.reason = "a target or pin was not reached";
    } else if (balance.offBalance) {
        v.judgement = PoseJudgement::kOffBalance;
        std::snprintf(buf, sizeof buf, "off balance (the centre of mass is %.1f cm outside the planted feet's support)",
                      balance.outsideCm);
        v.reason = buf;
    } else if (!v.capture.ranges) {
        v.judgement = PoseJudgement::kUnlikeCapture;
        const PoseLayout layout(skeleton);
        std::snprintf(buf, sizeof buf, "unlike the captured data (%s is %.0f deg past its captured range)",
                      layout.dofName(skeleton, v.capture.worstDof).c_str(), v.capture.worstExcessDeg);
        v.reason = buf;
    } else if (!v.capture.nearest) {
        v.judgement = PoseJudgement::kUnlikeCapture;
        std::snprintf(buf, sizeof buf,
                      "unlike the captured data (the body is %.1f cm from the nearest captured frame, limit %.1f cm)",
                      v.capture.nearestCm, capture.nearestLimitCm);
        v.reason = buf;
    } else {
        v.judgement = v.unusual > 0.0 ? PoseJudgement::kUnusual : PoseJudgement::kNatural;
    }
    v.admitted = v.reason.empty();
    return v;
}

std::string admissionDetails(const AdmissionVerdict& v, const gp::GpModel& model) {
    char buf[320];
    std::string out;
    if (v.capture.nearestClip >= 0) {
        std::snprintf(
            buf, sizeof buf,
            "nearest captured frame: %s frame %d, %.1f cm away (the capture's own moments: typically %.1f cm, "
            "at most %.1f cm)\n",
            model.clipName(v.capture.nearestClip).c_str(), v.capture.nearestFrame + 1, v.capture.nearestCm,
            v.nearestMedianCm, v.nearestLimitCm);
        out += buf;
    }
    if (v.capture.ranges) {
        out += "joint ranges: every angle within the captured range\n";
    } else {
        const PoseLayout layout(model.clip.skeleton);
        std::snprintf(buf, sizeof buf, "joint ranges: %d angle(s) outside, worst %s by %.0f deg\n",
                      v.capture.rangeViolations, layout.dofName(model.clip.skeleton, v.capture.worstDof).c_str(),
                      v.capture.worstExcessDeg);
        out += buf;
    }
    if (!v.reached) out += "a target or pin was not reached\n";
    if (v.belowFloor) out += "a target is below the floor\n";
    if (v.balance.judged) {
        std::snprintf(buf, sizeof buf,
                      "balance: the centre of mass is %.1f cm outside the planted feet's support (tolerance %.0f cm)\n",
                      v.balance.outsideCm, kBalanceToleranceCm);
        out += buf;
    }
    std::snprintf(buf, sizeof buf, "model's score: sigma^2 %.4g (held-out p%g %.4g), L_IK %.4g (held-out p%g %.4g)",
                  v.sigma2, v.range.percentile, v.range.sigma2Percentile, v.lik, v.range.percentile, v.range.likLimit);
    out += buf;
    return out;
}

}  // namespace mgp
