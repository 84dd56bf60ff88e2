#pragma once
// A handle drag spread over time: a drag that moves effector e to `targetCm` on frame t changes
// frames t−r..t+r, with a displacement that falls off smoothly to zero at both ends. It is a span
// regeneration (motion/motion_edit.h, kSpan) with keys t−r, t, t+r in displacement mode: the
// captured effector path plus d(s), d = 0 with zero slope at t ± r and d(t) = target − p_e(t),
// re-solved with the planted feet and pins held. r = 0 is the single-frame drag (no job).
// The keys are clamped to the clip, keeping one captured frame before and after the span so the
// joins stay C¹; a frame with no room on one side gets a one-sided falloff.
#include <string>

#include "motion/motion_edit.h"

namespace mgp {

// Default radius: a quarter second (30 frames at 120 fps).
int defaultFalloffRadius(double fps);

// The job for a drag at `frame` (0-based) to `targetCm`; "" in *problem when it can run, else why
// not (radius < 1, frame at the clip's first or last frame, a bad target).
MotionEditJob dragFalloffJob(gp::ModelVersionPtr version, Effector effector, int frame, const Eigen::Vector3d& targetCm,
                             int radius, std::vector<Effector> pins, std::string* problem);

}  // namespace mgp
