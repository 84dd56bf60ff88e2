#pragma once
// Whole-body centre of mass of a pose, from segment masses and centre-of-mass positions along each
// segment: de Leva (1996), "Adjustments to Zatsiorsky–Seluyanov's segment inertia parameters",
// J. Biomechanics 29(9), Table 4, male values. Each segment is one bone of the skeleton's ASF
// roles (Joint::bone): its centre of mass lies at `ratio` of the way from the bone's start (the
// joint) to its end (boneEndCm). The trunk's three parts (lower, middle, upper) are the lowerback,
// upperback and thorax bones; the head and neck are the head bone. Segments the skeleton lacks are
// left out and the rest renormalised; without both thighs and a trunk part there is no answer.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"
#include "skeleton/skeleton.h"

namespace mgp {

struct BodySegment {
    const char* bone;     // ASF role of the bone
    double massFraction;  // of the whole body
    double comRatio;      // centre of mass along the bone, from its start
};

// The table (de Leva 1996, male): fractions sum to 1.
const BodySegment* bodySegments(int* count);

// The table's segments one skeleton has, resolved once (which joint plays each bone), so that a
// solver evaluating the centre of mass many times neither searches the joints' names nor allocates
// each time. empty() without both thighs and a trunk part: then there is no centre of mass.
class BodyMass {
public:
    struct Segment {
        int joint;        // the last joint playing the segment's bone
        double fraction;  // of the whole body (the table's)
        double ratio;     // centre of mass along the bone, from its start
        double weight;    // fraction over the present segments' total
    };
    BodyMass() = default;
    explicit BodyMass(const Skeleton& skeleton);
    bool empty() const { return segments_.empty(); }
    const std::vector<Segment>& segments() const { return segments_; }

private:
    std::vector<Segment> segments_;
};

// Centre of mass (world, cm) of the pose whose FK is `fk`, or none (see above).
std::optional<Eigen::Vector3d> centreOfMass(const Skeleton& skeleton, const BodyMass& body, const FkState& fk);
std::optional<Eigen::Vector3d> centreOfMass(const Skeleton& skeleton, const FkState& fk);
std::optional<Eigen::Vector3d> centreOfMass(const Skeleton& skeleton, const Pose& pose);

// ∂(centre of mass)/∂y for the P pose-vector DOFs (3×P, cm/deg) of the pose whose FK is `fk`; false
// (and `jac` zero) where centreOfMass has no answer. A segment's point p_s moves with every DOF of
// its bone's joint and the joints above it: ∂p_s/∂θ = (π/180) ω × (p_s − q), ω the DOF's world axis
// and q its joint, as for an effector (forward_kinematics.h).
bool centreOfMassJacobian(const Skeleton& skeleton, const BodyMass& body, const PoseLayout& layout, const FkState& fk,
                          const Pose& pose, Eigen::Ref<Eigen::Matrix<double, 3, Eigen::Dynamic>> jac);
// λ · ∂²(centre of mass)/∂y² (P×P, cm/deg², symmetric): the second-order term a Newton step on a
// function of the centre of mass needs (the segments' points, as addPointHessianContracted).
void centreOfMassHessianContracted(const Skeleton& skeleton, const BodyMass& body, const PoseLayout& layout,
                                   const FkState& fk, const Pose& pose, const Eigen::Vector3d& lambda,
                                   Eigen::Ref<Eigen::MatrixXd> out);

// Horizontal (XZ) distance between two points (cm), and between the centres of mass of two
// poses, or none.
double horizontalDistanceCm(const Eigen::Vector3d& a, const Eigen::Vector3d& b);
std::optional<double> horizontalComShiftCm(const Skeleton& skeleton, const Pose& a, const Pose& b);

}  // namespace mgp
