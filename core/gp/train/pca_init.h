#pragma once
// Preprocessing and latent initialisation (docs/maths.md §5).
//  - constant-column removal (std ≤ 1e-6°), the removed columns held at their means;
//  - μ = column means, Ȳ = Y − 1μᵀ;
//  - whitened PCA: C = ȲᵀȲ/N, X = Ȳ U_d Λ_d^{-1/2}, so each latent column has mean 0 and
//    population variance 1. Eigenvector signs are fixed deterministically: the entry of largest
//    magnitude (first one on ties) is made positive.
#include <Eigen/Core>
#include <vector>

namespace mgp::gp {

// Latent dimension from the paper's eq. 4: 2 when the pose dimension is below 60, else 3.
int latentDimensionFor(int poseDim);

struct PcaInit {
    Eigen::MatrixXd X;            // N×d whitened latent points
    Eigen::VectorXd eigenvalues;  // the d largest, descending
    Eigen::MatrixXd components;   // D×d, unit columns, sign-fixed
};

// Ybar must be centred. Throws std::invalid_argument if d > D or a used eigenvalue is not > 0.
PcaInit whitenedPca(const Eigen::MatrixXd& Ybar, int d);

}  // namespace mgp::gp
