#pragma once
// The per-point objective L_IK (docs/maths.md §9), corrected form:
//
//   L_IK(x, y) = ‖W (y − f(x))‖² / (2σ²(x)) + (D/2) ln σ²(x) + ½‖x‖²
//   f(x)  = μ + Ŷᵀ K⁻¹ k(x)                (unscaled pose space, degrees, kept columns)
//   σ²(x) = 1/β + max(0, k_f(x,x) − k(x)ᵀ K⁻¹ k(x))   (so σ² ≥ 1/β exactly)
//
// ActiveSetPosterior is the GP posterior given the active set: the immutable precomputation of
// docs/maths.md §9.1 (chol K, K⁻¹, B = K⁻¹Ŷ) for one model state; evaluate() is thread-safe
// (const, no shared scratch). optimizeInactivePoints() runs
// Step 8: an independent SCG per inactive point, the points in fixed blocks whose evaluations are
// batched into matrix products, the blocks in parallel, each result written to its own
// preallocated slot, so the output is bit-identical for any thread count.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <atomic>
#include <vector>

#include "gp/kernel.h"
#include "gp/scg.h"
#include "gp/temporal_prior.h"

namespace mgp::gp {

// Scratch for the allocation-free ActiveSetPosterior::evaluate overload: sized on first use, reused after.
struct PointWorkspace {
    Eigen::VectorXd k, v, a, f, r, wr, bwr, phiX;  // v = L⁻¹k (K = LLᵀ), a = K⁻¹k
    Eigen::VectorXd rbf, angular, cosine;          // per active point: the RBF and angular parts of k, φ(x)·φ(x_j)
    Eigen::MatrixXd J;                             // M×d: ∂k/∂x
    Eigen::MatrixXd linvJ;                         // M×d: L⁻¹ ∂k/∂x (latentHessian)
    double variance = 0.0;                         // σ²(x) of the last evaluation
    bool clamped = false;  // the noise-free part of σ² was clamped at 0 (σ² = 1/β, flat in x)
};

// Scratch for ActiveSetPosterior::evaluateBatch: sized on first use, reused after.
struct PointBatchWorkspace {
    PointWorkspace point;                 // one point's kernel terms at a time
    Eigen::MatrixXd K, V, A, F, WR, BWR;  // M×b: k, L⁻¹k, K⁻¹k; D×b: f, W²(y − f); M×b: B W²(y − f)
    Eigen::MatrixXd J;                    // M×(d·b): each point's ∂k/∂x, side by side
    Eigen::VectorXd diag, diagGrad;       // per point: k(x,x), and ∂k(x,x)/∂x = diagGrad · x
    Eigen::VectorXd E, s2;                // per point: ‖W(y − f)‖², σ²
    std::vector<char> clamped;            // per point: σ²'s noise-free part clamped at 0
    Eigen::VectorXd x;                    // the point at hand
};

class ActiveSetPosterior {
public:
    // XI: active latent points (M×d); Yhat: centred active rows (M×D); mu: training mean (D);
    // w: scale weights (D). Throws std::runtime_error if K cannot be factored.
    ActiveSetPosterior(const Kernel& kernel, const Eigen::MatrixXd& XI, const Eigen::MatrixXd& Yhat,
                       const Eigen::VectorXd& mu, const Eigen::VectorXd& w);

    int latentDim() const { return static_cast<int>(XI_.cols()); }
    int poseDim() const { return static_cast<int>(mu_.size()); }
    const Kernel& kernel() const { return kernel_; }
    double jitter() const { return jitter_; }

    // Mean pose f(x) and variance σ²(x).
    void predict(const Eigen::VectorXd& x, Eigen::VectorXd& mean, double& variance) const;
    // σ²(x) at every row of `points` (n×d), as predict gives it, without the means: one K⁻¹
    // product for all of them (a matrix product instead of n matrix-vector products). For maps.
    Eigen::VectorXd variances(const Eigen::MatrixXd& points) const;
    // The same prediction from the GP conditioned on every active point except `heldOut`
    // (distinct indices into the active set): the block-inverse identity
    //   (K_{−B})⁻¹ = P − Q S⁻¹ Qᵀ,   K⁻¹ = [P Q; Qᵀ S]
    // gives it in O(M|B| + |B|³) from this model's K⁻¹ and K⁻¹Ŷ, with no refactorisation
    // (docs/maths-ik.md §5: what a captured pose scores when the model has not seen its moment).
    void predictHoldingOut(const Eigen::VectorXd& x, const std::vector<int>& heldOut, Eigen::VectorXd& mean,
                           double& variance) const;
    // L_IK(x, y) under that held-out prediction; its σ² goes to `variance`.
    double evaluateHoldingOut(const Eigen::VectorXd& x, const Eigen::VectorXd& y, const std::vector<int>& heldOut,
                              double& variance) const;

