#pragma once
// Locality: how much each DOF's change costs when a gesture moves some effectors, so that a hand
// drag bends the arm first and the spine and legs only as much as the target needs. The
// constrained IK adds ½ ℓ Σ_k w_k (y_k − y_ref,k)² and the span solver ℓ Σ_k w_k u_k²
// (docs/maths-ik.md §1, docs/maths-regeneration.md "Objective").
#include <vector>

#include "skeleton/skeleton.h"

namespace mgp {

// The default ℓ per degree² of each solver (ConstrainedIkRequest::locality, SpanWeights::locality),
// chosen on sweeps of 5–40 cm hand raises on a kick and a walk (docs/maths-ik.md §1): the largest
// value at which the IK still converges on ≥ 95 % of `bench --only ik`'s cold starts (300 left
// 87 %), and for the span the smallest that keeps the head, the other hand and the feet within
// 0.15 × the raise on both clips.
constexpr double kDefaultLocality = 100.0;
constexpr double kDefaultSpanLocality = 300.0;

// Locality weight w ∈ [0, 1] of every pose-vector DOF (PoseLayout order) for targets on
// `effectors`: 0 on a target's limb (its end joint and kLocalityFreeHops joints above it: a hand's
// wrist, forearm and upper arm; a foot's ankle, shin and thigh; the head and neck), rising
// linearly to 1 over the next kLocalityRampHops joints (a clavicle ½, the thorax 1), 1 elsewhere
// (the spine, the legs, the other limbs, the root's rotation). With no effectors every weight is 1.
constexpr int kLocalityFreeHops = 2;
constexpr int kLocalityRampHops = 2;
std::vector<double> localityWeights(const Skeleton& skeleton, const std::vector<Effector>& effectors);
// The same weights as plain IK's step metric (PlainIkJob::dofCost): m_k = 1 + cost·w_k, so a DOF of
// weight 1 costs 1 + cost times a targeted limb's (docs/maths-ik.md §8).
std::vector<double> localityDofCost(const Skeleton& skeleton, const std::vector<Effector>& effectors, double cost);

}  // namespace mgp
