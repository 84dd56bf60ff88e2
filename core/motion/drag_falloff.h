#pragma once
// A handle drag spread over time: a drag that leaves effector e at p* on frame t (the drag's
// accepted pose) changes frames t−r..t+r, with a displacement that falls off smoothly to zero at
// both ends. It is a span regeneration (motion/motion_edit.h, kSpan) with keys t−r, t, t+r in
// displacement mode: the captured effector path plus d(s), d = 0 with zero slope at t ± r and
// d(t) = p* − p_e(t), re-solved with the planted feet and pins held. Frame t itself is held at
// the drag's pose and latent point, bit for bit (what the user saw on release, and what the
// adaptive update was judged on); its neighbours join it smoothly. r = 0 is the single-frame drag
// (no job).
// The keys are clamped to the clip: a frame with less than r frames on one side gets a shorter
// falloff there, and on the clip's first or last frame the dragged frame is the span's end (keys
// t, t+r or t−r, t): the falloff is one-sided.
#include <memory>
#include <string>

#include "motion/motion_edit.h"

namespace mgp {

// Default radius: a quarter second (30 frames at 120 fps).
int defaultFalloffRadius(double fps);

// The job for a drag of `effector` at `frame` (0-based) that ended in `dragPose` with latent point
// `dragX` (empty: the frame's captured latent point); "" in *problem when it can run, else why
// not (radius < 1, a clip of fewer than 3 frames, a pose of another skeleton, NaN).
// `base`: the motion as edited so far (MotionEditJob::base): the displacement fades into it, so
// the neighbours keep what earlier edits put there. Null: the captured clip.
MotionEditJob dragFalloffJob(gp::ModelVersionPtr version, Effector effector, int frame, const Pose& dragPose,
                             const Eigen::VectorXd& dragX, int radius, std::vector<Effector> pins, std::string* problem,
                             std::shared_ptr<const EditBase> base = nullptr);

}  // namespace mgp
