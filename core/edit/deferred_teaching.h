#pragma once
// Poses the animator accepted while a training run was still refining its model (docs/maths.md
// §23). Each refinement replaces the model, so a pose taught to one of them would
// be lost with it: the document keeps such poses and teaches them to the model the run ends
// with, its latent point on that model found by refitLatent (edit/latent_refit.h).
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "edit/adaptive_worker.h"
#include "eval/admission.h"
#include "gp/model_version.h"
#include "skeleton/pose_layout.h"

namespace mgp {

struct DeferredPose {
    int frame = 0;                // the edited clip frame (0-based)
    Eigen::VectorXd yKept;        // the accepted pose, the model's kept columns
    Pose edited;                  // the frame's pose as accepted (it is taught only if the frame still has it)
    std::vector<Effector> moved;  // what the edit put where the animator asked (eval/admission.h)
    Balance balance;              // judgeBalance of the pose on its frame (model-independent)
};

struct DeferredTeaching {
    AdaptiveSample sample;     // x found on the model, the pose, the frame
    AdmissionVerdict verdict;  // whether the model admits it (as a drag's pose is admitted)
};

// The latest entry per frame, oldest frame first: a frame edited twice is taught its last pose.
std::vector<DeferredPose> latestPerFrame(const std::vector<DeferredPose>& poses);

// The sample to post for `pose` on `version`, with its admission verdict. nullopt when the pose
// does not fit the model (another column count) or the fit is not finite.
std::optional<DeferredTeaching> teachingOnModel(const gp::ModelVersion& version, const DeferredPose& pose);

}  // namespace mgp
