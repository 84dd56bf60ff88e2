#pragma once
// A whole-pose change on one frame (paste, mirror, a joint rotation) as an additive animation
// layer with blend in and out, as Maya's animation layers and Blender's NLA strips do it: the
// change Δ of frame t0 is added to frames t0−r..t0+r with weight w(t) below. Δ is the root's
// change of position, each three-axis joint's change of rotation D (applied as D^w before the
// frame's own rotation: a joint turning fast under the layer keeps its speed), and each other
// joint's change of its Euler channels (the short way round), applied as w·Δ; with
//
//   w(t) = (1 − d)²(1 + 2d),   d = |t − t0| / r
//
// (the cubic Hermite blend): 1 at t0, 0 with zero slope at t0 ± r, so the layered motion joins
// the motion around it C¹. The drag falloff then re-solves that span from the layered motion
// under the learned prior with contacts held (EditorDocument::setCurrentPose, docs/maths-regeneration.md).
#include <vector>

#include "skeleton/pose_layout.h"
#include "skeleton/skeleton.h"

namespace mgp {

// w(t) above; 0 outside t0 ± radius; radius < 1 gives 1 at t0 and 0 elsewhere.
double poseLayerWeight(int t, int t0, int radius);

// `from` → `to` is the change on frame t0 (poses of `skeleton`); adds w(t)·Δ to frames[t] for t in
// t0 ± radius. A side
// with fewer frames than `radius` before the clip's end blends over the frames it has (its r is the
// distance to the end), so the layer is 0 on the clip's first and last frame unless t0 is one. Frame t0 becomes `to` up
// to rounding of the angle wrap (callers that need it exact set it). The poses must all be of one skeleton.
void addPoseLayer(const Skeleton& skeleton, std::vector<Pose>& frames, int t0, int radius, const Pose& from,
                  const Pose& to);

// How fast (cm/s) the layer may move a hand or foot on top of the motion under it, at most: an
// animator's blend in and out, not a pop (docs/maths-regeneration.md, "Whole-pose changes").
constexpr double kLayerSpeedCmPerSecond = 90.0;
// The widest layer, in falloff radii (8 quarter seconds: two seconds each side at the default).
constexpr int kLayerWidening = 8;

// The steepest slope (cm per unit weight) of a hand's or foot's path along the blend from + wΔ,
// w from 0 to 1, sampled at sixteenths: an Euler blend can swing a hand out and back, so the end
// points alone do not bound it.
double poseLayerSteepestCm(const Skeleton& skeleton, const Pose& from, const Pose& to);
// Frames a Hermite blend needs to move something `distanceCm` at most kLayerSpeedCmPerSecond on
// top of its motion: ⌈1.5·Δ·fps / v⌉ (the blend's steepest slope is 1.5/n per frame); 0 for none.
int layerBlendFrames(double distanceCm, double fps);
// The layer radius of the change from → to: `radius` (the falloff), widened until the blend adds
// at most kLayerSpeedCmPerSecond to any hand or foot (layerBlendFrames of the steepest slope S), at
// most kLayerWidening·radius. radius < 1 is returned as it is (no spread). A side that the clip's
// end cuts shorter (addPoseLayer) blends faster than that.
int poseLayerRadius(const Skeleton& skeleton, const Pose& from, const Pose& to, int radius, double fps);

// The most a hand or foot gains on one frame step (cm) when the motion `under` is layered with the
// change under[t0] → to at `radius` (addPoseLayer): max over steps and effectors of
// |Δ layered| − |Δ under|, 0 if nothing gains. The blend's own slope is one part of it; the other is
// the motion under the layer, which the layer turns: an arm held differently sweeps its hand faster
// through the same joint motion, so a wide layer over a fast passage can add more than a narrow one.
double poseLayerExcessCm(const Skeleton& skeleton, const std::vector<Pose>& under, int t0, int radius, const Pose& to);
// The layer radius for the change under[t0] → to over the motion `under`, measured on it:
// poseLayerRadius's speed rule, unless its layered motion still adds more than
// kLayerSpeedCmPerSecond / fps cm per frame step to a hand or foot; then, of the radii from
// `radius` up to kLayerWidening·radius in steps of max(1, radius/2) (integer), the one whose layered
// motion gains least (poseLayerExcessCm; another radius replaces the rule's only if it gains at
// least 0.05 cm less, kLayerExcessMarginCm).
int poseLayerRadiusOver(const Skeleton& skeleton, const std::vector<Pose>& under, int t0, const Pose& to, int radius,
                        double fps);

}  // namespace mgp
