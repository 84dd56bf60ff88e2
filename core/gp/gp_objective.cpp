#include "gp/gp_objective.h"

#include <cmath>
#include <limits>

#include "util/cholesky_inverse.h"

namespace mgp::gp {

bool jitterCholesky(const Eigen::MatrixXd& K, Eigen::LLT<Eigen::MatrixXd>& llt, double& jitter) {
    jitter = 0.0;
    if (!K.allFinite()) return false;
    llt.compute(K);
    if (llt.info() == Eigen::Success) return true;
    const double base = 1e-5 * std::abs(K.diagonal().mean());
    double eps = base > 0.0 ? base : 1e-10;
    for (int attempt = 0; attempt < 10; ++attempt, eps *= 10.0) {
        Eigen::MatrixXd Kj = K;
        Kj.diagonal().array() += eps;
        llt.compute(Kj);
        if (llt.info() == Eigen::Success) {
            jitter = eps;
            return true;
        }
    }
    return false;
}

GpEvaluation evaluateGp(const Kernel& kernel, const Eigen::MatrixXd& XI, const Eigen::MatrixXd& Yhat,
                        const GpObjectiveOptions& options, bool wantGradient) {
    GpWorkspace workspace;
    return evaluateGp(kernel, XI, Yhat, options, wantGradient, workspace);
}

GpEvaluation evaluateGp(const Kernel& kernel, const Eigen::MatrixXd& XI, const Eigen::MatrixXd& Yhat,
                        const GpObjectiveOptions& options, bool wantGradient, GpWorkspace& ws) {
    GpEvaluation ev;
    const Eigen::Index m = XI.rows(), d = XI.cols(), D = Yhat.cols();
    const double inf = std::numeric_limits<double>::infinity();
    ev.value = inf;
    ev.gradPsi = Eigen::VectorXd::Zero(kernel.paramCount());
    ev.gradX = Eigen::MatrixXd::Zero(m, d);
    if (m == 0 || D == 0 || Yhat.rows() != m || !XI.allFinite()) return ev;

    GramParts& parts = ws.parts;
    Eigen::MatrixXd &K = ws.K, &G = ws.G;
    kernel.parts(XI, parts);
    K.resize(m, m);
    K.noalias() = kernel.alpha() * parts.R;
    if (kernel.hasEta()) K.noalias() += kernel.eta() * parts.E;
    K.diagonal().array() += 1.0 / kernel.beta();
    Eigen::LLT<Eigen::MatrixXd>& llt = ws.llt;
    if (!jitterCholesky(K, llt, ev.jitter)) return ev;
    const Eigen::MatrixXd& L = llt.matrixLLT();
    const double logDet = 2.0 * L.diagonal().array().log().sum();

    const Eigen::MatrixXd P = llt.matrixL().solve(Yhat);  // L⁻¹ Ŷ
    ev.s = P.colwise().squaredNorm().transpose();
    if (!ev.s.allFinite() || (ev.s.array() <= 0.0).any()) return ev;

    const double c = options.jacobianCoef < 0.0 ? static_cast<double>(m) : options.jacobianCoef;
    switch (options.weights) {
        case WeightMode::kProfileGauge: {
            const double g = std::exp(ev.s.array().log().mean());
            ev.w = (g / ev.s.array()).sqrt().matrix();
            break;
        }
        case WeightMode::kProfileFree: ev.w = (c / ev.s.array()).sqrt().matrix(); break;
        case WeightMode::kFixed: ev.w = options.fixedW; break;
    }
    if (ev.w.size() != D || !ev.w.allFinite() || (ev.w.array() <= 0.0).any()) return ev;

    const double sumLogW = options.weights == WeightMode::kProfileGauge ? 0.0 : ev.w.array().log().sum();
    const double dataTerm = 0.5 * (ev.w.array().square() * ev.s.array()).sum();
    double value = 0.5 * static_cast<double>(D) * logDet + dataTerm + 0.5 * XI.squaredNorm() +
                   kernel.logParams().sum() - c * sumLogW;
    ev.gradLogW = (ev.w.array().square() * ev.s.array() - c).matrix();
    if (!std::isfinite(value)) return ev;

    if (wantGradient) {
        // K⁻¹ = L⁻ᵀ L⁻¹, lower triangle, from L in place (util/cholesky_inverse.h); K⁻¹Ŷ = L⁻ᵀ P.
        G = L;
        choleskyInverseInPlace(G, ws.scratch);
        const Eigen::MatrixXd A = llt.matrixU().solve(P) * ev.w.asDiagonal();
        G *= 0.5 * static_cast<double>(D);
        G.selfadjointView<Eigen::Lower>().rankUpdate(A, -0.5);     // G = ½(D K⁻¹ − A Aᵀ), lower half
        G.triangularView<Eigen::StrictlyUpper>() = G.transpose();  // exactly symmetric for gradX
        ev.gradPsi = kernel.gradLogParams(parts, G);
        ev.gradPsi.array() += 1.0;  // each +ln θ prior adds exactly 1
        ev.gradX = kernel.gradX(XI, parts, G, ws.gradX) + XI;
        if (!ev.gradPsi.allFinite() || !ev.gradX.allFinite()) {
            ev.gradPsi.setZero();
            ev.gradX.setZero();
            return ev;
        }
    }
    ev.value = value;
    ev.ok = true;
    return ev;
}

Eigen::VectorXd packParams(const Eigen::VectorXd& psi, const Eigen::MatrixXd& XI) {
    Eigen::VectorXd z(psi.size() + XI.size());
    z.head(psi.size()) = psi;
    z.tail(XI.size()) = Eigen::Map<const Eigen::VectorXd>(XI.data(), XI.size());
    return z;
}

void unpackParams(const Eigen::VectorXd& z, int paramCount, int m, int d, Eigen::VectorXd& psi, Eigen::MatrixXd& XI) {
    psi = z.head(paramCount);
    XI = Eigen::Map<const Eigen::MatrixXd>(z.data() + paramCount, m, d);
}

}  // namespace mgp::gp
