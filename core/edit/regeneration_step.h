#pragma once
// What a finished regeneration (a path edit or a drag's falloff, motion/motion_edit.h) changes
// in the document: the frames it solved as edits, the moved keys' poses for the adaptive update,
// and the one-line summary the status bar shows (docs/architecture.md §2).
#include <string>
#include <vector>

#include "edit/adaptive_worker.h"
#include "edit/clip_edits.h"
#include "edit/edit_history.h"
#include "motion/motion_edit.h"

namespace mgp {

// The solved frames' new edits (pose and latent point).
FrameEdits regeneratedFrames(const MotionEditJob& job);
// A new undo step for a path regeneration: every solved frame, before (from `edits`) and after.
EditStep regenerationStep(const MotionEditJob& job, const ClipEdits& edits);
// Folds a drag's falloff into that drag's own step: frames the step did not touch yet get
// their current edit as `before`, and every solved frame but the held dragged one its new
// `after` (the dragged frame keeps the drag's record).
void mergeFalloff(const MotionEditJob& job, const ClipEdits& edits, EditStep& dragStep);
// As the CLI's `edit --adaptive`: the poses at the moved inner keys (not the in-betweens), for
// the model to learn. Keys whose solve is not finite are left out.
std::vector<AdaptiveSample> movedKeySamples(const MotionEditJob& job);
// "regenerated 12 frames, max residual …" (frame numbers 1-based, as on the timeline).
std::string regenerationSummary(const MotionEditJob& job, bool updateQueued);
std::string falloffSummary(const MotionEditJob& job, int falloffRadius, int spreadRadius, const std::string& stepLabel);

}  // namespace mgp
