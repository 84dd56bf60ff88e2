#include "gp/train/trainer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <stdexcept>

#include "gp/gp_objective.h"
#include "gp/point_objective.h"
#include "gp/scg.h"
#include "gp/train/active_step.h"
#include "gp/train/ivm.h"
#include "gp/train/pca_init.h"
#include "skeleton/clip.h"
#include "skeleton/pose_layout.h"
#include "util/parallel_for.h"

namespace mgp::gp {

TrainingData prepareTrainingData(const Eigen::MatrixXd& poses, const std::vector<int>& frames) {
    if (poses.cols() < 1) throw std::invalid_argument("prepareTrainingData: expected pose columns");
    if (static_cast<Eigen::Index>(frames.size()) != poses.rows())
        throw std::invalid_argument("prepareTrainingData: one frame number per row");
    if (poses.rows() < 3)
        throw std::invalid_argument("expected at least 3 training frames, found " + std::to_string(poses.rows()));
    // A NaN or Inf angle would make every kernel value, and so the saved model, NaN.
    for (Eigen::Index t = 0; t < poses.rows(); ++t)
        for (Eigen::Index k = 0; k < poses.cols(); ++k)
            if (!std::isfinite(poses(t, k)))
                throw std::invalid_argument("expected finite training poses, found " +
                                            std::string(std::isnan(poses(t, k)) ? "NaN" : "Inf") + " at clip frame " +
                                            std::to_string(frames[static_cast<std::size_t>(t)] + 1) + ", pose DOF " +
                                            std::to_string(k));
    TrainingData out;
    out.frames = frames;
    out.constantColumns = constantColumns(poses, 1e-6);
    for (int k = 0; k < static_cast<int>(poses.cols()); ++k)
        if (!std::binary_search(out.constantColumns.begin(), out.constantColumns.end(), k))
            out.keptColumns.push_back(k);
    // Nothing varies: there is nothing to learn (and D = 0 would divide by zero in the gauge).
    if (out.keptColumns.empty())
        throw std::invalid_argument(
            "expected at least one pose DOF that varies over the training frames, found every pose DOF constant (the "
            "same pose in every frame)");
    out.constantValues.resize(out.constantColumns.size());
    for (std::size_t k = 0; k < out.constantColumns.size(); ++k)
        out.constantValues[k] = poses.col(out.constantColumns[k]).mean();
    out.Y.resize(poses.rows(), out.keptColumns.size());
    for (std::size_t k = 0; k < out.keptColumns.size(); ++k) out.Y.col(k) = poses.col(out.keptColumns[k]);
    out.mu = out.Y.colwise().mean().transpose();
    return out;
}

double overlapFraction(const std::vector<int>& a, const std::vector<int>& b) {
    if (a.empty()) return 1.0;
    std::vector<int> sa = a, sb = b;
    std::sort(sa.begin(), sa.end());
    std::sort(sb.begin(), sb.end());
    std::vector<int> both;
    std::set_intersection(sa.begin(), sa.end(), sb.begin(), sb.end(), std::back_inserter(both));
    return static_cast<double>(both.size()) / static_cast<double>(a.size());
}

namespace {

Eigen::MatrixXd rowsOf(const Eigen::MatrixXd& A, const std::vector<int>& idx) {
    Eigen::MatrixXd out(idx.size(), A.cols());
    for (std::size_t r = 0; r < idx.size(); ++r) out.row(r) = A.row(idx[r]);
    return out;
}

Eigen::MatrixXd centredRows(const TrainingData& data, const std::vector<int>& idx) {
    Eigen::MatrixXd out = rowsOf(data.Y, idx);
    out.rowwise() -= data.mu.transpose();
    return out;
}

std::vector<int> complementOf(const std::vector<int>& active, int n) {
    std::vector<char> in(n, 0);
    for (int i : active) in[i] = 1;
    std::vector<int> out;
    for (int i = 0; i < n; ++i)
        if (!in[i]) out.push_back(i);
    return out;
}

// Raw parameter values in the paper's order: α, β, γ, (η).
Eigen::VectorXd rawParams(const Eigen::VectorXd& psi) {
    Kernel k(psi.size() == 4 ? KernelKind::kFas : KernelKind::kSgplvm, psi);
    Eigen::VectorXd out(psi.size());
    out[0] = k.alpha();
    out[1] = k.beta();
    out[2] = k.gamma();
    if (psi.size() == 4) out[3] = k.eta();
    return out;
}

// The progress callback and cancel flag of the older train() signatures as a TrainControl.
TrainControl controlOf(const std::function<void(const IterationLog&)>& progress, const std::atomic<bool>* cancel) {
    TrainControl control;
    if (progress) control.afterIteration = [&progress](const Trainer& t) { progress(t.log().back()); };
    control.cancel = cancel;
    return control;
}

}  // namespace

double defaultPriorWeight(int outerIterations) {
    constexpr double kQuickT = 10.0, kFullT = 30.0;  // kFullT: the default T
    const double t = std::clamp(static_cast<double>(outerIterations), kQuickT, kFullT);
    const double s = std::log(t / kQuickT) / std::log(kFullT / kQuickT);  // 0 at T ≤ 10, 1 at T ≥ 30
    return kQuickPriorWeight * std::pow(kFullPriorWeight / kQuickPriorWeight, s);
}

double TrainOptions::resolvedPriorWeight() const {
    if (prior == LatentPrior::kNone) return 0.0;
    return priorWeight ? *priorWeight : defaultPriorWeight(outerIterations);
}

void TrainOptions::validate() const {
    if (activeSize < 1) throw std::invalid_argument("TrainOptions: expected activeSize ≥ 1");
    if (outerIterations < 0) throw std::invalid_argument("TrainOptions: expected outerIterations ≥ 0");
    if (scgIterations < 0 || pointIterations < 0)
        throw std::invalid_argument("TrainOptions: expected scgIterations, pointIterations ≥ 0");
    if (!(tolerance > 0.0) || !std::isfinite(tolerance))
        throw std::invalid_argument("TrainOptions: expected a finite tolerance > 0");
    if (!(scgTolX >= 0.0) || !(scgTolF >= 0.0))
        throw std::invalid_argument("TrainOptions: expected SCG tolerances ≥ 0");
    if (priorWeight && (!(*priorWeight >= 0.0) || !std::isfinite(*priorWeight)))
        throw std::invalid_argument("TrainOptions: expected a finite priorWeight ≥ 0");
    if (!(startNoise >= 0.0) || !std::isfinite(startNoise))
        throw std::invalid_argument("TrainOptions: expected a finite startNoise ≥ 0");
}

namespace {

// Standard normal draws that are the same on every standard library: Box–Muller over
// std::mt19937, whose output sequence the standard fixes (std::normal_distribution's is not).
Eigen::MatrixXd standardNormal(Eigen::Index rows, Eigen::Index cols, unsigned seed) {
    std::mt19937 gen(seed);
    auto uniform = [&] { return (static_cast<double>(gen()) + 0.5) / 4294967296.0; };  // (0, 1)
    Eigen::MatrixXd z(rows, cols);
    for (Eigen::Index i = 0; i < z.size(); i += 2) {
        const double r = std::sqrt(-2.0 * std::log(uniform())), a = 2.0 * M_PI * uniform();
        z(i) = r * std::cos(a);
        if (i + 1 < z.size()) z(i + 1) = r * std::sin(a);
    }
    return z;
}

}  // namespace

Trainer::Trainer(TrainingData data, const TrainOptions& options) : data_(std::move(data)), opt_(options) {
    opt_.validate();
    const Eigen::MatrixXd Ybar = data_.Y.rowwise() - data_.mu.transpose();
    // Eq. 4 on the varying DOFs: d = 2 for every ASF clip (at most 47), 3 for a BVH with D ≥ 60.
    const int d = latentDimensionFor(static_cast<int>(data_.Y.cols()));
    X_ = whitenedPca(Ybar, std::min<int>(d, static_cast<int>(data_.Y.cols()))).X;
    if (opt_.startNoise > 0.0) X_ += opt_.startNoise * standardNormal(X_.rows(), X_.cols(), opt_.startSeed);
    psi_ = Eigen::VectorXd::Zero(paramCount(opt_.kind));  // α = β = γ = η = 1
    if (opt_.prior == LatentPrior::kSmooth)
        prior_ = TemporalPrior::secondDifference(data_.frames, opt_.resolvedPriorWeight(), data_.clips);
    if (opt_.prior == LatentPrior::kPaced)
        prior_ = TemporalPrior::posePaced(data_.frames, data_.Y, opt_.resolvedPriorWeight(), data_.clips);
    if (opt_.backConstraints) {  // start from the mapping's nearest reach of the PCA layout
        back_ = BackConstraint(Ybar);
        A_ = back_.fit(X_);
        X_ = back_.latent(A_);
    }
    active_ = selectActive();
    const GpEvaluation ev =
        evaluateGp(Kernel(opt_.kind, psi_), rowsOf(X_, active_), centredRows(data_, active_), objective(), false);
    lInit_ = ev.value;
    if (!prior_.empty()) lInit_ += prior_.value(X_);
    prevW_ = ev.ok ? ev.w : Eigen::VectorXd::Ones(data_.Y.cols());
    // The paper's Step 3 initialises w = 1; the Step-9 Δ of the first iteration is measured
    // against that.
    prevW_.setOnes();
}

GpObjectiveOptions Trainer::objective() const {
    GpObjectiveOptions o;
    if (opt_.paperLiteral) {
        o.weights = WeightMode::kProfileFree;
        o.jacobianCoef = static_cast<double>(data_.Y.rows());
    }
    return o;
}

std::vector<int> Trainer::selectActive() const {
    return selectActiveSet(Kernel(opt_.kind, psi_), X_, opt_.activeSize, resolveWorkers(opt_.threads)).active;
}

double Trainer::optimizeActive(const std::vector<int>& active, IterationLog* entry, const std::atomic<bool>* cancel) {
    ScgOptions so;
    so.maxIterations = opt_.scgIterations;
    so.tolX = opt_.scgTolX;
    so.tolF = opt_.scgTolF;
    if (cancel) so.shouldStop = [cancel] { return cancel->load(); };
    ActiveStepResult step;
    if (!back_.empty()) {  // every point moves with A (docs/maths.md §22)
        BackStepResult back = optimizeBackConstrainedStep(opt_.kind, psi_, A_, back_, active,
                                                          centredRows(data_, active), prior_, so, objective());
        A_ = std::move(back.A);
        X_ = back_.latent(A_);
        step = std::move(back.step);
    } else {
        // The inactive rows stay where they are during Step 6.
        const LatentTerm extra = prior_.empty() ? LatentTerm() : priorOnActive(prior_, X_, active);
        step =
            optimizeActiveStep(opt_.kind, psi_, rowsOf(X_, active), centredRows(data_, active), so, objective(), extra);
    }
    psi_ = step.psi;
    for (std::size_t i = 0; i < active.size(); ++i) X_.row(active[i]) = step.XI.row(static_cast<Eigen::Index>(i));
    if (entry) {
        entry->L_before = step.before;
        entry->L = step.after;
        entry->gradInf = step.gradInf;
        entry->scgIterations = step.iterations;
        entry->jitter = step.jitter;
        entry->trialJitterMax = step.trialJitterMax;
        entry->psi = psi_;
        entry->w = step.ok ? step.w : prevW_;
    }
    return step.after;
}

void Trainer::optimizeInactive(const std::vector<int>& active, const std::atomic<bool>* cancel) {
    const std::vector<int> inactive = complementOf(active, static_cast<int>(X_.rows()));
    // Back-constrained points are not free: Step 6 already moved every one along the mapping.
    if (inactive.empty() || !back_.empty()) return;
    const Eigen::MatrixXd Yhat = centredRows(data_, active);
    const GpEvaluation ev = evaluateGp(Kernel(opt_.kind, psi_), rowsOf(X_, active), Yhat, objective(), false);
    if (!ev.ok) return;  // cannot factor K: leave the inactive points where they are
    const ActiveSetPosterior pm(Kernel(opt_.kind, psi_), rowsOf(X_, active), Yhat, data_.mu, ev.w);
    ScgOptions so;
    so.maxIterations = opt_.pointIterations;
    so.tolX = opt_.scgTolX;
    so.tolF = opt_.scgTolF;
    optimizeInactivePoints(pm, data_.Y, inactive, X_, so, opt_.threads, cancel, prior_.empty() ? nullptr : &prior_);
}

std::vector<double> Trainer::objectiveHistory() const {
    std::vector<double> out{lInit_};
    for (const IterationLog& e : log_) out.push_back(e.L);
    for (double v : out)
        if (!std::isfinite(v)) return {};
    return out;
}

Eigen::VectorXd Trainer::currentWeights() const {
    const GpEvaluation ev =
        evaluateGp(Kernel(opt_.kind, psi_), rowsOf(X_, active_), centredRows(data_, active_), objective(), false);
    return ev.ok ? ev.w : prevW_;
}

bool Trainer::step(const std::atomic<bool>* cancel) {
    const auto t0 = std::chrono::steady_clock::now();
    auto isCancelled = [&] { return cancel && cancel->load(); };
    if (isCancelled()) {
        cancelled_ = true;
        return false;
    }
    IterationLog e;
    e.iter = static_cast<int>(log_.size()) + 1;
    const std::vector<int> previous = active_;
    const std::vector<int> i5 = frozen_ ? active_ : selectActive();  // Step 5
    optimizeActive(i5, &e, cancel);                                  // Step 6
    if (isCancelled()) {
        cancelled_ = true;
        return false;
    }
    active_ = frozen_ ? i5 : selectActive();  // Step 7
    optimizeInactive(active_, cancel);        // Step 8
    if (isCancelled()) {                      // the state is part-way through an iteration: not logged
        cancelled_ = true;
        return false;
    }
    // Step 9.
    const Eigen::VectorXd rawNow = rawParams(e.psi),
                          rawPrev = rawParams(log_.empty() ? Eigen::VectorXd::Zero(e.psi.size()) : log_.back().psi);
    const Eigen::VectorXd logNow = e.psi,
                          logPrev = log_.empty() ? Eigen::VectorXd::Zero(e.psi.size()) : log_.back().psi;
    e.maxDeltaRaw = std::max((rawNow - rawPrev).cwiseAbs().maxCoeff(), (e.w - prevW_).cwiseAbs().maxCoeff());
    e.maxDeltaLog =
        std::max((logNow - logPrev).cwiseAbs().maxCoeff(), (e.w.array().log() - prevW_.array().log()).abs().maxCoeff());
    e.activeOverlap = overlapFraction(active_, previous);
    prevW_ = e.w;
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    log_.push_back(e);
    const double metric = opt_.test == ConvergenceTest::kRaw ? e.maxDeltaRaw : e.maxDeltaLog;
    return std::isfinite(metric) && metric < opt_.tolerance;
}

TrainingData trainingDataFromClip(const Clip& clip, const std::vector<int>& frames) {
    const Eigen::MatrixXd all = poseMatrix(clip);
    Eigen::MatrixXd rows(frames.size(), all.cols());
    for (std::size_t r = 0; r < frames.size(); ++r) {
        if (frames[r] < 0 || frames[r] >= clip.frameCount())
            throw std::invalid_argument("trainingDataFromClip: frame " + std::to_string(frames[r]) +
                                        " outside the clip");
        rows.row(static_cast<Eigen::Index>(r)) = all.row(frames[r]);
    }
    return prepareTrainingData(rows, frames);
}

TrainingData trainingDataFromClips(const std::vector<const Clip*>& clips, const std::vector<std::vector<int>>& frames) {
    if (clips.empty() || clips.size() != frames.size())
        throw std::invalid_argument("trainingDataFromClips: expected one frame list per clip (at least one clip)");
    if (clips.size() == 1) return trainingDataFromClip(*clips[0], frames[0]);
    std::size_t n = 0;
    for (const auto& f : frames) n += f.size();
    Eigen::MatrixXd rows(static_cast<Eigen::Index>(n), PoseLayout(clips[0]->skeleton).size());
    std::vector<int> allFrames, clipOf;
    for (std::size_t c = 0; c < clips.size(); ++c) {
        const Eigen::MatrixXd all = poseMatrix(*clips[c]);
        for (int f : frames[c]) {
            if (f < 0 || f >= clips[c]->frameCount())
                throw std::invalid_argument("trainingDataFromClips: frame " + std::to_string(f) + " outside clip " +
                                            clips[c]->name);
            rows.row(static_cast<Eigen::Index>(allFrames.size())) = all.row(f);
            allFrames.push_back(f);
            clipOf.push_back(static_cast<int>(c));
        }
    }
    TrainingData out = prepareTrainingData(rows, allFrames);
    out.clips = std::move(clipOf);
    return out;
}

TrainResult trainOnClip(Clip clip, const TrainOptions& options,
                        const std::function<void(const IterationLog&)>& progress, const std::atomic<bool>* cancel) {
    return trainOnClip(std::move(clip), options, controlOf(progress, cancel));
}

TrainResult trainOnClip(Clip clip, const TrainOptions& options, const TrainControl& control) {
    unwrapClip(clip);
    std::vector<int> frames(clip.frameCount());
    for (int t = 0; t < clip.frameCount(); ++t) frames[t] = t;
    TrainResult result = train(trainingDataFromClip(clip, frames), options, control);
    result.model.clip = std::move(clip);
    return result;
}

GpModel snapshotModel(const Trainer& trainer, bool converged) {
    const TrainOptions& options = trainer.options();
    GpModel m;
    m.kind = options.kind;
    m.logParams = trainer.logParams();
    m.X = trainer.latent();
    m.Y = trainer.data().Y;
    m.mu = trainer.data().mu;
    m.active = trainer.activeSet();
    m.w = trainer.currentWeights();
    m.keptColumns = trainer.data().keptColumns;
    m.constantColumns = trainer.data().constantColumns;
    m.constantValues = trainer.data().constantValues;
    m.trainingFrames = trainer.data().frames;
    m.trainingClips = trainer.data().clips;
    m.settings.activeSize = options.activeSize;
    m.settings.outerIterations = options.outerIterations;
    m.settings.scgIterations = options.scgIterations;
    m.settings.pointIterations = options.pointIterations;
    m.settings.tolerance = options.tolerance;
    m.settings.prior = options.prior;
    m.settings.priorWeight = options.resolvedPriorWeight();
    m.settings.backConstraints = options.backConstraints;
    m.iterations = static_cast<int>(trainer.log().size());
    m.converged = converged;
    m.objectiveHistory = trainer.objectiveHistory();
    return m;
}

TrainResult train(const TrainingData& data, const TrainOptions& options,
                  const std::function<void(const IterationLog&)>& progress, const std::atomic<bool>* cancel) {
    return train(data, options, controlOf(progress, cancel));
}

TrainResult train(const TrainingData& data, const TrainOptions& options, const TrainControl& control) {
    const auto start = std::chrono::steady_clock::now();
    Trainer trainer(data, options);
    TrainResult res;
    res.lInit = trainer.initialObjective();
    double longestIteration = 0.0;
    for (int t = 0; t < options.outerIterations; ++t) {
        // The budget: an iteration that would end after it (judged by the longest so far) does not start.
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (control.timeBudgetSeconds > 0.0 && t > 0 && elapsed + longestIteration > control.timeBudgetSeconds) {
            res.outOfTime = true;
            break;
        }
        const bool conv = trainer.step(control.cancel);
        if (trainer.cancelled()) {
            res.cancelled = true;
            break;
        }
        longestIteration = std::max(longestIteration, trainer.log().back().seconds);
        if (control.afterIteration) control.afterIteration(trainer);
        if (conv) {
            res.converged = true;
            if (options.stopOnConvergence) break;
        }
    }
    res.log = trainer.log();
    res.model = snapshotModel(trainer, res.converged);
    return res;
}

}  // namespace mgp::gp
