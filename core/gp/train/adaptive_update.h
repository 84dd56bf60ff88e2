#pragma once
// The adaptive ("dynamic") active set of docs/maths.md §11. After an accepted edit (x*, y*):
//   1. append the pair to the data (N ← N + 1; μ stays the original training mean);
//   2. re-run the IVM selection (docs/maths.md §6) from scratch;
//   3. run Step 6 (SCG over ψ = ln θ and the active latent points on L_GP, W profiled under the
//      gauge) warm-started from the current state for K_adapt = 100 iterations;
//   4. no Step 8: inactive points keep their positions.
// The result is a new immutable ModelVersion; the input version is never modified. A non-finite
// sample or an update whose objective is not finite is rejected (version stays null).
#include <Eigen/Core>
#include <string>

#include "gp/model_version.h"

namespace mgp::gp {

struct AdaptiveUpdateResult {
    ModelVersionPtr version;  // null when rejected
    bool accepted = false;
    std::string diagnostic;  // why it was rejected, or "ok"
    int scgIterations = 0;
    double objectiveBefore = 0.0;  // L_GP on the new active set before Step 6
    double objectiveAfter = 0.0;
    bool newPointActive = false;  // x* entered the active set
    int activeChanged = 0;        // points in the new active set that were not in the old one
};

// yKept: the D kept pose columns of the accepted pose (degrees). clipFrame: the edited frame
// (0-based), recorded as the new row's frame.
AdaptiveUpdateResult adaptiveUpdate(const ModelVersion& current, const Eigen::VectorXd& xStar,
                                    const Eigen::VectorXd& yKept, int clipFrame, int scgIterations = 100);

}  // namespace mgp::gp
