#pragma once
// How good a trained model's latent layout is (docs/maths.md §20), as numbers `motiongp evaluate`
// and `bench --only model` report:
//  (a) continuity: the latent step between time-consecutive training frames over the median
//      distance of all pairs of latent points (p50, p90, p99); a layout that keeps each motion
//      one curve has every step small, one cut into arcs has a heavy tail;
//  (b) held-out reconstruction: a model trained without some frames places each left-out frame
//      by minimising L_IK(x, y) over x from its pose y (best of the 3 nearest training frames'
//      latent points as starts), reconstructs f(x) and reports the RMS error over the 44 non-root
//      DOFs in degrees, next to the nearest-training-frame baseline (the training pose nearest
//      in that same RMS); and the in-betweening error of x interpolated in time from the two
//      neighbouring training frames' latent points (no pose used: what a continuous layout buys);
//  (c) the full-GP yardstick: the log marginal likelihood of all N training rows (columns
//      standardised) under a full GP on the given latent points with an RBF + bias + white kernel
//      whose four hyperparameters are re-fitted (SCG on their logs), per value (÷ N·D).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "gp/model.h"
#include "gp/train/trainer.h"

namespace mgp::eval {

// Time-consecutive pairs of training rows (rows sorted by frame; a pair is kept when the frame gap
// is > 0 and ≤ 3 median gaps, the segmentation of the temporal prior).
std::vector<std::pair<int, int>> timeConsecutivePairs(const std::vector<int>& frames);

// Percentile q ∈ [0, 1] by linear interpolation between order statistics (v is copied).
double percentile(std::vector<double> v, double q);

struct ContinuityReport {
    int steps = 0;                    // consecutive pairs measured
    double medianPairDistance = 0.0;  // median ‖x_i − x_j‖ over pairs i < j (every pair for N ≤ 3000)
    double p50 = 0.0, p90 = 0.0, p99 = 0.0, max = 0.0;  // step / medianPairDistance
};
ContinuityReport latentContinuity(const Eigen::MatrixXd& X, const std::vector<int>& frames);
// latentContinuity of each source clip of `model` on its own rows (in clip order): a clip's steps
// over the median pair distance of that clip's latent points.
std::vector<ContinuityReport> latentContinuityPerClip(const gp::GpModel& model);

struct FullGpScore {
    bool ok = false;
    double logLikelihood = 0.0;  // ln p(Ys | X, θ*), Ys the standardised columns
    double perValue = 0.0;       // logLikelihood / (N·D)
    double alpha = 0.0, gamma = 0.0, bias = 0.0, noiseVariance = 0.0;
    int iterations = 0;
};
// −ln p(Ys | X, ψ) with ψ = (ln α, ln γ, ln b, ln β) for K = α exp(−γ r²/2) + b + δ/β, and its
// gradient in ψ when grad is non-null. Returns +∞ if K cannot be factored.
double fullGpNegLogLikelihood(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Ys, const Eigen::Vector4d& psi,
                              Eigen::Vector4d* grad);
// Standardises Y's columns (centred, unit population variance; constant columns dropped) and fits ψ
// from two starts (γ = 1 and 20 over the median squared latent distance), keeping the better.
FullGpScore fitFullGp(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y, int maxIterations = 150);
constexpr int kYardstickMaxRows = 2000;

struct HeldOutSplit {
    std::vector<int> trainFrames, heldFrames;  // clip frames, ascending
};
// One frame in `every` of `frames` is held out: the frames at 1-based positions p ≡ offset
// (mod every) in time order. offset 0 (the default) holds out the every-th, 2·every-th, …;
// offset k ∈ [1, every) the k-th, (every+k)-th, …, so different offsets give disjoint held-out
// sets. Duplicates are dropped first.
HeldOutSplit everyNthHeldOut(std::vector<int> frames, int every = 10, int offset = 0);

struct HeldOutReport {
    int heldOut = 0, trained = 0;
    double rmsDeg = 0.0;         // f(x*) against the true pose, non-root DOFs
    double nearestRmsDeg = 0.0;  // nearest training pose against the true pose
    // In-betweening: x placed by linear interpolation in time between the latent points of the
    // training frames just before and after (frames with both, in one segment: `timeCount`), no
    // pose information used; f(x) against the true pose.
    double timeRmsDeg = 0.0;
    int timeCount = 0;
    // The held-out frame f(x*) reconstructs worst (clip frame, 0-based) and its RMS, and the
    // median frame's: one misplaced frame can carry a split's RMS.
    int worstFrame = -1;
    double worstFrameRmsDeg = 0.0, medianFrameRmsDeg = 0.0;
};
// `model` was trained without heldFrames; its clip supplies the true poses.
HeldOutReport heldOutReconstruction(const gp::GpModel& model, const std::vector<int>& heldFrames, int iterations = 200);

// Mean and spread of one measure over several held-out splits (offsets). sd is the sample
// standard deviation (n − 1; 0 for one value): how far one retraining on one split can move it.
struct Spread {
    int count = 0;
    double mean = 0.0, sd = 0.0, min = 0.0, max = 0.0;
};
Spread spreadOf(const std::vector<double>& values);

// The held-out protocol over several offsets: per offset, the model's frames minus that
// offset's split, retrained with `options`, scored by heldOutReconstruction.
struct HeldOutOffsetsReport {
    std::vector<int> offsets;
    std::vector<HeldOutReport> perOffset;
    std::vector<double> trainSeconds;  // wall time of each retraining
    Spread rmsDeg, nearestRmsDeg, timeRmsDeg;
};
// Summaries of per-offset reports (the Spread fields; offsets/trainSeconds are left as given).
void summarizeHeldOut(HeldOutOffsetsReport& report);
HeldOutOffsetsReport heldOutOverOffsets(const gp::GpModel& model, const gp::TrainOptions& options, int every,
                                        const std::vector<int>& offsets);

// The options a model was trained with (kind and settings), for retraining on a split.
gp::TrainOptions trainOptionsOf(const gp::GpModel& model);

}  // namespace mgp::eval
