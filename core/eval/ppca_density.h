#pragma once
// Probabilistic PCA density (Tipping & Bishop), the model-independent density of the editing
// range protocol (docs/maths.md §14 test 4): a Gaussian N(μ, U_q Λ_q U_qᵀ + σ²(I − U_q U_qᵀ))
// with σ² the mean of the discarded eigenvalues. A different family from the GPLVM on purpose.
#include <Eigen/Core>

namespace mgp {

class PpcaDensity {
public:
    // rows = samples. q is clamped to [1, D − 1]. A variance floor keeps σ² > 0 for rank-deficient data.
    PpcaDensity(const Eigen::MatrixXd& samples, int q, double varianceFloor = 1e-6);
    double logDensity(const Eigen::VectorXd& y) const;
    int components() const { return static_cast<int>(U_.cols()); }

private:
    Eigen::VectorXd mu_;
    Eigen::MatrixXd U_;       // D×q principal directions
    Eigen::VectorXd lambda_;  // q eigenvalues
    double sigma2_ = 1.0;
    double logNorm_ = 0.0;  // −½ ln|C| − (D/2) ln 2π
};

// The 1st-percentile (or `quantile`) held-out log density: k contiguous folds, each scored by a
// PPCA fitted on the others.
double heldOutLogDensityQuantile(const Eigen::MatrixXd& samples, int q, int folds, double quantile);

}  // namespace mgp
