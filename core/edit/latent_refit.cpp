#include "edit/latent_refit.h"

#include <cmath>
#include <cstdlib>
#include <limits>

#include "gp/point_objective.h"
#include "gp/scg.h"

namespace mgp {
namespace {

// The training row of the primary clip's `frame`, or the nearest frame's row (0 when the primary
// clip has no rows, which prepareTrainingClips never produces).
int rowNearestFrame(const gp::GpModel& model, int frame) {
    int best = 0, bestGap = -1;
    for (int r = 0; r < static_cast<int>(model.trainingFrames.size()); ++r) {
        if (model.rowClip(r) != 0) continue;
        const int gap = std::abs(model.trainingFrames[static_cast<std::size_t>(r)] - frame);
        if (bestGap < 0 || gap < bestGap) {
            best = r;
            bestGap = gap;
        }
    }
    return best;
}

}  // namespace

Eigen::VectorXd refitLatent(const gp::ModelVersion& version, int frame, const Eigen::VectorXd& yKept,
                            const Eigen::VectorXd* start) {
    const gp::GpModel& model = *version.model;
    const gp::ActiveSetPosterior& posterior = *version.posterior;
    const int d = posterior.latentDim();
    Eigen::VectorXd none = Eigen::VectorXd::Constant(d, std::numeric_limits<double>::quiet_NaN());
    if (yKept.size() != posterior.poseDim() || !yKept.allFinite() || model.X.rows() == 0) return none;
    const Eigen::MatrixXd y = yKept.transpose();
    gp::ScgOptions options;
    options.maxIterations = model.settings.pointIterations;
    Eigen::VectorXd best = none;
    double bestLik = std::numeric_limits<double>::infinity();
    auto fitFrom = [&](const Eigen::VectorXd& x0) {
        if (x0.size() != d || !x0.allFinite()) return;
        Eigen::MatrixXd x = x0.transpose();
        gp::optimizeInactivePoints(posterior, y, {0}, x, options, 1);
        const Eigen::VectorXd fitted = x.row(0).transpose();
        const double lik = posterior.evaluate(fitted, yKept, nullptr, nullptr);
        if (fitted.allFinite() && std::isfinite(lik) && lik < bestLik) {
            best = fitted;
            bestLik = lik;
        }
    };
    fitFrom(model.X.row(rowNearestFrame(model, frame)).transpose());
    if (start) fitFrom(*start);
    return best;
}

}  // namespace mgp
