#include "gp/train/ivm.h"

#include <cmath>

namespace mgp::gp {

IvmResult selectActiveSet(const Kernel& kernel, const Eigen::MatrixXd& X, int m) {
    IvmResult out;
    const int n = static_cast<int>(X.rows());
    if (m >= n) {
        out.active.resize(n);
        for (int i = 0; i < n; ++i) out.active[i] = i;
        return out;
    }
    Eigen::VectorXd diag = kernel.diagFRows(X);
    const double noise = 1.0 / kernel.beta();
    Eigen::MatrixXd V(m, n);  // row r = v of the r-th selected point
    std::vector<char> taken(n, 0);
    out.active.reserve(m);
    for (int r = 0; r < m; ++r) {
        int j = -1;
        for (int i = 0; i < n; ++i)
            if (!taken[i] && (j < 0 || diag[i] > diag[j])) j = i;
        Eigen::VectorXd c = kernel.cross(X, Eigen::VectorXd(X.row(j).transpose()));
        if (r > 0) c.noalias() -= V.topRows(r).transpose() * V.col(j).head(r);
        const double piv = std::sqrt(diag[j] + noise);
        V.row(r) = (c / piv).transpose();
        for (int i = 0; i < n; ++i) diag[i] = std::max(0.0, diag[i] - V(r, i) * V(r, i));
        taken[j] = 1;
        out.active.push_back(j);
    }
    out.variances = diag;
    return out;
}

}  // namespace mgp::gp
