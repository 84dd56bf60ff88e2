#pragma once
// The latent point of a given pose on a given model: L_IK(x, y) minimised over x with y fixed, as
// Step 8 fits a training row (docs/maths.md §9.3). An edit keeps the x it was solved at, which
// belongs to the model of that solve; after another model is installed (a retrain, a refinement)
// that x says nothing, and the pose's verdict and teaching need its point on the new model.
#include <Eigen/Core>

#include "gp/model_version.h"

namespace mgp {

// Minimises L_IK(·, yKept) on `version` from the latent point of the primary clip's training row
// nearest `frame` and, when given, from `start` (e.g. the x the pose had on the previous model);
// the fit with the lower L_IK wins. Non-finite when nothing fits.
Eigen::VectorXd refitLatent(const gp::ModelVersion& version, int frame, const Eigen::VectorXd& yKept,
                            const Eigen::VectorXd* start = nullptr);

}  // namespace mgp
