#pragma once
// ModelVersion: one immutable, numbered state of a trained model together with its §6.2
// precomputation (chol K, K⁻¹, K⁻¹Ŷ). Solvers hold a shared_ptr to the version they started
// with; the adaptive update publishes a new version instead of changing this one, so a solve
// never sees a half-updated model.
#include <memory>

#include "gp/model.h"
#include "gp/point_objective.h"
#include "gp/training_range.h"

namespace mgp::gp {

struct ModelVersion {
    int number = 0;  // 0 = as trained or loaded; +1 per accepted adaptive update
    std::shared_ptr<const GpModel> model;
    std::shared_ptr<const ActiveSetPosterior> posterior;
    // σ² and L_IK percentiles over the training rows (what an admissible edited pose must meet).
    TrainingRange range;

    // Builds the precomputation; throws std::runtime_error if K cannot be factored.
    static std::shared_ptr<const ModelVersion> make(GpModel model, int number = 0);
};

using ModelVersionPtr = std::shared_ptr<const ModelVersion>;

}  // namespace mgp::gp
