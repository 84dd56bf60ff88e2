#include "gp/train/pca_init.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>

namespace mgp::gp {

int latentDimensionFor(int poseDim) { return poseDim < 60 ? 2 : 3; }

PcaInit whitenedPca(const Eigen::MatrixXd& Ybar, int d) {
    const Eigen::Index n = Ybar.rows(), D = Ybar.cols();
    if (d < 1 || d > D || n < 2) throw std::invalid_argument("whitenedPca: need 1 ≤ d ≤ D and N ≥ 2");
    const Eigen::MatrixXd C = (Ybar.transpose() * Ybar) / static_cast<double>(n);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(C);
    if (es.info() != Eigen::Success) throw std::invalid_argument("whitenedPca: eigen-decomposition failed");
    PcaInit out;
    out.eigenvalues.resize(d);
    out.components.resize(D, d);
    for (int j = 0; j < d; ++j) {
        const Eigen::Index src = D - 1 - j;  // eigenvalues ascend
        const double lambda = es.eigenvalues()[src];
        if (!(lambda > 0.0)) throw std::invalid_argument("whitenedPca: data has fewer than d directions of variance");
        Eigen::VectorXd u = es.eigenvectors().col(src);
        Eigen::Index big = 0;
        for (Eigen::Index k = 1; k < D; ++k)
            if (std::abs(u[k]) > std::abs(u[big])) big = k;
        if (u[big] < 0.0) u = -u;
        out.eigenvalues[j] = lambda;
        out.components.col(j) = u;
    }
    out.X = Ybar * out.components * out.eigenvalues.cwiseSqrt().cwiseInverse().asDiagonal();
    return out;
}

}  // namespace mgp::gp
