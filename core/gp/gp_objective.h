#pragma once
// The training objective L_GP (docs/maths.md §4), corrected as decided there:
//
//   L_GP = (D/2) ln|K| + ½ Σ_k w_k² s_k + ½ Σ_{i∈I} ‖x_i‖² + Σ_p ln θ_p − c Σ_k ln w_k,
//   s_k = ŷ_kᵀ K⁻¹ ŷ_k, c = M (rows of the data term), θ = (α, γ, β[, η]).
//
// By default W is profiled out under the scale gauge Σ ln w_k = 0: w_k = sqrt(g/s_k),
// g = exp(mean ln s_k) (docs/maths.md §4.2). The gradient is then taken with W held at that value
// (envelope theorem). Evaluation is stable (docs/maths.md §4.4): Cholesky with escalating jitter,
// log-params clamped to ±36 inside the kernel, and no NaN ever leaves evaluateGp(): a failure
// returns value = +∞ with ok = false.
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "gp/kernel.h"

namespace mgp::gp {

enum class WeightMode {
    kProfileGauge,  // w_k = sqrt(g/s_k), Σ ln w = 0 (the default for both models)
    kProfileFree,   // w_k = sqrt(c/s_k), no gauge
    kFixed          // w given explicitly (tests of the gauge family, docs/maths.md §4.2)
};

struct GpObjectiveOptions {
    WeightMode weights = WeightMode::kProfileGauge;
    Eigen::VectorXd fixedW;      // for kFixed (size D)
    double jacobianCoef = -1.0;  // c of −c Σ ln w_k; < 0 means M
};

struct GpEvaluation {
    bool ok = false;
    double value = 0.0;        // +∞ when !ok
    Eigen::VectorXd gradPsi;   // ∂L/∂ψ (paramCount)
    Eigen::MatrixXd gradX;     // ∂L/∂X_I (M×d)
    Eigen::VectorXd gradLogW;  // raw ∂L/∂ln w_k = w_k² s_k − c (W not projected)
    Eigen::VectorXd w, s;      // weights used and the quadratic forms s_k
    double jitter = 0.0;       // jitter added to K's diagonal (0 normally)
};

// Cholesky with escalating jitter (docs/maths.md §4.4 step 2): no jitter, then 1e-5·mean(diag K),
// ×10 per retry, at most 10 tries. Returns false if every try failed. `jitter` receives the amount
// added.
bool jitterCholesky(const Eigen::MatrixXd& K, Eigen::LLT<Eigen::MatrixXd>& llt, double& jitter);

// The M×M scratch of one evaluation, reused by the caller across calls (no page faults per call),
// like PointWorkspace for the per-point objective. Only storage is reused, never values, so a
// result does not depend on what the workspace held. One workspace per thread.
struct GpWorkspace {
    GramParts parts;
    Eigen::MatrixXd K, G, scratch;
    Eigen::LLT<Eigen::MatrixXd> llt;
    GradXScratch gradX;
};

// L_GP and its gradient at (kernel, X_I) for the centred active rows Ŷ (M×D, unscaled).
GpEvaluation evaluateGp(const Kernel& kernel, const Eigen::MatrixXd& XI, const Eigen::MatrixXd& Yhat,
                        const GpObjectiveOptions& options, bool wantGradient, GpWorkspace& workspace);
// The same with a workspace of its own (allocates; for one-off evaluations).
GpEvaluation evaluateGp(const Kernel& kernel, const Eigen::MatrixXd& XI, const Eigen::MatrixXd& Yhat,
                        const GpObjectiveOptions& options = {}, bool wantGradient = true);

// Packing of the Step-6 optimisation vector z = [ψ; vec(X_I)] (X_I column-major).
Eigen::VectorXd packParams(const Eigen::VectorXd& psi, const Eigen::MatrixXd& XI);
void unpackParams(const Eigen::VectorXd& z, int paramCount, int m, int d, Eigen::VectorXd& psi, Eigen::MatrixXd& XI);

}  // namespace mgp::gp
