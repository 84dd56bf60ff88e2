#include "skeleton/synthetic_clip.h"

#include <cmath>

#include "skeleton/forward_kinematics.h"

namespace mgp {

namespace {

// Adds a joint whose offset is its parent's tail (ASF style). dofs: "xyz" subset.
int addBone(Skeleton& sk, const char* name, int parent, Eigen::Vector3d tailCm, const char* dofs,
            const Eigen::Matrix3d& axis = Eigen::Matrix3d::Identity()) {
    Joint j;
    j.name = j.bone = name;
    j.parent = parent;
    j.offsetCm = parent == 0 ? Eigen::Vector3d::Zero() : sk.joints[parent].tailCm;
    j.tailCm = tailCm;
    j.axis = axis;
    for (const char* c = dofs; *c; ++c) j.dof[*c - 'x'] = true;
    sk.joints.push_back(j);
    return sk.jointCount() - 1;
}

Skeleton makeSkeleton() {
    Skeleton sk;
    Joint root;
    root.name = root.bone = "root";
    root.dof = {true, true, true};
    sk.joints.push_back(root);
    // Elbows bend about world y in the rest (T) pose: the radius frame maps local x to world y.
    const Eigen::Matrix3d hinge = axisRotation(kAxisZ, M_PI / 2);
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? 1.0 : -1.0;  // left is +x (CMU)
        const std::string p = side == 0 ? "l" : "r";
        int j = addBone(sk, (p + "hipjoint").c_str(), 0, {s * 9.0, -6.0, 1.5}, "");
        j = addBone(sk, (p + "femur").c_str(), j, {0, -42.0, 0}, "xyz");
        j = addBone(sk, (p + "tibia").c_str(), j, {0, -42.0, 0}, "x");
        j = addBone(sk, (p + "foot").c_str(), j, {0, -4.0, 13.0}, "xz");
        addBone(sk, (p + "toes").c_str(), j, {0, 0, 5.0}, "x");
    }
    int spine = addBone(sk, "lowerback", 0, {0, 12.0, -0.5}, "xyz");
    spine = addBone(sk, "upperback", spine, {0, 12.0, 0}, "xyz");
    const int thorax = addBone(sk, "thorax", spine, {0, 12.0, 0.5}, "xyz");
    int neck = addBone(sk, "lowerneck", thorax, {0, 8.0, 0.5}, "xyz");
    neck = addBone(sk, "upperneck", neck, {0, 8.0, 0}, "xyz");
    addBone(sk, "head", neck, {0, 11.0, 1.0}, "xyz");
    for (int side = 0; side < 2; ++side) {
        const double s = side == 0 ? 1.0 : -1.0;
        const std::string p = side == 0 ? "l" : "r";
        int j = addBone(sk, (p + "clavicle").c_str(), thorax, {s * 17.0, 2.0, -1.0}, "yz");
        j = addBone(sk, (p + "humerus").c_str(), j, {s * 29.0, 0, 0}, "xyz");
        j = addBone(sk, (p + "radius").c_str(), j, {s * 25.0, 0, 0}, "x", hinge);
        j = addBone(sk, (p + "wrist").c_str(), j, {s * 3.0, 0, 0}, "y");
        const int hand = addBone(sk, (p + "hand").c_str(), j, {s * 8.0, 0, 0}, "xz");
        addBone(sk, (p + "fingers").c_str(), hand, {s * 4.0, 0, 0}, "x");
        addBone(sk, (p + "thumb").c_str(), j, {s * 3.0, 0, 3.0}, "xz");
    }
    sk.resolveEffectors();
    return sk;
}

}  // namespace

Clip makeSyntheticWalk(int frames) {
    Clip clip;
    clip.name = "synthetic_walk";
    clip.format = ClipFormat::kSynthetic;
    clip.convention = "synthetic";
    clip.fps = 120.0;
    clip.skeleton = makeSkeleton();
    const Skeleton& sk = clip.skeleton;
    auto J = [&](const char* bone) { return sk.findBone(bone); };
    const int cycle = 120;
    FkState fk;
    for (int t = 0; t < std::max(1, frames); ++t) {
        const double ph = 2.0 * M_PI * t / cycle;
        Pose pose;
        pose.anglesDeg.assign(sk.jointCount(), Eigen::Vector3d::Zero());
        auto set = [&](const char* bone, double x, double y, double z) {
            pose.anglesDeg[J(bone)] = Eigen::Vector3d(x, y, z);
        };
        for (int side = 0; side < 2; ++side) {
            const double phase = ph + (side == 0 ? 0.0 : M_PI);  // legs in antiphase
            const bool left = side == 0;
            const double hip = -25.0 * std::sin(phase);  // negative = leg forward (+z)
            const double knee = 5.0 + 32.0 * std::max(0.0, std::sin(phase + 0.9));
            const double ankle = -6.0 + 10.0 * std::sin(phase + 1.8);
            set(left ? "lfemur" : "rfemur", hip, 0.0, left ? -2.0 : 2.0);
            set(left ? "ltibia" : "rtibia", knee, 0.0, 0.0);
            set(left ? "lfoot" : "rfoot", ankle, 0.0, 0.0);
            // The arm on this side swings with the opposite leg.
            const double swing = 18.0 * std::sin(phase);
            set(left ? "lclavicle" : "rclavicle", 0.0, 0.0, left ? -4.0 : 4.0);
            set(left ? "lhumerus" : "rhumerus", 0.0, left ? swing : -swing, left ? -78.0 : 78.0);
            set(left ? "lradius" : "rradius",
                left ? -18.0 - 8.0 * std::max(0.0, -std::sin(phase)) : 18.0 + 8.0 * std::max(0.0, -std::sin(phase)),
                0.0, 0.0);
            set(left ? "lwrist" : "rwrist", 0.0, left ? 5.0 : -5.0, 0.0);
        }
        set("root", 2.0, 4.0 * std::sin(ph), 2.5 * std::sin(ph));
        set("lowerback", 3.0, 0.0, 0.0);
        set("thorax", -1.0, -5.0 * std::sin(ph), 0.0);
        set("lowerneck", -6.0, 0.0, 0.0);
        set("head", 4.0, 2.0 * std::sin(ph), 0.0);
        // Forward at 1.2 m/s with a small side sway; height chosen so the lower foot is 3 cm up.
        pose.rootCm = Eigen::Vector3d(2.0 * std::sin(ph), 0.0, 120.0 * t / clip.fps);
        forwardKinematics(sk, pose, fk);
        const double lowest =
            std::min(effectorCm(sk, fk, Effector::kLFoot).y(), effectorCm(sk, fk, Effector::kRFoot).y());
        pose.rootCm.y() = 3.0 - lowest;
        clip.frames.push_back(std::move(pose));
    }
    return clip;
}

}  // namespace mgp
