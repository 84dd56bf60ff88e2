#include "skeleton/pose_layout.h"

#include <algorithm>

namespace mgp {

const std::array<AsfPoseDof, kAsfPoseDofs>& asfPoseDofTable() {
    static const std::array<AsfPoseDof, kAsfPoseDofs> table = {{
        {"root", kAxisX},      {"root", kAxisY},      {"root", kAxisZ},      {"lfemur", kAxisX},
        {"lfemur", kAxisY},    {"lfemur", kAxisZ},    {"ltibia", kAxisX},    {"lfoot", kAxisX},
        {"lfoot", kAxisZ},     {"rfemur", kAxisX},    {"rfemur", kAxisY},    {"rfemur", kAxisZ},
        {"rtibia", kAxisX},    {"rfoot", kAxisX},     {"rfoot", kAxisZ},     {"lowerback", kAxisX},
        {"lowerback", kAxisY}, {"lowerback", kAxisZ}, {"upperback", kAxisX}, {"upperback", kAxisY},
        {"upperback", kAxisZ}, {"thorax", kAxisX},    {"thorax", kAxisY},    {"thorax", kAxisZ},
        {"lowerneck", kAxisX}, {"lowerneck", kAxisY}, {"lowerneck", kAxisZ}, {"upperneck", kAxisX},
        {"upperneck", kAxisY}, {"upperneck", kAxisZ}, {"head", kAxisX},      {"head", kAxisY},
        {"head", kAxisZ},      {"lclavicle", kAxisY}, {"lclavicle", kAxisZ}, {"lhumerus", kAxisX},
        {"lhumerus", kAxisY},  {"lhumerus", kAxisZ},  {"lradius", kAxisX},   {"lwrist", kAxisY},
        {"rclavicle", kAxisY}, {"rclavicle", kAxisZ}, {"rhumerus", kAxisX},  {"rhumerus", kAxisY},
        {"rhumerus", kAxisZ},  {"rradius", kAxisX},   {"rwrist", kAxisY},
    }};
    return table;
}

const std::array<const char*, kModelBones>& modelBoneNames() {
    static const std::array<const char*, kModelBones> names = {
        "lhipjoint", "lfemur",    "ltibia",    "lfoot",     "rhipjoint", "rfemur", "rtibia",    "rfoot",
        "lowerback", "upperback", "thorax",    "lowerneck", "upperneck", "head",   "lclavicle", "lhumerus",
        "lradius",   "lwrist",    "rclavicle", "rhumerus",  "rradius",   "rwrist"};
    return names;
}

bool isDroppedAsfBone(const std::string& bone) {
    static const char* dropped[] = {"lhand", "rhand", "lfingers", "rfingers", "lthumb", "rthumb", "ltoes", "rtoes"};
    return std::any_of(std::begin(dropped), std::end(dropped), [&](const char* d) { return bone == d; });
}

std::vector<std::string> missingModelBones(const Skeleton& skeleton) {
    std::vector<std::string> out;
    for (const char* bone : modelBoneNames())
        if (skeleton.findBone(bone) < 0) out.push_back(bone);
    return out;
}

PoseLayout::PoseLayout(const Skeleton& skeleton) : kind_(skeleton.poseVector) {
    const auto add = [&](int joint, int axis) {
        joint_.push_back(joint);
        axis_.push_back(axis);
    };
    if (kind_ == PoseVectorKind::kAsfModel) {
        for (const AsfPoseDof& d : asfPoseDofTable()) add(skeleton.findBone(d.bone), d.axis);
        return;
    }
    // Channels: the root's three rotations first (as in the ASF vector), then every joint's.
    if (skeleton.jointCount() == 0) return;
    for (int a = 0; a < 3; ++a) add(0, a);
    for (int j = 1; j < skeleton.jointCount(); ++j)
        for (int a = 0; a < 3; ++a)
            if (skeleton.joints[j].dof[a]) add(j, a);
}

std::string PoseLayout::dofName(const Skeleton& skeleton, int dof) const {
    // ASF: the table's bone role (also for a bone the skeleton lacks); channels: the joint's name.
    const std::string name =
        kind_ == PoseVectorKind::kAsfModel ? asfPoseDofTable()[dof].bone : skeleton.joints[joint_[dof]].name;
    return name + " r" + "xyz"[axis_[dof]];
}

void PoseLayout::extract(const Pose& pose, double* y) const {
    for (int i = 0; i < size(); ++i) y[i] = joint_[i] >= 0 ? pose.anglesDeg[joint_[i]][axis_[i]] : 0.0;
}

Eigen::VectorXd PoseLayout::extract(const Pose& pose) const {
    Eigen::VectorXd y(size());
    extract(pose, y.data());
    return y;
}

void PoseLayout::apply(const double* y, Pose& pose) const {
    for (int i = 0; i < size(); ++i)
        if (joint_[i] >= 0) pose.anglesDeg[joint_[i]][axis_[i]] = y[i];
}

bool posesIdentical(const Pose& a, const Pose& b) { return a.rootCm == b.rootCm && a.anglesDeg == b.anglesDeg; }

bool allFinite(const Pose& pose) {
    if (!pose.rootCm.allFinite()) return false;
    for (const auto& a : pose.anglesDeg)
        if (!a.allFinite()) return false;
    return true;
}

}  // namespace mgp
