#pragma once
// The outer training loop, Steps 1–10 (docs/maths.md §8), shared by FASGPLVM and SGPLVM:
//
//   preprocess (docs/maths.md §5): constant columns out, μ, whitened PCA X, θ = 1, w = 1
//   for t = 1..T:
//     Step 5  I := IVM(X, θ, M)
//     Step 6  SCG over (ψ = ln θ, X_I) on L_GP (W profiled under the gauge), S iterations
//     Step 7  I := IVM(X, θ, M)
//     Step 8  for j ∉ I: SCG on L_IK(x_j, y_j) (parallel, deterministic)
//     Step 9  Δ_raw = max{|Δα|, |Δβ|, |Δγ|, (|Δη|), |Δw_k|}; stop if Δ_raw < C
//   Step 10: stop at T.
//
// With M ≥ N every point is active and Steps 7–8 do nothing. Everything is deterministic (PCA
// sign rule, IVM tie rule, per-point slots in Step 8): identical inputs give identical bits for
// any thread count. The Trainer can be stepped one outer iteration at a time, cancelled from
// another thread (checked between steps), and copied (to branch a run, e.g. Table 1's control
// with the active set frozen).
#include <Eigen/Core>
#include <atomic>
#include <functional>
#include <optional>
#include <vector>

#include "gp/gp_objective.h"
#include "gp/kernel.h"
#include "gp/model.h"
#include "gp/temporal_prior.h"
#include "gp/train/back_constraints.h"

namespace mgp::gp {

enum class ConvergenceTest { kRaw, kLog };

// λ of the temporal prior when none is given, by the outer-iteration budget T (docs/maths.md §19
// says how it was chosen, docs/maths.md §23 why the full weight starts at the default T = 30):
// kQuickPriorWeight for T ≤ 10, kFullPriorWeight for T ≥ 30, and log-linear in T between. A short
// run starts from the PCA layout's fragments and needs the stronger pull to join them within its
// few iterations; a long run joins them with the weaker prior, which leaves the GP likelihood more
// say (better held-out reconstruction).
constexpr double kQuickPriorWeight = 100.0;
constexpr double kFullPriorWeight = 30.0;
double defaultPriorWeight(int outerIterations);

struct TrainOptions {
    KernelKind kind = KernelKind::kFas;
    int activeSize = 200;       // M
    int outerIterations = 30;   // T (docs/maths.md §23: what T = 100 bought over 30, measured)
    int scgIterations = 100;    // per Step 6
    int pointIterations = 100;  // per point in Step 8
    double tolerance = 0.01;    // C
    double scgTolX = 1e-4, scgTolF = 1e-4;
    ConvergenceTest test = ConvergenceTest::kRaw;
    bool stopOnConvergence = true;
    int threads = 0;  // Step 8's and the IVM's threads, ≤ 0: hardware concurrency
    // The paper-literal eq. 5 (for Table 1's comparison run only): Jacobian term −N Σ ln w_k
    // and no gauge (W profiled without constraint, w_k = sqrt(N/s_k)). It has no minimiser
    // (docs/maths.md §4.2); the default corrected objective uses c = M and Σ ln w_k = 0.
    bool paperLiteral = false;
    // Temporal prior on the latent points (docs/maths.md §19): kNone is the paper's model (table1,
    // table2 and the committed fixtures use it); kSmooth, the default (docs/experiments/training.md
    // says why), adds (λ/2) Σ ‖second difference of x over time‖² to Steps 6 and 8,
    // λ = priorWeight, or defaultPriorWeight(outerIterations) when it is not set.
    LatentPrior prior = LatentPrior::kSmooth;
    std::optional<double> priorWeight;
    // The λ a run with these options uses (0 with LatentPrior::kNone).
    double resolvedPriorWeight() const;
    // Back-constraints (docs/maths.md §22): X = K A, a smooth function of the poses; Step 6
    // optimises (ψ, A) and Step 8 is skipped. Combines with any prior (on X = K A).
    bool backConstraints = false;
    // A stated perturbation of the start, for repeated protocol runs (docs/maths.md §14.5):
    // independent N(0, startNoise²) added to every whitened-PCA latent coordinate (unit variance),
    // drawn from a generator seeded with startSeed. 0: the paper's start, untouched.
    double startNoise = 0.0;
    unsigned startSeed = 0;

