#pragma once
// Held effectors: what the animator placed stays placed (docs/architecture.md §6, "Held effectors").
// An effector the animator put somewhere on a frame (a drag's handle, a path's effector; the
// frame's EditRecord::moved) is held there by every later gesture: a drag on that frame holds it
// where it is, and a later falloff, spread or path regeneration holds it on each frame that has
// it, where the motion as edited so far has it. It stays held until the animator releases it (or
// drags it again, which places it anew), or until an edit replaces the frame's record without it:
// a latent drag, reverting the frame. These functions read and change that record;
// EditorDocument owns the steps.
#include <vector>

#include "edit/clip_edits.h"
#include "motion/motion_quality.h"

namespace mgp {

// Whether `e` is held on `frame` (an edit there placed it and it was not released).
bool isHeld(const ClipEdits& edits, int frame, Effector e);
// Whether any frame holds anything.
bool anyHeld(const ClipEdits& edits);
// The effectors held on `frame`, in effector order (none on a captured frame).
std::vector<Effector> heldOn(const ClipEdits& edits, int frame);
// The runs of frames within first..last on which an effector other than `except` is held, one
// interval per effector and run (the form MotionEditJob::heldPlaced takes); Effector::kCount
// excepts none.
std::vector<ContactInterval> heldRuns(const ClipEdits& edits, int first, int last, Effector except);
// `a` with the effectors of `b` it lacks, in effector order (what a new gesture's record holds:
// the frame's earlier placements and the new one).
std::vector<Effector> withHeld(std::vector<Effector> a, const std::vector<Effector>& b);
// The change that releases `e` on `frame` and on the neighbouring frames that hold it without a
// gap (the run one gesture placed it over): each such record without `e`. Empty if `e` is not held
// on `frame`.
FrameEdits releaseRun(const ClipEdits& edits, int frame, Effector e);
// The change that releases every held effector on every frame. Empty if nothing is held.
FrameEdits releaseEverywhere(const ClipEdits& edits);

}  // namespace mgp
