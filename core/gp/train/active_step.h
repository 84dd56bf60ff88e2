#pragma once
// Step 6 of the training loop (docs/maths.md §8) as a free function: SCG over (ψ = ln θ, X_I) on
// L_GP with W profiled out under the gauge (docs/maths.md §4.2), from the given warm start. Used
// by the trainer's outer loop and by the adaptive update (docs/maths.md §11).
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "gp/gp_objective.h"
#include "gp/kernel.h"
#include "gp/scg.h"
#include "gp/temporal_prior.h"

namespace mgp::gp {

struct ActiveStepResult {
    Eigen::VectorXd psi;          // clamped to the kernel's box, so it is the value evaluated
    Eigen::MatrixXd XI;           // optimised active latent points
    Eigen::VectorXd w;            // profiled weights at the end (empty if the end was not finite)
    double before = 0.0;          // L_GP at the warm start
    double after = 0.0;           // L_GP at the end
    double gradInf = 0.0;         // ‖∇L_GP‖∞ at the end
    double jitter = 0.0;          // Cholesky jitter at the end point (0 normally)
    double trialJitterMax = 0.0;  // largest jitter of any evaluation, rejected trial steps included
    int iterations = 0;
    bool ok = false;  // the end point evaluated finitely
};

// An extra term on the active latent points (the temporal prior, docs/maths.md §19): returns its
// value at X_I and writes ∂/∂X_I into grad (M×d, sized by the callee).
using LatentTerm = std::function<double(const Eigen::MatrixXd& XI, Eigen::MatrixXd& grad)>;

// The temporal prior as a term on the active rows (Step 6, docs/maths.md §19): L_smooth of X
// with rows `active` replaced by X_I and every other row held as in X; the gradient is the
// rows `active` of ∂L_smooth/∂X. X and active are copied into the term.
LatentTerm priorOnActive(const TemporalPrior& prior, const Eigen::MatrixXd& X, const std::vector<int>& active);

// The function Step 6 minimises, at z = packParams(ψ, X_I) (M = m rows): L_GP (+ extra(X_I)),
// gradient into g. ψ outside the ±kLogParamBound box is clamped by the kernel, so the function is
// flat there and g's ψ entry is 0; a NaN in ψ is a failed step (+∞, zero gradient). jitter (if
// given) receives the Cholesky jitter used. workspace: the caller's scratch (nullptr: a local one).
double activeStepObjective(KernelKind kind, const Eigen::VectorXd& z, int m, const Eigen::MatrixXd& Yhat,
                           const GpObjectiveOptions& objective, const LatentTerm& extra, Eigen::VectorXd& g,
                           double* jitter = nullptr, GpWorkspace* workspace = nullptr);

// With `extra` set, the minimised function is L_GP + extra(X_I) (before/after include it).
ActiveStepResult optimizeActiveStep(KernelKind kind, const Eigen::VectorXd& psi, const Eigen::MatrixXd& XI,
                                    const Eigen::MatrixXd& Yhat, const ScgOptions& options,
                                    const GpObjectiveOptions& objective = {}, const LatentTerm& extra = nullptr);

}  // namespace mgp::gp