    // Throws std::invalid_argument naming the first bad field.
    void validate() const;
};

// The training matrix after docs/maths.md §5 steps 1–3.
struct TrainingData {
    Eigen::MatrixXd Y;   // N×D kept columns (degrees)
    Eigen::VectorXd mu;  // D
    std::vector<int> keptColumns, constantColumns;
    Eigen::VectorXd constantValues;
    std::vector<int> frames;  // frame index of each row within its clip
    std::vector<int> clips;   // clip index of each row (empty: all one clip, clip 0)
};
// poses: N×P pose vectors (skeleton/pose_layout.h, unwrapped); frames: clip frame index of each row.
TrainingData prepareTrainingData(const Eigen::MatrixXd& poses, const std::vector<int>& frames);
// The rows of the clip's unwrapped pose matrix at `frames` (clip indices, 0-based).
TrainingData trainingDataFromClip(const Clip& clip, const std::vector<int>& frames);
// Several clips of one skeleton: the rows of clips[c] at frames[c], clip after clip, with
// TrainingData::clips set (one clip gives exactly trainingDataFromClip).
TrainingData trainingDataFromClips(const std::vector<const Clip*>& clips, const std::vector<std::vector<int>>& frames);

struct IterationLog {
    int iter = 0;
    double L = 0.0;              // L_GP after Step 6 (on Step 5's active set), plus the temporal
                                 // prior's value over all rows when one is used
    double L_before = 0.0;       // L_GP before Step 6 on the same active set
    double maxDeltaRaw = 0.0;    // the paper's Step-9 metric
    double maxDeltaLog = 0.0;    // max |Δ ln(·)| over the same parameters
    double activeOverlap = 1.0;  // |I_t ∩ I_{t−1}| / M (Step-7 sets)
    double gradInf = 0.0;        // ‖∇L_GP‖∞ at the end of Step 6
    int scgIterations = 0;
    double jitter = 0.0;          // Cholesky jitter at the end of Step 6 (0 normally)
    double trialJitterMax = 0.0;  // largest jitter on any Step-6 evaluation, rejected SCG trials
                                  // included (wild trial steps, e.g. ψ_α near +36, need it)
    double seconds = 0.0;         // wall time of this iteration (never written to a model file)
    Eigen::VectorXd psi, w;       // θ (log) and W after Step 6
};

class Trainer {
public:
    Trainer(TrainingData data, const TrainOptions& options);

    // L_GP at the initial parameters on the first active set.
    double initialObjective() const { return lInit_; }
    // Runs one outer iteration (Steps 5–9). Returns true if the Step-9 test is met. Stops early
    // (returns false, cancelled() true) if `cancel` is set between steps.
    bool step(const std::atomic<bool>* cancel = nullptr);
    bool cancelled() const { return cancelled_; }
    // Holds the active set fixed from now on (Steps 5 and 7 reuse the last one).
    void freezeActiveSet(bool freeze) { frozen_ = freeze; }

    const std::vector<IterationLog>& log() const { return log_; }
    // L_init followed by L_GP after each logged iteration's Step 6 (GpModel::objectiveHistory);
    // empty if any of them is non-finite, so a saved model always reloads.
    std::vector<double> objectiveHistory() const;
    const Eigen::VectorXd& logParams() const { return psi_; }
    const Eigen::MatrixXd& latent() const { return X_; }
    const std::vector<int>& activeSet() const { return active_; }
    const TrainingData& data() const { return data_; }
    const TrainOptions& options() const { return opt_; }
    // The mapping and its weights A (X = K A) when back-constrained; empty otherwise.
    const BackConstraint& backConstraint() const { return back_; }
    const Eigen::MatrixXd& backWeights() const { return A_; }
    // Profiled W on the current active set.
    Eigen::VectorXd currentWeights() const;

    // Individual steps (public for the benchmark and tests).
    std::vector<int> selectActive() const;  // Step 5/7
    double optimizeActive(const std::vector<int>& active, IterationLog* entry,
                          const std::atomic<bool>* cancel = nullptr);                                  // Step 6
    void optimizeInactive(const std::vector<int>& active, const std::atomic<bool>* cancel = nullptr);  // Step 8

private:
    TrainingData data_;
    TrainOptions opt_;
    Eigen::VectorXd psi_;
    Eigen::MatrixXd X_;
    std::vector<int> active_;
    TemporalPrior prior_;
    BackConstraint back_;  // empty unless options.backConstraints
    Eigen::MatrixXd A_;    // X = back_.latent(A_) when back-constrained
    Eigen::VectorXd prevW_;
    double lInit_ = 0.0;
    bool frozen_ = false;
    bool cancelled_ = false;
    std::vector<IterationLog> log_;

    GpObjectiveOptions objective() const;
};

struct TrainResult {
    GpModel model;
    double lInit = 0.0;
    std::vector<IterationLog> log;
    bool converged = false;
    bool cancelled = false;
    bool outOfTime = false;  // stopped by TrainControl::timeBudgetSeconds
};

// The model of a run as it stands after its last finished outer iteration (what train() returns
// at the end): an editor can drag against it while the run goes on (clip and provenance fields
// are left to the caller).
GpModel snapshotModel(const Trainer& trainer, bool converged = false);

// How a run is watched and stopped from outside; every field is optional.
struct TrainControl {
    std::function<void(const Trainer&)> afterIteration;  // after each outer iteration (progress, snapshots)
    const std::atomic<bool>* cancel = nullptr;
    // > 0: no outer iteration starts that would end after this many seconds from the start,
    // judged by the longest iteration so far (the first always runs: a model is trained at least once).
    double timeBudgetSeconds = 0.0;
};

// Runs the whole loop and packs the model (clip and provenance fields are left to the caller).
// progress (optional) is called after every outer iteration.
TrainResult train(const TrainingData& data, const TrainOptions& options,
                  const std::function<void(const IterationLog&)>& progress = nullptr,
                  const std::atomic<bool>* cancel = nullptr);
TrainResult train(const TrainingData& data, const TrainOptions& options, const TrainControl& control);

// Trains on every frame of `clip` and stores the clip (unwrapped, so it matches the training rows)
// in the model; provenance fields are left to the caller.
TrainResult trainOnClip(Clip clip, const TrainOptions& options,
                        const std::function<void(const IterationLog&)>& progress = nullptr,
                        const std::atomic<bool>* cancel = nullptr);
TrainResult trainOnClip(Clip clip, const TrainOptions& options, const TrainControl& control);

// Fraction of `a` also in `b` (|a ∩ b| / |a|).
double overlapFraction(const std::vector<int>& a, const std::vector<int>& b);

}  // namespace mgp::gp