    // L_IK(x, y); gradients are written when the pointers are non-null (sized by the callee).
    double evaluate(const Eigen::VectorXd& x, const Eigen::VectorXd& y, Eigen::VectorXd* gradX,
                    Eigen::VectorXd* gradY) const;
    // The same value and gradients with no heap allocation after the first call on `ws` (the
    // interactive IK's and Step 8's path): k(x) and ∂k/∂x vectorised over the active points, σ² from the
    // Cholesky factor, free of the cancellation noise the K⁻¹ form above has next to the data
    // (docs/maths.md §9.1). gradX/gradY, when given, must already have sizes d and D.
    double evaluate(const Eigen::VectorXd& x, const Eigen::VectorXd& y, PointWorkspace& ws, Eigen::VectorXd* gradX,
                    Eigen::VectorXd* gradY) const;
    // L_IK and ∂L_IK/∂x at the b columns of X (d×b) against the columns of Y (D×b): what b calls
    // of the evaluate() above give, up to rounding, with their matrix-vector products done as
    // matrix products (L⁻¹K, L⁻ᵀ(L⁻¹K), BᵀK, B W²R), which run several times faster per
    // multiply-add. values gets b entries, gradX d×b.
    void evaluateBatch(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y, PointBatchWorkspace& ws,
                       Eigen::VectorXd& values, Eigen::MatrixXd& gradX) const;
    // After evaluate(x, y, ws, …) on the same x and y, with or without gradients: the gradients
    // that call would have written (the same arithmetic), so a value-only evaluation that turns
    // out to be needed with derivatives is not repeated.
    void gradients(const Eigen::VectorXd& x, PointWorkspace& ws, Eigen::VectorXd* gradX, Eigen::VectorXd* gradY) const;

    // After evaluate(x, y, ws, ...) on the same x: the mean's Jacobian ∂f/∂x (D×d) and the variance
    // gradient ∂σ²/∂x (d), both exact (∂σ²/∂x = 0 where the clamp is active). No allocation once
    // Jf and dSigma2 have their sizes.
    void meanVarianceJacobians(const Eigen::VectorXd& x, const PointWorkspace& ws, Eigen::MatrixXd& Jf,
                               Eigen::VectorXd& dSigma2) const;
    // After evaluate(x, y, ws, gradX, …) with a gradient and meanVarianceJacobians(x, ws, Jf, dSigma2)
    // on the same x: the exact Hessian ∂²L_IK/∂x² (d×d, y fixed), from the kernel's second
    // derivatives (docs/maths-ik.md §2). No allocation once ws and H have their sizes.
    void latentHessian(const Eigen::VectorXd& x, PointWorkspace& ws, const Eigen::MatrixXd& Jf,
                       const Eigen::VectorXd& dSigma2, Eigen::MatrixXd& H) const;

private:
    // σ²(x) = 1/β + max(0, k(x,x) − explained), where explained = k(x)ᵀK⁻¹k(x): predict's and
    // variances' one formula.
    double varianceGiven(const Eigen::VectorXd& x, double explained) const;
    // k(x), ∂k/∂x and their RBF and angular parts into ws (evaluate's and evaluateBatch's first step).
    void crossTerms(const Eigen::VectorXd& x, PointWorkspace& ws) const;
    // ∂L_IK/∂x from k's Jacobian J, a = K⁻¹k, bwr = B W²(y − f), E = ‖W(y − f)‖², σ² = s2 and the
    // diagonal's scale (gradients' and evaluateBatch's one formula).
    void latentGradient(const Eigen::VectorXd& x, const Eigen::Ref<const Eigen::MatrixXd>& J,
                        const Eigen::Ref<const Eigen::VectorXd>& a, const Eigen::Ref<const Eigen::VectorXd>& bwr,
                        double E, double s2, bool clamped, double diagGrad, Eigen::Ref<Eigen::VectorXd> gradX) const;
    // k(x,x) from ws.phiX of crossTerms at x.
    double diagonalAt(const PointWorkspace& ws) const;
    // ∂k(x,x)/∂x = this · x (needs ws.phiX of an evaluation at x).
    double diagonalGradientScale(const Eigen::VectorXd& x, const PointWorkspace& ws) const;

    Kernel kernel_;
    Eigen::MatrixXd XI_;
    Eigen::VectorXd mu_, w_;
    Eigen::LLT<Eigen::MatrixXd> llt_;
    Eigen::MatrixXd Kinv_, B_;
    Eigen::MatrixXd Linv_;  // L⁻¹ of K = LLᵀ (lower triangular): σ² without cancellation noise
    Eigen::MatrixXd phiI_;  // φ(x_j) of the active points (FAS), for the fused evaluation
    double jitter_ = 0.0;
};

// Step 8: for every row index in `points`, minimise L_IK(x, Y.row(i)) over x from X.row(i) with
// SCG, writing the result back into X. threads ≤ 0 means std::thread::hardware_concurrency().
// If `cancel` becomes true the remaining points are skipped (X is then partly updated).
// With a non-empty temporal `prior` (docs/maths.md §19) each point minimises L_IK plus the prior
// terms that involve it, its time neighbours held at their current values; the points go in
// three passes by their time position mod 3 (no two points of one pass share a term), each pass
// seeing the previous passes' results: a block Gauss-Seidel sweep, still deterministic.
void optimizeInactivePoints(const ActiveSetPosterior& model, const Eigen::MatrixXd& Y, const std::vector<int>& points,
                            Eigen::MatrixXd& X, const ScgOptions& options, int threads = 0,
                            const std::atomic<bool>* cancel = nullptr, const TemporalPrior* prior = nullptr);

}  // namespace mgp::gp
