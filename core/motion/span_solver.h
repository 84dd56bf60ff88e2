#pragma once
// Span regeneration as one problem: every frame strictly inside (first, last) is solved together.
//
// Unknowns: z_t = (x_t, y_t) for each inner frame t (latent point, kept pose columns in degrees).
// The root translation of every frame stays at its captured value. With u_t = y_t − ŷ_t and
// v_t = x_t − x̂_t the changes from the capture (ŷ, x̂; zero on the captured frames outside the
// span), the objective is
//
//   F = Σ_t [ κ·L_IK(x_t, y_t − r_t)                      learned prior (gp/point_objective.h)
//           + w_c Σ_c ‖FK_c(y_t) − p_c,t‖²                 targets: the edited path, held feet, pins
//           + ρ_root ‖u_t,root‖² + Σ_k (ρ + ½κℓ w_k) u_t,k²  root orientation (and everything) near capture,
//           + ρ_x ‖v_t‖² ]                                the body away from the edited limb more (ℓ)
//     + s_y Σ_s ‖u_{s−1} − 2u_s + u_{s+1}‖² + s_x Σ_s ‖v_{s−1} − 2v_s + v_{s+1}‖²
//
// with s over first..last, so the two captured frames on each side enter the differences and the
// span joins the capture with continuous value and velocity (C¹). κ = (1 − λ)/λ is the per-frame
// learned IK's weighting (ik/learned_ik.h) with every target equally stiff.
//
// Why this objective and not the per-frame one: per-frame solves start from each frame's own
// latent point, and neighbouring frames' latent points lie on different branches, so neighbouring
// solutions pop. Here the smoothness terms act on the CHANGE from the capture, so the captured
// motion costs nothing and only what the edit adds is smoothed; the captured detail stays.
// r_t = ŷ_t − f(x̂_t) is the captured frame's residual from the model mean (the detail the model
// does not explain): with `keepResidual` the prior judges y_t − r_t, so at zero edit the captured
// span is a stationary point of the prior's pose term instead of being pulled toward f(x). Root
// orientation is a pose DOF like the others but carries an extra stiffness ρ_root, so it turns
// only when the targets need it. Locality ℓ (ik/locality.h): w_k is 0 on the limbs of the path
// targets' effectors and 1 on the rest of the body, so an edited hand moves its arm, and the spine,
// the legs and the other limbs only as much as the path needs. It is scaled by ½κ so that one ℓ
// weighs against the prior as the constrained IK's ½ℓ‖y − y_ref‖² does beside its unscaled L_IK.
//
// Solver (default): Levenberg–Marquardt on the stacked z from the captured span. Its matrix is
// the exact Hessian of the quadratic terms (smoothness, stay, root), Gauss–Newton 2JᵀJ for the
// targets, the prior's exact y–y block κW²/σ²(x) and its x–x and x–y blocks by central
// differences of the analytic gradient in x. One block per frame; second differences couple
// frames up to two apart, so the matrix is block-banded and its Cholesky factor costs O(n) in
// the frame count (motion/block_banded.h). Steps are accepted only when F decreases.
// Option: L-BFGS (LBFGS++) on z, diagonally preconditioned by the start point's curvature; it
// needs hundreds of iterations on this stiff, coupled problem and is kept for comparison.
#include <Eigen/Core>
#include <atomic>
#include <string>
#include <vector>

#include "gp/model_version.h"
#include "ik/locality.h"
#include "motion/block_banded.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"
#include "skeleton/skeleton.h"

