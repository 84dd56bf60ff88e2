#pragma once
// Whether an edited pose may teach the model (the adaptive update, gp/train/adaptive_update.h), and how
// the editor words it. A pose is admitted when
//   - every target and pin of its solve was reached (ik/ik_types.h),
//   - no target was below the floor (its effector was held on the floor instead),
//   - it is not off balance where the captured pose was balanced, and
//   - it is like the capture (gp/capture_range.h): its joint angles within the captured ranges and
//     the rest of its body, the moved limbs left out, near some captured frame.
// The judgement is model-independent, so its verdicts agree with the editing-range protocol's
// naturalness tests on poses the model never saw (docs/maths-ik.md §5: 90.5 % against 83 % for the
// model's own L_IK percentile on 2 040 moves), and no update can move its limits: they come from
// the captured frames, which the version carries unchanged through every update.
//
// Words (what the legend and the status line say):
//   natural                   like the capture, nearer to it than the capture's median moment
//   unusual                   like the capture, but farther than the median (the amber ramp)
//   unlike the captured data  outside the joint ranges or farther than the nearest-frame limit
//   out of reach              a target or pin was not reached
//   through the floor         a target was below the floor
//   off balance               the captured pose stood balanced on its planted feet and this one's
//                             centre of mass falls more than 2 cm outside their support
//                             (motion/support_polygon.h)
// σ² and L_IK (the model's own score) are reported with the verdict, as numbers, not used by it.
#include <string>
#include <vector>

#include "gp/capture_range.h"
#include "gp/model_version.h"
#include "gp/training_range.h"
#include "motion/support_polygon.h"

namespace mgp {

enum class PoseJudgement { kNatural, kUnusual, kUnlikeCapture, kOutOfReach, kThroughFloor, kOffBalance };
const char* judgementWords(PoseJudgement j);  // the words above

struct AdmissionVerdict {
    bool admitted = false;
    PoseJudgement judgement = PoseJudgement::kNatural;
    bool reached = false, belowFloor = false;
    Balance balance;
    gp::CaptureLikeness capture;
    double nearestLimitCm = 0.0, nearestMedianCm = 0.0;  // the capture's (gp::CaptureRange)
    // Where the pose sits on the amber ramp, from the capture's median distance (0) to its limit (1).
    double unusual = 0.0;
    double sigma2 = 0.0, lik = 0.0;  // the model's score of the pose (shown, not judged)
    gp::TrainingRange range;         // the model's held-out score percentiles (shown, not judged)
    std::string reason;              // "" when admitted, else why not (one line, with the number that decided)
};

// `pose`: the edited pose (the model's skeleton); `moved`: the effectors the edit put somewhere.
// `balance`: judgeBalance of the pose on its frame (default: not judged).
AdmissionVerdict admitPose(const gp::ModelVersion& version, const Pose& pose, const std::vector<Effector>& moved,
                           bool reached, bool belowFloor, double sigma2, double lik, const Balance& balance = {});

// The numbers behind a verdict, a line each (the legend's tooltip): the nearest captured frame and
// its distance against the capture's own, the joint ranges, the model's σ² and L_IK against their
// held-out percentiles. ASCII only (the UI font has no Greek).
std::string admissionDetails(const AdmissionVerdict& verdict, const gp::GpModel& model);

}  // namespace mgp
