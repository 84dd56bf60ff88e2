#include "motion/drag_falloff.h"

#include <algorithm>
#include <cmath>

namespace mgp {

int defaultFalloffRadius(double fps) { return std::max(1, static_cast<int>(std::lround(0.25 * fps))); }

MotionEditJob dragFalloffJob(gp::ModelVersionPtr version, Effector effector, int frame, const Pose& dragPose,
                             const Eigen::VectorXd& dragX, int radius, std::vector<Effector> pins, std::string* problem,
                             std::shared_ptr<const EditBase> base) {
    MotionEditJob job;
    job.version = std::move(version);
    job.base = std::move(base);
    job.effector = effector;
    job.mode = PathMode::kDisplacement;
    job.pins = std::move(pins);
    auto fail = [&](const std::string& why) {
        if (problem) *problem = why;
        return job;
    };
    if (!job.version) return fail("expected a model, found none");
    const int n = job.version->model->clip.frameCount();
    if (radius < 1) return fail("expected a falloff radius of at least 1 frame, found " + std::to_string(radius));
    if (frame < 0 || frame > n - 1 || n < 3)
        return fail("expected a frame in 1.." + std::to_string(n) + " of a clip of at least 3 frames, found " +
                    std::to_string(frame + 1));
    const Skeleton& skeleton = job.version->model->clip.skeleton;
    if (static_cast<int>(dragPose.anglesDeg.size()) != skeleton.jointCount())
        return fail("expected a drag pose of the model's skeleton, found one with " +
                    std::to_string(dragPose.anglesDeg.size()) + " joints");
    if (!skeleton.hasEffector(effector))
        return fail(std::string("expected an effector of this skeleton, found ") + effectorName(effector));
    const Eigen::Vector3d targetCm = effectorCm(skeleton, dragPose, effector);
    if (!targetCm.allFinite()) return fail("expected a finite drag pose, found NaN or Inf");
    const int first = std::max(0, frame - radius), last = std::min(n - 1, frame + radius);
    if (job.base)
        if (const std::string invalid = validateEditBase(*job.version->model, *job.base); !invalid.empty())
            return fail(invalid);
    const Eigen::Vector3d captured = job.capturedTrajectory()[frame];
    // On the clip's first or last frame the dragged frame is itself the span's end: the falloff is
    // one-sided, fading from the drag into the motion on the one side the frame has.
    job.keyFrames.clear();
    job.keyOffsetsCm.clear();
    for (const int key : {first, frame, last}) {
        if (!job.keyFrames.empty() && key == job.keyFrames.back()) continue;
        job.keyFrames.push_back(key);
        job.keyOffsetsCm.push_back(key == frame ? Eigen::Vector3d(targetCm - captured) : Eigen::Vector3d::Zero());
    }
    job.heldPose = MotionEditJob::HeldPose{frame, dragPose, dragX};
    if (problem) *problem = job.validate();
    return job;
}

}  // namespace mgp
