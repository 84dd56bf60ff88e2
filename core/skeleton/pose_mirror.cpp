#include "skeleton/pose_mirror.h"

#include <cmath>
#include <cstring>
#include <utility>

#include "skeleton/forward_kinematics.h"
#include "skeleton/rotation.h"

namespace mgp {

namespace {

// The left/right name pairs a joint name may carry: (left form, right form) as prefix or suffix.
struct Affix {
    const char* left;
    const char* right;
    bool prefix;
};
constexpr Affix kAffixes[] = {{"Left", "Right", true}, {"left", "right", true}, {"l", "r", true},
                              {"L_", "R_", true},      {"L", "R", true},        {"_l", "_r", false},
                              {"_L", "_R", false},     {".L", ".R", false},     {"Left", "Right", false}};

bool startsWith(const std::string& s, const std::string& p) {
    return s.size() > p.size() && s.compare(0, p.size(), p) == 0;
}
bool endsWith(const std::string& s, const std::string& p) {
    return s.size() > p.size() && s.compare(s.size() - p.size(), p.size(), p) == 0;
}

// The right-side name of a left-side `name` under one affix, "" if it does not carry it.
std::string rightNameOf(const std::string& name, const Affix& a) {
    if (a.prefix) return startsWith(name, a.left) ? a.right + name.substr(std::strlen(a.left)) : "";
    return endsWith(name, a.left) ? name.substr(0, name.size() - std::strlen(a.left)) + a.right : "";
}

// Pairs (left joint, right joint) by `key` (the joint's name or its ASF bone role).
template <class Key>
std::vector<std::pair<int, int>> pairsBy(const Skeleton& sk, Key key) {
    std::vector<std::pair<int, int>> pairs;
    std::vector<bool> used(sk.joints.size(), false);
    for (const Affix& a : kAffixes)
        for (int i = 1; i < sk.jointCount(); ++i) {
            if (used[i]) continue;
            const std::string right = rightNameOf(key(sk.joints[i]), a);
            if (right.empty()) continue;
            for (int k = 1; k < sk.jointCount(); ++k)
                if (k != i && !used[k] && key(sk.joints[k]) == right) {
                    pairs.emplace_back(i, k);
                    used[i] = used[k] = true;
                    break;
                }
        }
    return pairs;
}

Eigen::Vector3d wrapNear(const Eigen::Vector3d& a, const Eigen::Vector3d& ref) {
    return {mgp::wrapNear(a[0], ref[0]), mgp::wrapNear(a[1], ref[1]), mgp::wrapNear(a[2], ref[2])};
}

// Maximises tr(qᵀ E(θ)) over the animated axes one at a time (each step exact), from `start`.
Eigen::Vector3d ascend(const Eigen::Matrix3d& q, const RotationOrder& order, const std::array<bool, 3>& dof,
                       Eigen::Vector3d theta) {
    for (int sweep = 0; sweep < 500; ++sweep) {
        double change = 0.0;
        for (int p = 0; p < 3; ++p) {
            const int a = order[p];
            if (!dof[a]) continue;
            Eigen::Matrix3d outer = Eigen::Matrix3d::Identity(), inner = Eigen::Matrix3d::Identity();
            for (int o = 0; o < p; ++o) outer = outer * axisRotation(order[o], theta[order[o]] * kDegToRad);
            for (int o = p + 1; o < 3; ++o) inner = inner * axisRotation(order[o], theta[order[o]] * kDegToRad);
            // tr(qᵀ A R_a B) = tr(M R_a), M = B qᵀ A; its maximum over θ is at atan2(M_bc − M_cb, M_bb + M_cc).
            const Eigen::Matrix3d m = inner * q.transpose() * outer;
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            const double best = mgp::wrapNear(std::atan2(m(b, c) - m(c, b), m(b, b) + m(c, c)) * kRadToDeg, theta[a]);
            change = std::max(change, std::abs(best - theta[a]));
            theta[a] = best;
        }
        if (change < 1e-12) break;
    }
    return theta;
}

double traceFit(const Eigen::Matrix3d& q, const Eigen::Vector3d& theta, const RotationOrder& order) {
    return (q.transpose() * eulerMatrix(theta, order)).trace();
}

}  // namespace

Eigen::Vector3d fitJointAngles(const Eigen::Matrix3d& q, const RotationOrder& order, const std::array<bool, 3>& dof,
                               const Eigen::Vector3d& reference) {
    const Eigen::Vector3d a = wrapNear(eulerFromMatrix(q, order), reference);
    const Eigen::Vector3d b = wrapNear(eulerAlternative(eulerFromMatrix(q, order), order), reference);
    if (dof[0] && dof[1] && dof[2]) return (a - reference).squaredNorm() <= (b - reference).squaredNorm() ? a : b;
    // Missing axes: start from each solution with them zeroed and keep the better fit.
    Eigen::Vector3d best = Eigen::Vector3d::Zero();
    double bestTrace = -1e300;
    for (Eigen::Vector3d start : {a, b, Eigen::Vector3d(reference)}) {
        for (int k = 0; k < 3; ++k)
            if (!dof[k]) start[k] = 0.0;
        const Eigen::Vector3d t = ascend(q, order, dof, start);
        const double tr = traceFit(q, t, order);
        if (tr > bestTrace + 1e-12) {
            bestTrace = tr;
            best = t;
        }
    }
    return best;
}

std::optional<PoseMirror> PoseMirror::make(const Skeleton& skeleton, std::string& error) {
    PoseMirror m(skeleton);
    const int n = skeleton.jointCount();
    std::vector<std::pair<int, int>> pairs = pairsBy(skeleton, [](const Joint& j) { return j.name; });
    if (pairs.empty()) pairs = pairsBy(skeleton, [](const Joint& j) { return j.bone; });
    if (pairs.empty()) {
        error =
            "mirror pose: expected left/right bone pairs (lfemur/rfemur, LeftUpLeg/RightUpLeg, ...), found none "
            "among the skeleton's " +
            std::to_string(n) + " joints: it has no symmetry to mirror with";
        return std::nullopt;
    }
    m.partner_.resize(n);
    for (int j = 0; j < n; ++j) m.partner_[j] = j;
    for (const auto& [l, r] : pairs) {
        m.partner_[l] = r;
        m.partner_[r] = l;
    }
    m.pairs_ = static_cast<int>(pairs.size());
    for (int j = 1; j < n; ++j) {
        const int p = skeleton.joints[j].parent, q = skeleton.joints[m.partner_[j]].parent;
        if (m.partner_[p] != q) {
            error = "mirror pose: expected the partners " + skeleton.joints[j].name + " and " +
                    skeleton.joints[m.partner_[j]].name + " to hang from mirror bones, found " +
                    skeleton.joints[p].name + " and " + skeleton.joints[q].name;
            return std::nullopt;
        }
    }
    // The sagittal plane's normal: left minus right rest positions (every G is I at rest).
    Pose rest;
    rest.anglesDeg.assign(n, Eigen::Vector3d::Zero());
    FkState fk;
    forwardKinematics(skeleton, rest, fk);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& [l, r] : pairs)
        sum += (fk.jointCm[l] - fk.jointCm[r]) + (boneEndCm(skeleton, fk, l) - boneEndCm(skeleton, fk, r));
    sum.y() = 0.0;
    if (sum.norm() < 1e-9) {
        error =
            "mirror pose: expected the left bones to lie beside the right ones, found them on top of each other "
            "(no horizontal left-right direction)";
        return std::nullopt;
    }
    m.lateral_ = sum.normalized();
    // Capture skeletons are built axis-aligned but their bones are not quite symmetric (CMU 35:
    // 0.6° off x). Snap to the nearest horizontal coordinate axis within 10°: a tilted plane would
    // make one-DOF joints (knees, elbows) unable to take their partner's mirrored rotation.
    for (const Eigen::Vector3d axis : {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ()})
        if (std::abs(m.lateral_.dot(axis)) >= std::cos(10.0 * kDegToRad))
            m.lateral_ = m.lateral_.dot(axis) > 0 ? axis : Eigen::Vector3d(-axis);
    m.forward_ = m.lateral_.cross(Eigen::Vector3d::UnitY()).normalized();
    m.S_ = Eigen::Matrix3d::Identity() - 2.0 * m.lateral_ * m.lateral_.transpose();
    m.conj_.resize(n);
    m.signFlip_.assign(n, false);
    for (int j = 1; j < n; ++j) {
        const Joint& jj = skeleton.joints[j];
        const Joint& pj = skeleton.joints[m.partner_[j]];
        m.conj_[j] = jj.axis.transpose() * m.S_ * pj.axis;
        const Eigen::Matrix3d& d = m.conj_[j];
        const bool diagonal = (d - Eigen::Matrix3d(d.diagonal().asDiagonal())).cwiseAbs().maxCoeff() < 1e-9 &&
                              (d.diagonal().cwiseAbs() - Eigen::Vector3d::Ones()).cwiseAbs().maxCoeff() < 1e-9;
        m.signFlip_[j] = diagonal && jj.order == pj.order;
        for (int a = 0; a < 3; ++a)
            if (pj.dof[a] && !jj.dof[a]) m.dropped_.push_back({j, a});
    }
    return m;
}

