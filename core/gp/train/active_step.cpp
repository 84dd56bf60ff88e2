#include "gp/train/active_step.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mgp::gp {

LatentTerm priorOnActive(const TemporalPrior& prior, const Eigen::MatrixXd& X, const std::vector<int>& active) {
    return [prior, X, active](const Eigen::MatrixXd& XI, Eigen::MatrixXd& grad) {
        Eigen::MatrixXd full = X;
        for (std::size_t i = 0; i < active.size(); ++i) full.row(active[i]) = XI.row(static_cast<Eigen::Index>(i));
        Eigen::MatrixXd g;
        const double v = prior.value(full, &g);
        grad.resize(static_cast<Eigen::Index>(active.size()), X.cols());
        for (std::size_t i = 0; i < active.size(); ++i) grad.row(static_cast<Eigen::Index>(i)) = g.row(active[i]);
        return v;
    };
}

double activeStepObjective(KernelKind kind, const Eigen::VectorXd& z, int m, const Eigen::MatrixXd& Yhat,
                           const GpObjectiveOptions& objective, const LatentTerm& extra, Eigen::VectorXd& g,
                           double* jitter, GpWorkspace* workspace) {
    const int p = paramCount(kind);
    const int d = m > 0 ? static_cast<int>((z.size() - p) / m) : 0;
    Eigen::VectorXd psi;
    Eigen::MatrixXd XI;
    unpackParams(z, p, m, d, psi, XI);
    if (psi.hasNaN()) {  // a failed trial step, as for non-finite X_I (docs/maths.md §4.4)
        g = Eigen::VectorXd::Zero(z.size());
        if (jitter) *jitter = 0.0;
        return std::numeric_limits<double>::infinity();
    }
    GpWorkspace local;
    GpEvaluation ev = evaluateGp(Kernel(kind, psi), XI, Yhat, objective, true, workspace ? *workspace : local);
    if (jitter) *jitter = ev.jitter;
    if (extra && ev.ok) {
        Eigen::MatrixXd gx;
        const double v = extra(XI, gx);
        ev.value += v;
        ev.gradX += gx;
        if (!std::isfinite(ev.value) || !ev.gradX.allFinite()) {
            ev.value = std::numeric_limits<double>::infinity();
            ev.gradPsi.setZero();
            ev.gradX.setZero();
        }
    }
    // Outside the box the kernel clamps ψ_p, so L is flat in ψ_p there: its derivative is 0.
    for (int i = 0; i < p; ++i)
        if (std::abs(psi[i]) > kLogParamBound) ev.gradPsi[i] = 0.0;
    g = packParams(ev.gradPsi, ev.gradX);
    return ev.value;
}

ActiveStepResult optimizeActiveStep(KernelKind kind, const Eigen::VectorXd& psi0, const Eigen::MatrixXd& XI0,
                                    const Eigen::MatrixXd& Yhat, const ScgOptions& options,
                                    const GpObjectiveOptions& objective, const LatentTerm& extra) {
    const int m = static_cast<int>(XI0.rows()), d = static_cast<int>(XI0.cols());
    const int p = paramCount(kind);
    ActiveStepResult out;
    GpWorkspace workspace;  // reused by every evaluation of this step (one thread)
    const ValueAndGradient fg = [&](const Eigen::VectorXd& z, Eigen::VectorXd& g) {
        double jitter = 0.0;
        const double value = activeStepObjective(kind, z, m, Yhat, objective, extra, g, &jitter, &workspace);
        out.trialJitterMax = std::max(out.trialJitterMax, jitter);
        return value;
    };
    const Eigen::VectorXd z0 = packParams(psi0, XI0);
    Eigen::VectorXd g0(z0.size());
    out.before = fg(z0, g0);
    const ScgResult r = scgMinimize(fg, z0, options);
    out.iterations = r.iterations;
    unpackParams(r.x, p, m, d, out.psi, out.XI);
    out.psi = out.psi.cwiseMax(-kLogParamBound).cwiseMin(kLogParamBound);
    GpEvaluation fin = evaluateGp(Kernel(kind, out.psi), out.XI, Yhat, objective, true, workspace);
    if (extra && fin.ok) {
        Eigen::MatrixXd gx;
        fin.value += extra(out.XI, gx);
        fin.gradX += gx;
    }
    out.jitter = fin.jitter;
    out.trialJitterMax = std::max(out.trialJitterMax, fin.jitter);
    out.after = fin.value;
    out.ok = fin.ok && std::isfinite(fin.value);
    if (out.ok) {
        out.w = fin.w;
        out.gradInf =
            std::max(fin.gradPsi.cwiseAbs().maxCoeff(), fin.gradX.size() ? fin.gradX.cwiseAbs().maxCoeff() : 0.0);
    }
    return out;
}

}  // namespace mgp::gp
