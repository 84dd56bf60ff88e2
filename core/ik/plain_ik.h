#pragma once
// Baseline IK without the learned prior: damped least squares on the pose vector's joint angles
// (skeleton/pose_layout.h; the DOFs the skeleton has), adaptive damping, iterated from the start
// pose until the residual stops falling. Users and tests compare it with the learned IK to see what
// the prior buys. Root translation is fixed unless `freeRootTranslation` (then it is three more
// unknowns, in cm, whose Jacobian columns are the identity: every point of the body moves with
// it); the root rotation is free, as in the learned IK, unless frozen.
#include <optional>
#include <vector>

#include "ik/ik_types.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"

namespace mgp {

// A joint's origin held at a world position (cm), e.g. a planted foot's ankle.
struct JointHold {
    int joint = -1;
    Eigen::Vector3d targetCm = Eigen::Vector3d::Zero();
};

struct PlainIkJob {
    // Inputs.
    const Skeleton* skeleton = nullptr;
    Pose start;
    std::vector<IkConstraint> constraints;
    std::vector<bool> frozenDofs;       // optional, one per pose-vector DOF: true = keep it at its start value
    bool freeRootTranslation = false;   // the root translation (cm) is solved for too
    std::vector<JointHold> jointHolds;  // met like the constraints (not reported in `results`)
    // Optional, one per pose-vector DOF, each > 0: the metric m_k of the step. Each step is the
    // least Σ_k m_k Δy_k² that meets the damped linearised constraints (weighted damped least
    // squares), so a costly DOF moves only as far as the targets need: m = 1 + c·w with the
    // locality weights w of ik/locality.h moves the targeted limbs first (docs/maths-ik.md §8).
    // Empty: every m_k = 1. The root translation's columns (freeRootTranslation) cost 1.
    std::vector<double> dofCost;
    int maxIterations = 500;
    double toleranceCm = 1e-3;    // stop once every residual is below this
    double initialDamping = 1.0;  // λ of (JJᵀ + λ² I), in cm

    // Outputs.
    Pose pose;
    std::vector<IkConstraintResult> results;
    bool reached = false;
    int iterations = 0;
    std::string diagnostic;  // why it stopped

    std::string validate() const;
    void solve();
};

// A hold this close (cm) to its place is kept; a pose that leaves one farther is settled.
constexpr double kSettledHoldCm = 0.01;
// The farthest of `holds` from its place in `pose` (cm); 0 without holds.
double worstHoldMissCm(const Skeleton& skeleton, const Pose& pose, const std::vector<IkConstraint>& holds);
// `pose` with every hold back at its place (each held as a pin) by the least change without the
// prior: damped least squares over the root translation and every DOF except the root rotation
// and `keptJoint`'s (−1: none), so that what the animator set stays as set and the upper body is
// not turned; its minimal-norm steps move only the chains of the holds (docs/maths-ik.md §7).
// With `soleReference`, each held foot's ankle is held too, where that pose has it, so that the
// foot keeps its sole instead of pivoting on the held ball (not when `keptJoint` is that ankle or
// below it: then the sole is what was turned). A settle is kept only if it brings the worst miss
// closer and leaves no hold farther from its place than it was (or than kSettledHoldCm); when the
// soles are what would cost a hold (a sole the legs cannot reach), the holds alone are settled.
// nullopt when every hold (and held ankle) is within kSettledHoldCm already, or no settle is kept. At most
// `maxIterations` steps. `moveRoot` false keeps the root translation too: the legs alone bring
// the holds back (a pose whose holds are met but whose held feet turned about their balls).
// `soleFeet`, when given, limits the kept soles to those held feet (the planted ones: a foot pinned
// in the air takes the orientation the new pose gives it).
std::optional<Pose> settleOnHolds(const Skeleton& skeleton, const Pose& pose, int keptJoint,
                                  const std::vector<IkConstraint>& holds, const Pose* soleReference = nullptr,
                                  int maxIterations = 500, bool moveRoot = true,
                                  const std::vector<Effector>* soleFeet = nullptr);

}  // namespace mgp
