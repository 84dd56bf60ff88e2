#pragma once
// Skeleton: a joint tree that represents both ASF bones and BVH joints.
//
// Conventions: world is Y up, right-handed, lengths in CENTIMETRES; angles in DEGREES.
// A joint sits at the START of the bone it rotates (an ASF bone's pivot, a BVH joint):
//   p_j   = p_parent + G_parent · offset_j          (offset in the parent's rest frame)
//   G_j   = G_parent · C_j · E(angles_j) · C_jᵀ     (C_j = the ASF `axis` frame, I for BVH)
//   end_j = p_j + G_j · tail_j                      (the bone's end point)
// The root's position is the clip's root translation and G_root = E(root angles).
// At the rest pose every G is the identity, so offsets and tails are world rest vectors; for an
// ASF bone tail = direction · length and every child's offset = its parent's tail.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "skeleton/rotation.h"

namespace mgp {

// The five end effectors an animator drags (docs/maths.md, conventions).
enum class Effector : int { kLHand = 0, kRHand, kLFoot, kRFoot, kHead, kCount };
constexpr int kEffectorCount = static_cast<int>(Effector::kCount);
const char* effectorName(Effector e);
bool parseEffector(const std::string& name, Effector& out);

struct Joint {
    std::string name;  // as in the source file
    std::string bone;  // the ASF bone name it plays ("" if none): root, lfemur, ...
    int parent = -1;   // -1 only for joint 0, the root
    Eigen::Vector3d offsetCm = Eigen::Vector3d::Zero();
    Eigen::Vector3d tailCm = Eigen::Vector3d::Zero();
    Eigen::Matrix3d axis = Eigen::Matrix3d::Identity();  // C_j
    RotationOrder order = kOrderZYX;
    std::array<bool, 3> dof{false, false, false};  // axes the source file animates (x, y, z)
};

// Which pose vector y a skeleton's clips train with (skeleton/pose_layout.h): the paper's 47 DOFs
// picked by ASF bone role (ASF/AMC and the synthetic clip), or every rotation channel of the
// skeleton's own hierarchy (BVH).
enum class PoseVectorKind { kAsfModel, kChannels };

// Where an effector sits: a point fixed in one joint's frame.
struct EffectorSite {
    int joint = -1;
    Eigen::Vector3d localCm = Eigen::Vector3d::Zero();
};

class Skeleton {
public:
    std::vector<Joint> joints;  // parents precede children; joints[0] is the root
    PoseVectorKind poseVector = PoseVectorKind::kAsfModel;

    int jointCount() const { return static_cast<int>(joints.size()); }
    int findJoint(const std::string& name) const;  // by file name, -1 if absent
    int findBone(const std::string& bone) const;   // by ASF bone role, -1 if absent
    bool isAncestorOrSelf(int ancestor, int joint) const;

    // Resolves the effector sites from the bone roles (call after the joints are final):
    // lhand/rhand = end of lwrist/rwrist (else start of lhand/rhand), lfoot/rfoot = end of
    // lfoot/rfoot (else start of ltoes/rtoes), head = end of head. Returns the effectors that
    // could not be resolved.
    std::vector<Effector> resolveEffectors();
    const EffectorSite& effectorSite(Effector e) const { return sites_[static_cast<int>(e)]; }
    bool hasEffector(Effector e) const { return effectorSite(e).joint >= 0; }

    // Checks the structural invariants (root first, parents before children); throws
    // std::logic_error naming the bad joint.
    void validate() const;

private:
    std::array<EffectorSite, kEffectorCount> sites_{};
};

}  // namespace mgp
