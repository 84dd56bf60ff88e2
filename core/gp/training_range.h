#pragma once
// The range a model's training frames span in σ²(x) and L_IK(x, y), and the rule that decides
// whether an edited pose may teach the model (the adaptive update, core/gp/adaptive_update.h).
//
// A pose (x*, y*) is admitted only when
//   - every target and pin of its solve was reached (core/ik/ik_types.h), and
//   - σ²(x*) ≤ 2 × the 99th percentile of σ² over the training rows' x_i and the midpoints between
//     consecutive training frames' x. σ² at a row itself is ≈ 1/β, so the path between rows is
//     the range the captured motion spans; the factor 2 admits a new pose just beyond it (a 15 cm
//     foot raise in a walk lands at 1.5× the percentile on a small model) while an
//     off-manifold pose lands at 10× or more (measured: tests/test_constrained_ik.cpp), and
//   - L_IK(x*, y*) ≤ the 99th percentile of L_IK(x_i, y_i) over the training rows.
// The percentiles are computed once per ModelVersion (ModelVersion::make). A refused pose stays
// an edit; it is just not fed to the model, so a broken pose never becomes training data.
#include <string>

#include "gp/model.h"
#include "gp/point_objective.h"

namespace mgp::gp {

constexpr double kTrainingRangePercentile = 99.0;
constexpr double kSigma2Margin = 2.0;

struct TrainingRange {
    double percentile = kTrainingRangePercentile;
    double sigma2Percentile = 0.0;  // of σ² at the rows and the midpoints between consecutive ones
    double sigma2Limit = 0.0;       // kSigma2Margin × sigma2Percentile
    double likLimit = 0.0;     // percentile of L_IK(x_i, y_i)
    double sigma2Median = 0.0, likMedian = 0.0;
    int rows = 0;
};

// Over every training row (X, Y) of `model` under `point` (its §6.2 precomputation).
TrainingRange computeTrainingRange(const GpModel& model, const PointModel& point,
                                   double percentile = kTrainingRangePercentile);

struct AdmissionVerdict {
    bool admitted = false;
    bool reached = false, sigma2InRange = false, likInRange = false;
    double sigma2 = 0.0, lik = 0.0;
    TrainingRange range;
    std::string reason;  // "" when admitted, else why not (one line)
};

AdmissionVerdict admitPose(const TrainingRange& range, bool reached, double sigma2, double lik);

}  // namespace mgp::gp
