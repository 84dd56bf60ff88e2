#pragma once
// ModelVersion: one immutable, numbered state of a trained model together with its
// precomputation (chol K, K⁻¹, K⁻¹Ŷ; docs/maths.md §9.1). Solvers hold a shared_ptr to the
// version they started with; the adaptive update publishes a new version instead of changing this
// one, so a solve never sees a half-updated model.
#include <memory>

#include "gp/capture_range.h"
#include "gp/model.h"
#include "gp/point_objective.h"
#include "gp/training_range.h"

namespace mgp::gp {

struct ModelVersion {
    int number = 0;  // 0 = as trained or loaded; +1 per accepted adaptive update
    std::shared_ptr<const GpModel> model;
    std::shared_ptr<const ActiveSetPosterior> posterior;
    // σ² and L_IK held-out percentiles over the training rows (what the model's score of a pose
    // means; shown with every admission verdict).
    TrainingRange range;
    // What the source clips' captured frames span (gp/capture_range.h): the admission's reference.
    std::shared_ptr<const CaptureRange> capture;

    // Builds the precomputation; throws std::runtime_error if K cannot be factored. `update`: the
    // version this one updates (an adaptive update of the same clips), whose range and capture
    // reference it keeps, so that teaching a pose never moves the limits the next pose is judged by.
    static std::shared_ptr<const ModelVersion> make(GpModel model, int number = 0,
                                                    const ModelVersion* update = nullptr);
};

using ModelVersionPtr = std::shared_ptr<const ModelVersion>;

}  // namespace mgp::gp