namespace mgp {

// One effector held at a world position on one frame (cm).
struct SpanTarget {
    int frame = 0;  // clip frame (0-based), strictly inside the span
    Effector effector = Effector::kRFoot;
    Eigen::Vector3d targetCm = Eigen::Vector3d::Zero();
    enum class Kind { kPath, kContact, kPin } kind = Kind::kPath;
};

// The motion an edit starts from (one entry per clip frame): each frame's pose and, where known,
// its latent point (an empty entry: the frame's captured latent start). The solvers treat it as
// "the capture": the change u, v, the stay and smoothness terms and the residual r_t are taken
// from it, so a second edit builds on the first instead of starting over from the capture.
struct EditBase {
    std::vector<Pose> frames;
    std::vector<Eigen::VectorXd> x;  // empty, or one per frame
    // Where held contacts, pins and placements are held (empty: `frames`). A whole-pose change
    // layers `frames` but holds what its frame kept in place where it was before the layer.
    std::vector<Pose> holdFrames;
    // Held effectors the change moved on purpose (a hand below a rotated elbow): held where
    // `frames` has them even when holdFrames is given.
    std::vector<Effector> followLayer;
    // Where the placements alone (MotionEditJob::heldPlaced) are held (empty: as the rest). A path
    // regeneration solves from the capture but holds what earlier gestures placed where the edited
    // motion has it; its planted feet and pins stay where `frames` has them.
    std::vector<Pose> placedFrames;
};

// "" or what is wrong with `base` for `model` (frame count, skeleton, latent size, NaN).
std::string validateEditBase(const gp::GpModel& model, const EditBase& base);

struct SpanWeights {
    double lambda = 0.999;                   // κ = (1 − λ)/λ on L_IK
    double target = 100.0;                   // weight of every target, per cm² (scales the targets' term)
    double smoothPose = 0.1;                 // s_y, per deg² of second difference of u
    double smoothLatent = 10.0;              // s_x, per (latent unit)² of second difference of v
    double root = 0.1;                       // ρ_root, per deg² of root orientation change
    double stay = 1e-4;                      // ρ, per deg² of any change
    double locality = kDefaultSpanLocality;  // ℓ per deg² of change, weighted by w_k and ½κ (see above)
    double stayLatent = 10.0;                // ρ_x, per (latent unit)² of change of x
    bool keepResidual = true;                // prior on y − r_t (see above); false: the paper's L_IK(x, y)
};

enum class SpanMethod { kLevenbergMarquardt, kLbfgs };

// kStalled: a target is out of reach and the distances of the missed ones stopped falling
// (SpanSolver::targetsStalled); the motion is the best found, the targets it missed are reported.
enum class SpanStop { kConverged, kStalled, kIterationCap, kLineSearch, kCancelled, kInvalid };
const char* spanStopName(SpanStop s);

struct SpanResult {
    std::vector<Pose> poses;               // one per inner frame, first+1..last−1
    std::vector<Eigen::VectorXd> x;        // latent points
    std::vector<Eigen::VectorXd> y;        // kept pose columns
    std::vector<double> lik;               // L_IK(x_t, y_t − r_t)
    std::vector<double> targetResidualCm;  // one per SpanTarget, in request order
    double objective = 0.0;
    int iterations = 0;
    int evaluations = 0;
    SpanStop stop = SpanStop::kInvalid;
    std::string diagnostic;
};

class SpanSolver {
public:
    // first, last: the span's captured end frames (first + 1 < last). Throws
    // std::invalid_argument when the span does not fit the model's clip.
    // `base`: the motion to start from (EditBase; null: the model's captured clip), of the model's
    // skeleton (MotionEditJob::validate checks it). Its root translations are kept. A base of
    // another frame count is another clip (in-betweening, motion/inbetween.h): it must carry a
    // latent point for every inner frame, else std::invalid_argument.
    SpanSolver(gp::ModelVersionPtr version, int first, int last, SpanWeights weights = {},
               const EditBase* base = nullptr);

