#pragma once
// How far a limb is stretched: the knee's or elbow's straightness (docs/maths-ik.md §3 step 6).
#include <optional>

#include "skeleton/forward_kinematics.h"

namespace mgp {

// For a hand or foot effector: |end − root| / (|middle − root| + |end − middle|) of its limb's two
// long bones (humerus and radius for a hand: shoulder, elbow, wrist; femur and tibia for a foot:
// hip, knee, ankle), found by ASF bone role. 1 means the elbow or knee is straight, which is
// where the limb's Jacobian loses rank and the effector cannot move further out to first order.
// Empty for the head, and for a skeleton without those bone roles.
std::optional<double> limbExtension(const Skeleton& skeleton, const FkState& fk, Effector e);

}  // namespace mgp
