#pragma once
// What every IK solver (learned or plain) takes and returns. Units: cm, world Y up; the pose's
// root translation is held fixed (the captured value of the edited frame).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "skeleton/skeleton.h"

namespace mgp {

// A constraint is reached when its residual is at most this (cm).
constexpr double kReachedToleranceCm = 0.5;

// Target strength, from "natural" to "exact" (used by the constrained learned IK; the penalty
// L-BFGS solver and plain IK ignore it):
//   1 (kStrengthExact)  met exactly when reachable with the pins held, else least squares;
//   s in (0, 1)         soft: the paper's penalty with λ = s, i.e. s/(1 − s)·‖FK − c‖² against L_IK,
//                       so the prior may leave the target short (0.999 is the paper's point);
//   small s             "natural": the pose stays near the prior's most likely pose.
// Pins are always hard, whatever their strength.
constexpr double kStrengthExact = 1.0;
constexpr double kStrengthPaper = 0.999;

struct IkConstraint {
    Effector effector = Effector::kRFoot;
    Eigen::Vector3d targetCm = Eigen::Vector3d::Zero();
    bool pin = false;  // a pin holds the effector where it is (targetCm = its start position)
    double strength = kStrengthExact;
};

struct IkConstraintResult {
    Effector effector = Effector::kRFoot;
    bool pin = false;
    double residualCm = 0.0;
    bool reached = false;
    double strength = kStrengthExact;
    // The target was below the floor: the effector was held on the floor instead (constrained
    // IK with a floor), so it is not reached.
    bool belowFloor = false;
};

// Whether any result is a target held on the floor instead of below it.
bool anyBelowFloor(const std::vector<IkConstraintResult>& results);
// The effectors a solve put somewhere (its targets, not its pins), in request order.
std::vector<Effector> movedEffectors(const std::vector<IkConstraintResult>& results);

// Checks targets before a solve; returns "" if fine, else what is wrong (NaN target, unknown
// effector on this skeleton, the same effector twice, a strength outside (0, 1]).
std::string validateConstraints(const Skeleton& skeleton, const std::vector<IkConstraint>& constraints);

}  // namespace mgp
