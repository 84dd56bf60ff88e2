#pragma once
// Back-constraints (Lawrence & Quiñonero-Candela 2006; docs/maths.md §22): the latent points are
// a smooth function of the poses instead of free parameters,
//
//   x_n = Σ_r a_r k_bc(y_n, y_{b_r}),   k_bc(y, y') = exp(−‖y − y'‖² / (2ℓ²)),   X = K A,
//
// over R basis rows b_r (every ⌈N/R⌉-th training row, R ≤ kMaxBackBasis), ℓ² a quarter of the
// median squared distance between training rows and basis rows. Training then optimises (ψ, A)
// in Step 6 and Step 8 has nothing to do: every inactive point follows the mapping, so two frames
// with similar poses always land close together. The kernel is fixed at construction (it depends
// on Y only).
#include <Eigen/Core>
#include <vector>

#include "gp/scg.h"
#include "gp/temporal_prior.h"
#include "gp/train/active_step.h"

namespace mgp::gp {

// Basis rows are capped so that K stays N×R (memory O(N·R), like the training's O(N·M)).
constexpr int kMaxBackBasis = 500;
// ℓ² over the median squared pose distance: 1/4 reconstructed held-out frames better than 1 on
// walk, kick and jump, and within 0.011° of 1/16 (better on the jump; docs/maths.md §22).
constexpr double kBackLengthScale2 = 0.25;

class BackConstraint {
public:
    BackConstraint() = default;
    // Ybar: N×D centred training rows. Throws std::invalid_argument if N < 2 or most rows are equal
    // (a zero median distance).
    explicit BackConstraint(const Eigen::MatrixXd& Ybar, int maxBasis = kMaxBackBasis);

    bool empty() const { return K_.size() == 0; }
    const Eigen::MatrixXd& kernel() const { return K_; }  // N×R
    const std::vector<int>& basisRows() const { return basis_; }
    double lengthScaleSquared() const { return ell2_; }

    // X = K A.
    Eigen::MatrixXd latent(const Eigen::MatrixXd& A) const { return K_ * A; }
    // The A whose K A is nearest to X in least squares (a tiny ridge keeps it unique): the
    // starting point that reproduces the PCA layout as closely as the mapping can.
    Eigen::MatrixXd fit(const Eigen::MatrixXd& X) const;

private:
    Eigen::MatrixXd K_;
    std::vector<int> basis_;
    double ell2_ = 0.0;
};

// Step 6's result (XI = the active rows of K A; gradInf over (ψ, A)) and the weights A.
struct BackStepResult {
    ActiveStepResult step;
    Eigen::MatrixXd A;
};

// The function Step 6 minimises under back-constraints, at z = packParams(ψ, A):
// L_GP(ψ, X_I = K_I A) + L_prior(K A) (prior may be empty), gradient
// ∂/∂A = K_Iᵀ ∂L_GP/∂X_I + Kᵀ ∂L_prior/∂X into g.
double backConstrainedObjective(KernelKind kind, const Eigen::VectorXd& z, const BackConstraint& bc,
                                const std::vector<int>& active, const Eigen::MatrixXd& Yhat, const TemporalPrior& prior,
                                const GpObjectiveOptions& objective, Eigen::VectorXd& g, double* jitter = nullptr,
                                GpWorkspace* workspace = nullptr);

// Step 6 under back-constraints: SCG over (ψ, A) from the given warm start.
BackStepResult optimizeBackConstrainedStep(KernelKind kind, const Eigen::VectorXd& psi, const Eigen::MatrixXd& A,
                                           const BackConstraint& bc, const std::vector<int>& active,
                                           const Eigen::MatrixXd& Yhat, const TemporalPrior& prior,
                                           const ScgOptions& options, const GpObjectiveOptions& objective = {});

}  // namespace mgp::gp
