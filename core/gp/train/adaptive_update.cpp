#include "gp/train/adaptive_update.h"

#include <algorithm>
#include <cmath>

#include "gp/train/active_step.h"
#include "gp/train/ivm.h"

namespace mgp::gp {

AdaptiveUpdateResult adaptiveUpdate(const ModelVersion& current, const Eigen::VectorXd& xStar,
                                    const Eigen::VectorXd& yKept, int clipFrame, int scgIterations) {
    AdaptiveUpdateResult out;
    const GpModel& old = *current.model;
    if (xStar.size() != old.latentDim() || yKept.size() != old.D()) {
        out.diagnostic = "expected a sample with " + std::to_string(old.latentDim()) + " latent and " +
                         std::to_string(old.D()) + " pose values, found " + std::to_string(xStar.size()) + " and " +
                         std::to_string(yKept.size());
        return out;
    }
    if (!xStar.allFinite() || !yKept.allFinite()) {
        out.diagnostic = "expected a finite sample, found NaN or Inf (update discarded)";
        return out;
    }
    GpModel m = old;  // the new version; `old` is never touched
    const int n = m.N();
    m.X.conservativeResize(n + 1, Eigen::NoChange);
    m.X.row(n) = xStar.transpose();
    m.Y.conservativeResize(n + 1, Eigen::NoChange);
    m.Y.row(n) = yKept.transpose();
    m.trainingFrames.push_back(clipFrame);
    if (!m.trainingClips.empty()) m.trainingClips.push_back(0);  // a frame of the primary (open) clip

    const Kernel kernel = m.kernel();
    m.active = selectActiveSet(kernel, m.X, m.settings.activeSize).active;
    out.newPointActive = std::find(m.active.begin(), m.active.end(), n) != m.active.end();
    for (int i : m.active)
        if (std::find(old.active.begin(), old.active.end(), i) == old.active.end()) ++out.activeChanged;

    const Eigen::MatrixXd XI = m.activeX();
    const Eigen::MatrixXd Yhat = m.activeYhat();
    ScgOptions options;
    options.maxIterations = scgIterations;
    const ActiveStepResult step = optimizeActiveStep(m.kind, m.logParams, XI, Yhat, options);
    out.scgIterations = step.iterations;
    out.objectiveBefore = step.before;
    out.objectiveAfter = step.after;
    if (!step.ok || !step.psi.allFinite() || !step.XI.allFinite()) {
        out.diagnostic = "expected a finite objective after the update, found a non-finite one (update discarded)";
        return out;
    }
    m.logParams = step.psi;
    for (std::size_t i = 0; i < m.active.size(); ++i) m.X.row(m.active[i]) = step.XI.row(static_cast<Eigen::Index>(i));
    m.w = step.w;
    try {
        out.version = ModelVersion::make(std::move(m), current.number + 1, &current);
    } catch (const std::exception& e) {
        out.diagnostic = std::string("expected a factorable kernel after the update, found: ") + e.what();
        return out;
    }
    out.accepted = true;
    out.diagnostic = "ok";
    return out;
}

}  // namespace mgp::gp