Eigen::Matrix3d PoseMirror::worldReflection(const Eigen::Matrix3d& rootRotation) const {
    // Heading H: the rotation about Y taking the rest forward to the root's horizontal forward.
    Eigen::Vector3d f = rootRotation * forward_;
    f.y() = 0.0;
    Eigen::Matrix3d h = Eigen::Matrix3d::Identity();
    if (f.norm() > 1e-9) {
        f.normalize();
        const double psi = std::atan2(forward_.cross(f).y(), forward_.dot(f));
        h = axisRotation(kAxisY, psi);
    }
    return h * S_ * h.transpose();
}

Pose PoseMirror::mirror(const Pose& pose) const {
    const Skeleton& sk = skeleton_;
    Pose out = pose;  // root position kept
    const Joint& root = sk.joints[0];
    const Eigen::Matrix3d r = eulerMatrix(pose.anglesDeg[0], root.order);
    out.anglesDeg[0] = fitJointAngles(worldReflection(r) * r * S_, root.order, root.dof, pose.anglesDeg[0]);
    for (int j = 1; j < sk.jointCount(); ++j) {
        const Joint& jj = sk.joints[j];
        const int p = partner_[j];
        const Eigen::Vector3d& src = pose.anglesDeg[p];
        const Eigen::Matrix3d& d = conj_[j];
        if (signFlip_[j]) {
            // D R_a(θ) D = R_a(det D · d_a · θ), det D = −1.
            Eigen::Vector3d flipped;
            bool lost = false;
            for (int a = 0; a < 3; ++a) {
                flipped[a] = d(a, a) > 0 ? -src[a] : src[a];
                if (!jj.dof[a] && flipped[a] != 0.0) lost = true;
            }
            if (!lost) {
                out.anglesDeg[j] = flipped;
                continue;
            }
        }
        const Eigen::Matrix3d q = d * eulerMatrix(src, sk.joints[p].order) * d.transpose();
        Eigen::Vector3d reference;
        for (int a = 0; a < 3; ++a) reference[a] = std::abs(d(a, a)) > 0.5 && d(a, a) > 0 ? -src[a] : src[a];
        out.anglesDeg[j] = fitJointAngles(q, jj.order, jj.dof, reference);
    }
    return out;
}

}  // namespace mgp
