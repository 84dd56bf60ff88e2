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

struct IkConstraint {
    Effector effector = Effector::kRFoot;
    Eigen::Vector3d targetCm = Eigen::Vector3d::Zero();
    bool pin = false;  // a pin holds the effector where it is (targetCm = its start position)
};

struct IkConstraintResult {
    Effector effector = Effector::kRFoot;
    bool pin = false;
    double residualCm = 0.0;
    bool reached = false;
};

// Checks targets before a solve; returns "" if fine, else what is wrong (NaN target, unknown
// effector on this skeleton, the same effector twice).
std::string validateConstraints(const Skeleton& skeleton, const std::vector<IkConstraint>& constraints);

}  // namespace mgp
