#pragma once
// The pose vector y (docs/maths.md §2): rotational DOFs in DEGREES, in one fixed order per
// skeleton (files, W, limits). Root translation (cm) is kept separately. Entries 0-2 are always
// the root's rx ry rz. Two kinds (Skeleton::poseVector):
//
// ASF model (ASF/AMC, synthetic): the paper's 47 DOFs, picked by ASF bone role:
//   0-2 root rx ry rz     15-17 lowerback     33-34 lclavicle ry rz   40-41 rclavicle ry rz
//   3-5 lfemur rx ry rz   18-20 upperback     35-37 lhumerus          42-44 rhumerus
//   6 ltibia rx           21-23 thorax        38 lradius rx           45 rradius rx
//   7-8 lfoot rx rz       24-26 lowerneck     39 lwrist ry            46 rwrist ry
//   9-11 rfemur           27-29 upperneck
//   12 rtibia rx          30-32 head
//   13-14 rfoot rx rz
//   The 22 bones are the 20 DOF-bearing non-root bones above plus lhipjoint and rhipjoint.
//
// Channels (BVH): the skeleton's own hierarchy: root rx ry rz, then every other joint's rotation
// channels (x, y, z among those the file animates) in joint order. Channels that never move are
// dropped later, as the ASF vector's are, by the model's constant columns (docs/maths.md §5,
// step 2).
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "skeleton/skeleton.h"

namespace mgp {

constexpr int kAsfPoseDofs = 47;  // rotational DOFs in the ASF model's y
constexpr int kModelBones = 22;   // bones of the simplified skeleton (root not counted)

struct AsfPoseDof {
    const char* bone;
    int axis;
};
const std::array<AsfPoseDof, kAsfPoseDofs>& asfPoseDofTable();
// The 22 bone names of the simplified skeleton (docs/maths.md §2.1), root excluded.
const std::array<const char*, kModelBones>& modelBoneNames();
// Bones of the full ASF skeleton that the model drops (held rigid): hands, fingers, thumbs, toes.
bool isDroppedAsfBone(const std::string& bone);
// The 22 model bones a skeleton lacks (e.g. upperback for a Daz-friendly BVH), in table order.
std::vector<std::string> missingModelBones(const Skeleton& skeleton);

// A joint-angle pose of one skeleton: root translation in cm plus (x, y, z) Euler angles in
// degrees per joint (angles[0] is the root rotation). Axes a joint does not animate stay 0.
struct Pose {
    Eigen::Vector3d rootCm = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> anglesDeg;
};
// Whether the root translation and every angle are finite (a solve that produced NaN is dropped).
bool allFinite(const Pose& pose);
// The same root translation and the same angles, bit for bit (the same pose, not a similar one).
bool posesIdentical(const Pose& a, const Pose& b);

// The pose vector of one skeleton (its kind decides which), bound to its joints.
class PoseLayout {
public:
    explicit PoseLayout(const Skeleton& skeleton);
    int size() const { return static_cast<int>(joint_.size()); }
    int joint(int dof) const { return joint_[dof]; }  // -1 if the skeleton lacks that ASF bone
    int axis(int dof) const { return axis_[dof]; }
    // "lfemur rx" (ASF bone role) or "LeftUpLeg rz" (the BVH joint's name); `skeleton` is the one
    // the layout was made for.
    std::string dofName(const Skeleton& skeleton, int dof) const;

    void extract(const Pose& pose, double* y) const;  // writes size() values
    Eigen::VectorXd extract(const Pose& pose) const;
    void apply(const double* y, Pose& pose) const;  // overwrites the size() mapped angles

private:
    PoseVectorKind kind_ = PoseVectorKind::kAsfModel;
    std::vector<int> joint_, axis_;
};

}  // namespace mgp
