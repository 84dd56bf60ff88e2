#include "edit/latent_refit.h"

#include <cmath>
#include <limits>

#include "gp/point_objective.h"
#include "gp/scg.h"

namespace mgp {

Eigen::VectorXd refitLatent(const gp::ModelVersion& version, int frame, const Eigen::VectorXd& yKept,
                            const Eigen::VectorXd* start) {
    const gp::GpModel& model = *version.model;
    const gp::ActiveSetPosterior& posterior = *version.posterior;
    const int d = posterior.latentDim();
    Eigen::VectorXd none = Eigen::VectorXd::Constant(d, std::numeric_limits<double>::quiet_NaN());
    if (yKept.size() != posterior.poseDim() || !yKept.allFinite() || model.X.rows() == 0) return none;
    gp::ScgOptions options;
    options.maxIterations = model.settings.pointIterations;
    const gp::ValueAndGradient fg = [&](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
        return posterior.evaluate(x, yKept, &g, nullptr);
    };
    Eigen::VectorXd best = none;
    double bestLik = std::numeric_limits<double>::infinity();
    auto fitFrom = [&](const Eigen::VectorXd& x0) {
        if (x0.size() != d || !x0.allFinite()) return;
        const Eigen::VectorXd fitted = gp::scgMinimize(fg, x0, options).x;
        const double lik = posterior.evaluate(fitted, yKept, nullptr, nullptr);
        if (fitted.allFinite() && std::isfinite(lik) && lik < bestLik) {
            best = fitted;
            bestLik = lik;
        }
    };
    fitFrom(model.X.row(model.primaryRowNearest(frame)).transpose());
    if (start) fitFrom(*start);
    return best;
}

}  // namespace mgp
