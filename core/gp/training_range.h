#pragma once
// The range a model's training frames span in σ²(x) and L_IK(x, y): what the model's own score of
// a pose means (the editor shows it with every verdict; the admission itself, eval/admission.h, is
// judged against the capture).
//
// The reference is the captured motion scored as NEW poses: for every training row i, the GP
// conditioned on the active points except those within ±kHeldOutWindowFrames clip frames of row
// i (rows of the same source clip only: another clip's frame numbers say nothing) predicts at x_i
// (ActiveSetPosterior::predictHoldingOut), giving σ²_i and
//   L_IK,i = ‖W(y_i − f_{−i}(x_i))‖² / (2σ²_i) + (D/2) ln σ²_i + ½‖x_i‖²,
// what a natural pose from a moment the model has not seen scores (docs/maths-ik.md §5). Scored
// in-sample instead, a row sits at σ² ≈ 1/β and L_IK far below anything an edit can reach.
// The percentiles are computed once per trained or loaded model (ModelVersion::make,
// O(N(M² + |B|³))) and carried unchanged through its adaptive updates, so the numbers the editor
// shows beside a verdict do not move when a pose is taught (they once moved from 141 to 292 after
// one update). Until the adaptive admission became model-independent they decided it: the pose's
// L_IK had to be at most the 99th percentile and σ² at most 2× its 99th percentile; on 2 040
// moves that rule agreed with the naturalness tests on 83 % of the poses (docs/maths-ik.md §5).
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
    double likLimit = 0.0;          // percentile of the held-out L_IK,i
    double sigma2Median = 0.0, likMedian = 0.0;
    int rows = 0;
};

// The p-th percentile (0–100) of v by linear interpolation between order statistics (the "R-7"
// definition); 0 for an empty v. The training range and the capture range (gp/capture_range.h)
// both use it.
double percentileOf(std::vector<double> v, double p);

// The held-out σ²_i and L_IK,i of every training row (in row order) of `model` under `point`
// (its precomputation, docs/maths.md §9.1), each row's moment hidden by ±windowFrames clip frames.
void heldOutMomentScores(const GpModel& model, const ActiveSetPosterior& point, int windowFrames,
                         std::vector<double>& sigma2, std::vector<double>& lik);

// The percentiles of heldOutMomentScores with the default window.
TrainingRange computeTrainingRange(const GpModel& model, const ActiveSetPosterior& point,
                                   double percentile = kTrainingRangePercentile);

}  // namespace mgp::gp
