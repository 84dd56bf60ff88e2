#include "gp/train/ivm.h"

#include <algorithm>
#include <cmath>

#include "util/parallel_for.h"

namespace mgp::gp {

namespace {

// Rows per chunk of a round's work. The chunks are fixed by N alone and each row's arithmetic
// stays within its chunk, so the selection is the same bits for any number of workers.
constexpr Eigen::Index kIvmChunk = 2048;

// The kernel column k_f(X[a:a+len], x_j) (as Kernel::cross), vectorised down the chunk's rows:
// X's columns are contiguous, and phi holds φ(x_n) = x_n / √(‖x_n‖² + ε²) for the angular part.
void kernelColumn(const Kernel& kernel, const Eigen::MatrixXd& X, const Eigen::MatrixXd& phi, Eigen::Index j,
                  Eigen::Index a, Eigen::Index len, Eigen::Ref<Eigen::VectorXd> out, Eigen::ArrayXd& scratch) {
    scratch.setZero(len);
    for (Eigen::Index c = 0; c < X.cols(); ++c) scratch += (X.col(c).segment(a, len).array() - X(j, c)).square();
    out = kernel.alpha() * (-0.5 * kernel.gamma() * scratch).exp();
    if (!kernel.hasEta()) return;
    scratch.setZero(len);
    for (Eigen::Index c = 0; c < X.cols(); ++c) scratch += phi.col(c).segment(a, len).array() * phi(j, c);
    out.array() += kernel.eta() * scratch.exp();
}

}  // namespace

IvmResult selectActiveSet(const Kernel& kernel, const Eigen::MatrixXd& X, int m, int threads) {
    IvmResult out;
    const int n = static_cast<int>(X.rows());
    if (m >= n) {
        out.active.resize(n);
        for (int i = 0; i < n; ++i) out.active[i] = i;
        return out;
    }
    Eigen::VectorXd diag = kernel.diagFRows(X);
    const double noise = 1.0 / kernel.beta();
    const Eigen::MatrixXd phi = kernel.hasEta() ? Kernel::directions(X) : Eigen::MatrixXd();
    // Column r = v of the r-th selected point: a round reads the first r columns down every row,
    // contiguously, and writes column r.
    Eigen::MatrixXd V(n, m);
    std::vector<char> taken(n, 0);
    out.active.reserve(m);
    const Eigen::Index chunks = (n + kIvmChunk - 1) / kIvmChunk;
    const int workers = static_cast<int>(std::clamp<Eigen::Index>(threads, 1, chunks));
    Eigen::VectorXd vj;
    for (int r = 0; r < m; ++r) {
        int j = -1;
        for (int i = 0; i < n; ++i)
            if (!taken[i] && (j < 0 || diag[i] > diag[j])) j = i;
        vj = V.row(j).head(r).transpose();
        const double piv = std::sqrt(diag[j] + noise);
        // c = k_f(X, x_j) − V[:, 0:r] v_j, then V[:, r] = c / piv and the variances lose V[:, r]².
        parallelFor(workers, [&](int w) {
            Eigen::ArrayXd scratch;
            for (Eigen::Index chunk = w; chunk < chunks; chunk += workers) {
                const Eigen::Index a = chunk * kIvmChunk, len = std::min<Eigen::Index>(kIvmChunk, n - a);
                auto c = V.col(r).segment(a, len);
                kernelColumn(kernel, X, phi, j, a, len, c, scratch);
                if (r > 0) c.noalias() -= V.block(a, 0, len, r) * vj;
                c /= piv;
                diag.segment(a, len) = (diag.segment(a, len).array() - c.array().square()).max(0.0);
            }
        });
        taken[j] = 1;
        out.active.push_back(j);
    }
    out.variances = diag;
    return out;
}

}  // namespace mgp::gp