    int innerCount() const { return n_; }
    int variableCount() const { return n_ * (d_ + D_); }
    // "" or what is wrong with the targets (frame outside the span, NaN, effector absent).
    std::string validate(const std::vector<SpanTarget>& targets) const;
    void setTargets(std::vector<SpanTarget> targets);  // must validate
    // Keeps inner frame `frame` at exactly `pose` and latent point `x` (a drag's accepted pose):
    // its variables become constants (zero gradient, an identity block decoupled from its
    // neighbours, so every step leaves them bit for bit), and the frames around it join it
    // through the second differences. "" when held, else why not (not an inner frame, another
    // skeleton, x not d-dimensional, NaN).
    std::string holdFrame(int frame, const Pose& pose, const Eigen::VectorXd& x);
    // Sets the span's first or last frame (a fixed end) to `pose` instead of the base's: its
    // change from the base enters the second differences, so the inner frames join it as they
    // join a held inner frame (a drag on the clip's first or last frame). "" or why not.
    std::string holdEnd(int frame, const Pose& pose);
    // The captured span's stacked z (the start point).
    const Eigen::VectorXd& capturedZ() const { return z0_; }
    // F and its gradient (exposed for the gradient test).
    double objective(const Eigen::VectorXd& z, Eigen::VectorXd& grad);
    // Minimises F from the captured span. Never throws.
    // Stops when an accepted step lowers F by less than relativeTolerance·max(1, |F|).
    SpanResult solve(int maxIterations = 100, double relativeTolerance = 1e-9,
                     const std::atomic<bool>* cancel = nullptr, SpanMethod method = SpanMethod::kLevenbergMarquardt);
    // Levenberg–Marquardt also stops (kStalled) when, over kStallWindow accepted steps, the missed
    // targets' distances stopped falling (targetsStalled; docs/maths-regeneration.md, "Solver").
    // 0 turns that test off (the comparison in the tests).
    static constexpr int kStallWindow = 10;
    static constexpr double kDefaultStallRelative = 1e-2;
    void setStallRelative(double relative) { stallRelative_ = relative; }
    // The stall test on the targets' distances e (cm) at a window's start and end: some target is
    // missed now (by more than kReachedToleranceCm), and each target missed now has stood still:
    // its e² changed by less than `relative`·e² now, or e by less than kStallStepCm. A target
    // closing in (a reachable one next to a large miss), newly missed or drifting away by more
    // keeps the solve going.
    static constexpr double kStallStepCm = 0.1;
    static bool targetsStalled(const std::vector<double>& startCm, const std::vector<double>& nowCm, double relative);

private:
    void poseOf(int i, const Eigen::VectorXd& z, Pose& pose);
    void computeScaling();
    void assemble(const Eigen::VectorXd& z, BlockBandedMatrix& h);
    SpanResult solveLbfgs(int maxIterations, double relativeTolerance, const std::atomic<bool>* cancel);
    SpanResult solveLm(int maxIterations, double relativeTolerance, const std::atomic<bool>* cancel);
    SpanResult finish(SpanResult r, const Eigen::VectorXd& best);
    std::vector<double> targetResidualsCm(const Eigen::VectorXd& z);  // one per target, in order
    gp::ModelVersionPtr version_;
    PoseLayout layout_;
    SpanWeights w_;
    double stallRelative_ = kDefaultStallRelative;
    int first_, last_, n_, d_, D_;
    double kappa_;
    std::vector<Eigen::VectorXd> xCap_;        // x̂ of frames first−1..last+1 (index t − first + 1)
    std::vector<Eigen::VectorXd> yCap_;        // ŷ likewise
    std::vector<Eigen::VectorXd> resid_;       // r_t of inner frames
    std::vector<Pose> innerBase_;              // the base (or captured) pose of each inner frame
    int frames_ = 0;                           // frames of the base motion (the clip's without one)
    std::vector<std::vector<int>> targetsOf_;  // inner frame → indices into targets_
    std::vector<SpanTarget> targets_;
    std::vector<int> rootKept_;       // kept-column indices of the root orientation
    int heldInner_ = -1;              // inner index of the held frame (holdFrame), or −1
    Eigen::VectorXd uFirst_, uLast_;  // the ends' change from the base (holdEnd; empty: none)
    Pose heldPose_;
    Eigen::VectorXd z0_, scale_;
    Eigen::VectorXd stay_;  // ρ + ℓ w_k per kept column
    // Workspace.
    gp::PointWorkspace pointWs_;
    FkState fk_;
    Pose pose_;
    Eigen::VectorXd full_, gradFull_, xt_, yt_, gx_, gy_;
    Eigen::Matrix<double, 3, Eigen::Dynamic> jac_;
    // What objective() last computed, reused by assemble() at the same z: each target's
    // Jacobian (kept columns, 3×D) and each frame's prior gradient (x, y) and σ².
    Eigen::VectorXd lastZ_;
    std::vector<Eigen::MatrixXd> targetJac_;
    std::vector<Eigen::VectorXd> priorGx_, priorGy_;
    std::vector<double> priorVar_;
};

}  // namespace mgp
