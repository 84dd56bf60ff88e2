#pragma once
// Mirror pose: the left/right mirror image of a pose, using the skeleton's own symmetry
// (docs/maths.md §21).
//
// Symmetry. Left/right bone pairs come from the joints' names: a prefix l/r (ASF lhumerus,
// rhumerus; Daz lShldr, rShldr), L/R or L_/R_ (LHipJoint), Left/Right (CMU BVH LeftUpLeg,
// RightUpLeg), or a suffix _l/_r, _L/_R, .L/.R; failing those, the ASF bone roles the BVH
// conventions gave the joints. Both names must exist. The sagittal plane's normal n (the character's left, in the rest
// frame) is the mean of (left − right) rest joint positions over the pairs, made horizontal (Y is up) and snapped to
// the nearest horizontal coordinate axis when within 10° (capture skeletons are axis-aligned), and S = I − 2nnᵀ
// reflects across it.
//
// Mirroring. With L_j = C_j E_j C_jᵀ a joint's local rotation in the common rest frame (C_j its
// axis frame, E_j its Euler matrix), the mirror gives joint j its partner π(j)'s rotation
// reflected: L'_j = S L_π(j) S, i.e. E'_j = D E_π(j) Dᵀ with D = C_jᵀ S C_π(j), converted back to
// j's own rotation order. Unpaired bones (spine, neck, head) are their own partner. When D is a
// diagonal sign matrix and the orders agree (CMU skeletons), this is exact per-angle sign flips.
//
// Root: the root position and the heading are kept; the body is mirrored about the character's
// own sagittal plane (as Maya and Blender mirror a pose): G'_root = M G_root S, where
// M = H S Hᵀ is the world reflection across the vertical plane through the root containing the
// character's forward direction (H the heading, a rotation about Y). The result's world joint
// positions are then the reflections through that plane of the partners' (exactly, on a
// symmetric skeleton).
//
// A DOF the partner has and the joint lacks (droppedAxes()): the joint's own DOFs are fitted to
// the mirrored rotation by least squares (the closest rotation in the Frobenius norm), so the
// rotation about the missing axis is lost; the pose stays valid.
#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "skeleton/pose_layout.h"
#include "skeleton/skeleton.h"

namespace mgp {

struct DroppedAxis {
    int joint = -1;  // the joint that lacks the DOF
    int axis = 0;    // 0, 1, 2 = x, y, z
};

class PoseMirror {
public:
    // The symmetry of `skeleton`, or nullopt with `error` saying why (no left/right pairs, or a
    // pair whose parents are not partners).
    static std::optional<PoseMirror> make(const Skeleton& skeleton, std::string& error);

    Pose mirror(const Pose& pose) const;

    int partner(int joint) const { return partner_[joint]; }  // itself when unpaired
    int pairCount() const { return pairs_; }
    const Eigen::Vector3d& lateralAxis() const { return lateral_; }  // n, unit, horizontal
    const Eigen::Matrix3d& reflection() const { return S_; }         // S
    const std::vector<DroppedAxis>& droppedAxes() const { return dropped_; }
    // World reflection M across the sagittal plane of a pose with root rotation `rootRotation`
    // (through the root position): x ↦ root + M (x − root).
    Eigen::Matrix3d worldReflection(const Eigen::Matrix3d& rootRotation) const;

private:
    explicit PoseMirror(const Skeleton& skeleton) : skeleton_(skeleton) {}

    Skeleton skeleton_;  // a copy: the mirror outlives no clip it was made from
    std::vector<int> partner_;
    std::vector<Eigen::Matrix3d> conj_;  // D_j = C_jᵀ S C_π(j)
    std::vector<bool> signFlip_;         // D_j is a diagonal sign matrix and the orders agree
    int pairs_ = 0;
    Eigen::Vector3d lateral_ = Eigen::Vector3d::UnitX();
    Eigen::Vector3d forward_ = Eigen::Vector3d::UnitZ();  // horizontal, ⟂ n
    Eigen::Matrix3d S_ = Eigen::Matrix3d::Identity();
    std::vector<DroppedAxis> dropped_;
};

// The closest angles (x, y, z degrees) to rotation `q` in joint order `order` that use only the
// axes `dof` animates (the others are 0): of the two Euler solutions (each angle shifted by 360°
// to lie nearest `reference`), the nearer one; with missing axes, coordinate ascent on tr(qᵀE).
Eigen::Vector3d fitJointAngles(const Eigen::Matrix3d& q, const RotationOrder& order, const std::array<bool, 3>& dof,
                               const Eigen::Vector3d& reference);

}  // namespace mgp
