#include "skeleton/forward_kinematics.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Geometry>
#include <limits>

namespace mgp {

void forwardKinematics(const Skeleton& skeleton, const Pose& pose, FkState& fk) {
    const int n = skeleton.jointCount();
    if (static_cast<int>(fk.jointCm.size()) != n) {
        fk.jointCm.resize(n);
        fk.global.resize(n);
        fk.parentFrame.resize(n);
    }
    for (int j = 0; j < n; ++j) {
        const Joint& joint = skeleton.joints[j];
        const Eigen::Matrix3d local = eulerMatrix(pose.anglesDeg[j], joint.order);
        if (joint.parent < 0) {
            fk.jointCm[j] = pose.rootCm + joint.offsetCm;
            fk.parentFrame[j] = joint.axis;
        } else {
            const int p = joint.parent;
            fk.jointCm[j] = fk.jointCm[p] + fk.global[p] * joint.offsetCm;
            fk.parentFrame[j] = fk.global[p] * joint.axis;
        }
        fk.global[j] = fk.parentFrame[j] * local * joint.axis.transpose();
    }
}

double headingRadians(const FkState& fk) {
    const Eigen::Vector3d forward = fk.global[0].col(2);
    return std::atan2(forward.x(), forward.z());
}

Eigen::Matrix3d headingRemoval(const FkState& fk) { return axisRotation(kAxisY, -headingRadians(fk)); }

Eigen::Vector3d boneEndCm(const Skeleton& skeleton, const FkState& fk, int joint) {
    return fk.jointCm[joint] + fk.global[joint] * skeleton.joints[joint].tailCm;
}

Eigen::Vector3d effectorCm(const Skeleton& skeleton, const FkState& fk, Effector e) {
    const EffectorSite& site = skeleton.effectorSite(e);
    if (site.joint < 0) return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    return fk.jointCm[site.joint] + fk.global[site.joint] * site.localCm;
}

Eigen::Vector3d effectorCm(const Skeleton& skeleton, const Pose& pose, Effector e) {
    FkState fk;
    forwardKinematics(skeleton, pose, fk);
    return effectorCm(skeleton, fk, e);
}

Eigen::Vector3d dofWorldAxis(const Skeleton& skeleton, const FkState& fk, const Pose& pose, int joint, int axis) {
    // With R = R_o0 · R_o1 · R_o2, the DOF o_k rotates about (base · R_o0 ⋯ R_o(k-1)) e_{o_k}.
    const RotationOrder& order = skeleton.joints[joint].order;
    Eigen::Matrix3d frame = fk.parentFrame[joint];
    for (int a : order) {
        if (a == axis) return frame.col(a);
        const double angle = pose.anglesDeg[joint][a];
        if (angle != 0.0) frame = frame * axisRotation(a, angle * kDegToRad);
    }
    return frame.col(axis);  // unreachable for a valid order
}

void effectorJacobian(const Skeleton& skeleton, const PoseLayout& layout, const FkState& fk, const Pose& pose,
                      Effector e, Eigen::Ref<Eigen::Matrix<double, 3, Eigen::Dynamic>> jac) {
    const EffectorSite& site = skeleton.effectorSite(e);
    if (site.joint < 0) {
        jac.setZero();
        return;
    }
    pointJacobian(skeleton, layout, fk, pose, site.joint, effectorCm(skeleton, fk, e), jac);
}

void pointJacobian(const Skeleton& skeleton, const PoseLayout& layout, const FkState& fk, const Pose& pose,
                   int pointJoint, const Eigen::Vector3d& pe,
                   Eigen::Ref<Eigen::Matrix<double, 3, Eigen::Dynamic>> jac) {
    jac.setZero();
    for (int i = 0; i < layout.size(); ++i) {
        const int j = layout.joint(i);
        if (j < 0 || !skeleton.isAncestorOrSelf(j, pointJoint)) continue;
        const Eigen::Vector3d w = dofWorldAxis(skeleton, fk, pose, j, layout.axis(i));
        jac.col(i) = kDegToRad * w.cross(pe - fk.jointCm[j]);
    }
}

void effectorHessianContracted(const Skeleton& skeleton, const PoseLayout& layout, const FkState& fk, const Pose& pose,
                               Effector e, const Eigen::Vector3d& lambda, Eigen::Ref<Eigen::MatrixXd> out) {
    out.setZero();
    const EffectorSite& site = skeleton.effectorSite(e);
    if (site.joint < 0) return;
    addPointHessianContracted(skeleton, layout, fk, pose, site.joint, effectorCm(skeleton, fk, e), lambda, out);
}

void addPointHessianContracted(const Skeleton& skeleton, const PoseLayout& layout, const FkState& fk, const Pose& pose,
                               int pointJoint, const Eigen::Vector3d& pe, const Eigen::Vector3d& lambda,
                               Eigen::Ref<Eigen::MatrixXd> out) {
    // The chain's DOFs: index, joint, position in the joint's rotation order (outermost first),
    // world axis ω and ω × (p − q).
    // Per-thread scratch sized to the largest pose vector seen: a solve's calls allocate nothing.
    struct ChainScratch {
        std::vector<int> dof, joint, rank, depth;
        std::vector<Eigen::Vector3d> w, v;
    };
    thread_local ChainScratch scratch;
    const std::size_t P = static_cast<std::size_t>(layout.size());
    if (scratch.dof.size() < P) {
        for (std::vector<int>* a : {&scratch.dof, &scratch.joint, &scratch.rank, &scratch.depth}) a->resize(P);
        scratch.w.resize(P);
        scratch.v.resize(P);
    }
    std::vector<int>& dof = scratch.dof;
    std::vector<int>& joint = scratch.joint;
    std::vector<int>& rank = scratch.rank;
    std::vector<int>& depth = scratch.depth;
    std::vector<Eigen::Vector3d>& w = scratch.w;
    std::vector<Eigen::Vector3d>& v = scratch.v;
    int n = 0;
    for (int i = 0; i < layout.size(); ++i) {
        const int j = layout.joint(i);
        if (j < 0 || !skeleton.isAncestorOrSelf(j, pointJoint)) continue;
        const RotationOrder& order = skeleton.joints[j].order;
        dof[n] = i;
        joint[n] = j;
        rank[n] = static_cast<int>(std::find(order.begin(), order.end(), layout.axis(i)) - order.begin());
        depth[n] = 0;
        for (int up = skeleton.joints[j].parent; up >= 0; up = skeleton.joints[up].parent) ++depth[n];
        w[n] = dofWorldAxis(skeleton, fk, pose, j, layout.axis(i));
        v[n] = w[n].cross(pe - fk.jointCm[j]);
        ++n;
    }
    const double k2 = kDegToRad * kDegToRad;
    for (int a = 0; a < n; ++a) {
        for (int b = a; b < n; ++b) {
            // Which of the two is upstream: the ancestor joint, or the outer axis of one joint.
            bool aUp;
            if (joint[a] == joint[b])
                aUp = rank[a] <= rank[b];
            else
                aUp = depth[a] < depth[b];  // both lie on the root-to-effector path
            const int up = aUp ? a : b, down = aUp ? b : a;
            const double h = k2 * lambda.dot(w[up].cross(v[down]));
            out(dof[a], dof[b]) += h;
            if (b != a) out(dof[b], dof[a]) += h;
        }
    }
}

}  // namespace mgp
