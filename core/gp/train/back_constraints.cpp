#include "gp/train/back_constraints.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mgp::gp {

BackConstraint::BackConstraint(const Eigen::MatrixXd& Ybar, int maxBasis) {
    const int n = static_cast<int>(Ybar.rows());
    if (n < 2)
        throw std::invalid_argument("back-constraints: expected at least 2 training rows, found " + std::to_string(n));
    if (maxBasis < 1) throw std::invalid_argument("back-constraints: expected at least 1 basis row");
    const int stride = (n + maxBasis - 1) / maxBasis;
    for (int i = 0; i < n; i += stride) basis_.push_back(i);
    const int r = static_cast<int>(basis_.size());
    // Squared distances from every row to every basis row.
    Eigen::MatrixXd B(r, Ybar.cols());
    for (int j = 0; j < r; ++j) B.row(j) = Ybar.row(basis_[j]);
    const Eigen::VectorXd yy = Ybar.rowwise().squaredNorm(), bb = B.rowwise().squaredNorm();
    Eigen::MatrixXd d2 = (-2.0 * Ybar * B.transpose()).colwise() + yy;
    d2.rowwise() += bb.transpose();
    d2 = d2.cwiseMax(0.0);
    // ℓ² = kBackLengthScale2 × the median squared distance over pairs of distinct rows: the
    // mapping varies on the scale at which the clip's poses differ (docs/maths.md §22 has the
    // factors measured).
    std::vector<double> pairs;
    pairs.reserve(static_cast<std::size_t>(n) * r);
    for (int j = 0; j < r; ++j)
        for (int i = 0; i < n; ++i)
            if (i != basis_[j]) pairs.push_back(d2(i, j));
    std::nth_element(pairs.begin(), pairs.begin() + static_cast<std::ptrdiff_t>(pairs.size() / 2), pairs.end());
    ell2_ = kBackLengthScale2 * pairs[pairs.size() / 2];
    if (!(ell2_ > 0.0))
        throw std::invalid_argument("back-constraints: expected training poses that differ, found most of them equal");
    K_ = (-0.5 / ell2_ * d2).array().exp().matrix();
}

Eigen::MatrixXd BackConstraint::fit(const Eigen::MatrixXd& X) const {
    Eigen::MatrixXd G = K_.transpose() * K_;
    // Ridge of 10⁻⁸ of the mean diagonal: the basis columns of a smooth kernel are nearly
    // dependent, and the smallest-norm fit is the tamest start for SCG.
    const double ridge = 1e-8 * G.diagonal().mean();
    G.diagonal().array() += ridge;
    return G.ldlt().solve(K_.transpose() * X);
}

double backConstrainedObjective(KernelKind kind, const Eigen::VectorXd& z, const BackConstraint& bc,
                                const std::vector<int>& active, const Eigen::MatrixXd& Yhat, const TemporalPrior& prior,
                                const GpObjectiveOptions& objective, Eigen::VectorXd& g, double* jitter,
                                GpWorkspace* workspace) {
    const int p = paramCount(kind);
    const int r = static_cast<int>(bc.kernel().cols());
    const int d = static_cast<int>((z.size() - p) / r);
    const int m = static_cast<int>(active.size());
    Eigen::VectorXd psi;
    Eigen::MatrixXd A;
    unpackParams(z, p, r, d, psi, A);
    Eigen::MatrixXd KI(m, r);
    for (int i = 0; i < m; ++i) KI.row(i) = bc.kernel().row(active[static_cast<std::size_t>(i)]);
    Eigen::VectorXd gz;
    double value =
        activeStepObjective(kind, packParams(psi, KI * A), m, Yhat, objective, nullptr, gz, jitter, workspace);
    Eigen::VectorXd gpsi;
    Eigen::MatrixXd gXI;
    unpackParams(gz, p, m, d, gpsi, gXI);
    Eigen::MatrixXd gA = KI.transpose() * gXI;
    if (std::isfinite(value) && !prior.empty()) {
        Eigen::MatrixXd gX;
        value += prior.value(bc.latent(A), &gX);
        gA += bc.kernel().transpose() * gX;
    }
    if (!std::isfinite(value) || !gA.allFinite()) {
        g = Eigen::VectorXd::Zero(z.size());
        return std::numeric_limits<double>::infinity();
    }
    g = packParams(gpsi, gA);
    return value;
}

BackStepResult optimizeBackConstrainedStep(KernelKind kind, const Eigen::VectorXd& psi0, const Eigen::MatrixXd& A0,
                                           const BackConstraint& bc, const std::vector<int>& active,
                                           const Eigen::MatrixXd& Yhat, const TemporalPrior& prior,
                                           const ScgOptions& options, const GpObjectiveOptions& objective) {
    const int p = paramCount(kind);
    const int r = static_cast<int>(A0.rows()), d = static_cast<int>(A0.cols());
    BackStepResult result;
    ActiveStepResult& out = result.step;
    GpWorkspace workspace;
    const ValueAndGradient fg = [&](const Eigen::VectorXd& z, Eigen::VectorXd& g) {
        double jitter = 0.0;
        const double value =
            backConstrainedObjective(kind, z, bc, active, Yhat, prior, objective, g, &jitter, &workspace);
        out.trialJitterMax = std::max(out.trialJitterMax, jitter);
        return value;
    };
    const Eigen::VectorXd z0 = packParams(psi0, A0);
    Eigen::VectorXd g(z0.size());
    out.before = fg(z0, g);
    const ScgResult res = scgMinimize(fg, z0, options);
    out.iterations = res.iterations;
    unpackParams(res.x, p, r, d, out.psi, result.A);
    out.psi = out.psi.cwiseMax(-kLogParamBound).cwiseMin(kLogParamBound);
    double jitter = 0.0;
    out.after = backConstrainedObjective(kind, packParams(out.psi, result.A), bc, active, Yhat, prior, objective, g,
                                         &jitter, &workspace);
    out.jitter = jitter;
    out.trialJitterMax = std::max(out.trialJitterMax, jitter);
    const Eigen::MatrixXd X = bc.latent(result.A);
    out.XI.resize(static_cast<Eigen::Index>(active.size()), d);
    for (std::size_t i = 0; i < active.size(); ++i) out.XI.row(static_cast<Eigen::Index>(i)) = X.row(active[i]);
    out.ok = std::isfinite(out.after);
    if (out.ok) {
        out.w = evaluateGp(Kernel(kind, out.psi), out.XI, Yhat, objective, false, workspace).w;
        out.gradInf = g.cwiseAbs().maxCoeff();
    }
    return result;
}

}  // namespace mgp::gp
