#pragma once
// The range a model's training frames span in σ²(x) and L_IK(x, y), and the rule that decides
// whether an edited pose may teach the model (the adaptive update, core/gp/adaptive_update.h).
//
// The reference is the captured motion scored as NEW poses: for every training row i, the GP
// conditioned on the active points except those within ±kHeldOutWindowFrames clip frames of row
// i (rows of the same source clip only: another clip's frame numbers say nothing) predicts at x_i (ActiveSetPosterior::predictHoldingOut), giving σ²_i and
//   L_IK,i = ‖W(y_i − f_{−i}(x_i))‖² / (2σ²_i) + (D/2) ln σ²_i + ½‖x_i‖²,
// what a natural pose from a moment the model has not seen scores (docs/maths-ik.md §5). Scored
// in-sample instead, a row sits at σ² ≈ 1/β and L_IK far below anything an edit can reach, so
// the rule refused every edit. A pose (x*, y*) is admitted only when
//   - every target and pin of its solve was reached (core/ik/ik_types.h), and
//   - L_IK(x*, y*) ≤ the 99th percentile of the held-out L_IK,i, and
//   - σ²(x*) ≤ 2 × the 99th percentile of the held-out σ²_i (it rarely binds: a held-out moment's
//     σ² is already near the prior variance α + 1/β; L_IK, which contains σ², decides).
// The percentiles are computed once per ModelVersion (ModelVersion::make, O(N(M² + |B|³))). A
// refused pose stays an edit; it is just not fed to the model, so a broken pose never becomes
// training data.
#include <string>
#include <vector>

#include "gp/model.h"
#include "gp/point_objective.h"

namespace mgp::gp {

constexpr double kTrainingRangePercentile = 99.0;
constexpr double kSigma2Margin = 2.0;
// ±10 clip frames (1/12 s at 120 fps), the same exclusion as the naturalness tests' fallback.
constexpr int kHeldOutWindowFrames = 10;

struct TrainingRange {
    double percentile = kTrainingRangePercentile;
    double sigma2Percentile = 0.0;  // of the held-out σ²_i
    double sigma2Limit = 0.0;       // kSigma2Margin × sigma2Percentile
    double likLimit = 0.0;     // percentile of the held-out L_IK,i
    double sigma2Median = 0.0, likMedian = 0.0;
    int rows = 0;
};

// The held-out σ²_i and L_IK,i of every training row (in row order) of `model` under `point`
// (its §6.2 precomputation), each row's moment hidden by ±windowFrames clip frames.
void heldOutMomentScores(const GpModel& model, const ActiveSetPosterior& point, int windowFrames, std::vector<double>& sigma2,
                         std::vector<double>& lik);

// The percentiles of heldOutMomentScores with the default window.
TrainingRange computeTrainingRange(const GpModel& model, const ActiveSetPosterior& point,
                                   double percentile = kTrainingRangePercentile);

struct AdmissionVerdict {
    bool admitted = false;
    bool reached = false, sigma2InRange = false, likInRange = false;
    double sigma2 = 0.0, lik = 0.0;
    TrainingRange range;
    std::string reason;  // "" when admitted, else why not (one line)
};

// `belowFloor`: a target was below the floor and its effector was held on it (the pose is refused
// with that reason: what the user asked for was not met).
AdmissionVerdict admitPose(const TrainingRange& range, bool reached, double sigma2, double lik, bool belowFloor = false);

}  // namespace mgp::gp
