#include "skeleton/centre_of_mass.h"

#include <cstring>
#include <iterator>
#include <vector>

namespace mgp {
namespace {
// de Leva (1996) Table 4, male: mass fraction and CM position along the segment. The table measures
// the head, trunk parts from their cranial end; the ASF bones of those run upwards (from the joint
// nearer the pelvis), so their ratios are 1 − the table's: head and neck 50.02 % from the vertex,
// upper trunk 50.66 %, middle 45.02 %, lower 61.15 % from their cranial ends. The limbs are
// measured from the proximal joint, as the bones run. The ASF bones only approximate de Leva's
// landmarks (the CMU lowerback / upperback / thorax do not end at the omphalion or xiphion).
constexpr BodySegment kSegments[] = {
    {"lfemur", 0.1416, 0.4095},          {"rfemur", 0.1416, 0.4095},    // thigh, from the hip
    {"ltibia", 0.0433, 0.4459},          {"rtibia", 0.0433, 0.4459},    // shank, from the knee
    {"lfoot", 0.0137, 0.4415},           {"rfoot", 0.0137, 0.4415},     // foot, from the ankle
    {"lhumerus", 0.0271, 0.5772},        {"rhumerus", 0.0271, 0.5772},  // upper arm, from the shoulder
    {"lradius", 0.0162, 0.4574},         {"rradius", 0.0162, 0.4574},   // forearm, from the elbow
    {"lhand", 0.0061, 0.7900},           {"rhand", 0.0061, 0.7900},     // hand, from the wrist
    {"head", 0.0694, 1.0 - 0.5002},                                     // head and neck
    {"lowerback", 0.1117, 1.0 - 0.6115},                                // lower trunk
    {"upperback", 0.1633, 1.0 - 0.4502},                                // middle trunk
    {"thorax", 0.1596, 1.0 - 0.5066},                                   // upper trunk
};
Eigen::Vector3d segmentPoint(const Skeleton& skeleton, const FkState& fk, const BodyMass::Segment& s) {
    const Eigen::Vector3d start = fk.jointCm[s.joint];
    return start + s.ratio * (boneEndCm(skeleton, fk, s.joint) - start);
}

}  // namespace

const BodySegment* bodySegments(int* count) {
    *count = static_cast<int>(std::size(kSegments));
    return kSegments;
}

BodyMass::BodyMass(const Skeleton& skeleton) {
    double mass = 0.0;
    bool thighs[2] = {false, false}, trunk = false;
    for (const BodySegment& s : kSegments) {
        int joint = -1;
        for (int j = 0; j < skeleton.jointCount(); ++j)
            if (skeleton.joints[j].bone == s.bone) joint = j;
        if (joint < 0) continue;
        segments_.push_back({joint, s.massFraction, s.comRatio, 0.0});
        mass += s.massFraction;
        if (std::strcmp(s.bone, "lfemur") == 0) thighs[0] = true;
        if (std::strcmp(s.bone, "rfemur") == 0) thighs[1] = true;
        trunk = trunk || std::strcmp(s.bone, "lowerback") == 0 || std::strcmp(s.bone, "upperback") == 0 ||
                std::strcmp(s.bone, "thorax") == 0;
    }
    if (!thighs[0] || !thighs[1] || !trunk) {
        segments_.clear();
        return;
    }
    for (Segment& p : segments_) p.weight = p.fraction / mass;
}

std::optional<Eigen::Vector3d> centreOfMass(const Skeleton& skeleton, const BodyMass& body, const FkState& fk) {
    if (body.empty()) return std::nullopt;
    // Summed with the table's fractions and divided once.
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double mass = 0.0;
    for (const BodyMass::Segment& p : body.segments()) {
        sum += p.fraction * segmentPoint(skeleton, fk, p);
        mass += p.fraction;
    }
    return sum / mass;
}

std::optional<Eigen::Vector3d> centreOfMass(const Skeleton& skeleton, const FkState& fk) {
    return centreOfMass(skeleton, BodyMass(skeleton), fk);
}

bool centreOfMassJacobian(const Skeleton& skeleton, const BodyMass& body, const PoseLayout& layout, const FkState& fk,
                          const Pose& pose, Eigen::Ref<Eigen::Matrix<double, 3, Eigen::Dynamic>> jac) {
    jac.setZero();
    if (body.empty()) return false;
    for (int i = 0; i < layout.size(); ++i) {
        const int j = layout.joint(i);
        if (j < 0) continue;
        // Σ over the segments this DOF moves of w_s (p_s − q_j), then ω × that.
        Eigen::Vector3d lever = Eigen::Vector3d::Zero();
        for (const BodyMass::Segment& s : body.segments())
            if (skeleton.isAncestorOrSelf(j, s.joint))
                lever += s.weight * (segmentPoint(skeleton, fk, s) - fk.jointCm[j]);
        if (lever.isZero(0.0)) continue;
        jac.col(i) = kDegToRad * dofWorldAxis(skeleton, fk, pose, j, layout.axis(i)).cross(lever);
    }
    return true;
}

void centreOfMassHessianContracted(const Skeleton& skeleton, const BodyMass& body, const PoseLayout& layout,
                                   const FkState& fk, const Pose& pose, const Eigen::Vector3d& lambda,
                                   Eigen::Ref<Eigen::MatrixXd> out) {
    out.setZero();
    for (const BodyMass::Segment& s : body.segments())
        addPointHessianContracted(skeleton, layout, fk, pose, s.joint, segmentPoint(skeleton, fk, s), s.weight * lambda,
                                  out);
}

std::optional<Eigen::Vector3d> centreOfMass(const Skeleton& skeleton, const Pose& pose) {
    FkState fk;
    forwardKinematics(skeleton, pose, fk);
    return centreOfMass(skeleton, fk);
}

double horizontalDistanceCm(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return Eigen::Vector2d(a.x() - b.x(), a.z() - b.z()).norm();
}

std::optional<double> horizontalComShiftCm(const Skeleton& skeleton, const Pose& a, const Pose& b) {
    const std::optional<Eigen::Vector3d> ca = centreOfMass(skeleton, a), cb = centreOfMass(skeleton, b);
    if (!ca || !cb) return std::nullopt;
    return horizontalDistanceCm(*ca, *cb);
}

}  // namespace mgp
