#include "io/bvh_writer.h"

#include <cstdio>
#include <functional>

#include "io/atomic_file.h"
#include "skeleton/rotation.h"

namespace mgp {

namespace {

bool isModelBone(const std::string& bone) {
    if (bone == "root") return true;
    for (const char* b : modelBoneNames())
        if (bone == b) return true;
    return false;
}

void appendf(std::string& out, const char* fmt, double a, double b, double c) {
    char buf[160];
    std::snprintf(buf, sizeof buf, fmt, a, b, c);
    out += buf;
}

// The End Site block of a leaf joint at indentation `pad`.
void appendEndSite(std::string& out, const std::string& pad, const Eigen::Vector3d& tail) {
    out += pad + "  End Site\n" + pad + "  {\n";
    appendf(out, (pad + "    OFFSET %.9f %.9f %.9f\n").c_str(), tail.x(), tail.y(), tail.z());
    out += pad + "  }\n";
}

// MOTION, Frames and Frame Time.
void appendMotionHeader(std::string& out, const Clip& clip) {
    char buf[96];
    out += "MOTION\n";
    out += "Frames: " + std::to_string(clip.frameCount()) + "\n";
    std::snprintf(buf, sizeof buf, "Frame Time: %.9f\n", 1.0 / clip.fps);
    out += buf;
}

// A BVH clip written back in its own hierarchy: every joint under its own name, OFFSETs and
// motion in the source's units, each joint's rotation channels in its own order and the angles
// as they are (no re-decomposition), so a BVH importer places every joint where the source does.
std::string formatSourceHierarchyBvh(const Clip& clip) {
    const Skeleton& sk = clip.skeleton;
    const int n = sk.jointCount();
    const double unit = clip.cmPerFileUnit > 0.0 ? 1.0 / clip.cmPerFileUnit : 1.0;  // file units per cm
    std::vector<std::vector<int>> children(n);
    for (int j = 1; j < n; ++j) children[sk.joints[j].parent].push_back(j);
    static const char* const kAxisName[] = {"X", "Y", "Z"};
    std::vector<std::vector<int>> channels(n);  // rotation axes per joint, in file order
    for (int j = 0; j < n; ++j)
        for (int a : sk.joints[j].order)
            if (j == 0 || sk.joints[j].dof[a]) channels[j].push_back(a);

    std::string out = "HIERARCHY\n";
    std::vector<int> fileOrder;
    std::function<void(int, int)> emit = [&](int j, int depth) {
        const std::string pad(static_cast<std::size_t>(depth) * 2, ' ');
        const Joint& joint = sk.joints[j];
        out += pad + (j == 0 ? "ROOT " : "JOINT ") + joint.name + "\n" + pad + "{\n";
        const Eigen::Vector3d off = joint.offsetCm * unit;
        appendf(out, (pad + "  OFFSET %.9f %.9f %.9f\n").c_str(), off.x(), off.y(), off.z());
        const std::size_t count = channels[j].size() + (j == 0 ? 3 : 0);
        out += pad + "  CHANNELS " + std::to_string(count) + (j == 0 ? " Xposition Yposition Zposition" : "");
        for (int a : channels[j]) out += std::string(" ") + kAxisName[a] + "rotation";
        out += "\n";
        fileOrder.push_back(j);
        for (int c : children[j]) emit(c, depth + 1);
        if (children[j].empty()) appendEndSite(out, pad, joint.tailCm * unit);
        out += pad + "}\n";
    };
    emit(0, 0);

    appendMotionHeader(out, clip);
    char buf[64];
    for (const Pose& pose : clip.frames) {
        const Eigen::Vector3d root = pose.rootCm * unit;  // the root's OFFSET is 0: positions are absolute
        appendf(out, "%.9f %.9f %.9f", root.x(), root.y(), root.z());
        for (int j : fileOrder)
            for (int a : channels[j]) {
                std::snprintf(buf, sizeof buf, " %.9f", pose.anglesDeg[j][a]);
                out += buf;
            }
        out += "\n";
    }
    return out;
}

}  // namespace

std::string formatBvh(const Clip& clip) {
    if (clip.skeleton.poseVector == PoseVectorKind::kChannels) return formatSourceHierarchyBvh(clip);
    const Skeleton& sk = clip.skeleton;
    const int n = sk.jointCount();
    // Keep the model bones and every ancestor of one (parents precede children, so walk back).
    std::vector<bool> keep(n, false);
    for (int j = n - 1; j >= 0; --j) {
        if (isModelBone(sk.joints[j].bone)) keep[j] = true;
        if (keep[j] && sk.joints[j].parent >= 0) keep[sk.joints[j].parent] = true;
    }
    keep[0] = true;
    std::vector<std::vector<int>> children(n);
    for (int j = 1; j < n; ++j)
        if (keep[j]) children[sk.joints[j].parent].push_back(j);
    auto nameOf = [&](int j) {
        return j == 0 ? std::string("root") : sk.joints[j].bone.empty() ? sk.joints[j].name : sk.joints[j].bone;
    };

    std::string out = "HIERARCHY\n";
    std::vector<int> order;  // joints in file (channel) order
    std::function<void(int, int)> emit = [&](int j, int depth) {
        const std::string pad(static_cast<std::size_t>(depth) * 2, ' ');
        const Joint& joint = sk.joints[j];
        out += pad + (j == 0 ? "ROOT " : "JOINT ") + nameOf(j) + "\n" + pad + "{\n";
        const Eigen::Vector3d off = j == 0 ? Eigen::Vector3d::Zero() : joint.offsetCm;
        appendf(out, (pad + "  OFFSET %.9f %.9f %.9f\n").c_str(), off.x(), off.y(), off.z());
        out += pad + (j == 0 ? "  CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n"
                             : "  CHANNELS 3 Zrotation Yrotation Xrotation\n");
        order.push_back(j);
        for (int c : children[j]) emit(c, depth + 1);
        if (children[j].empty()) appendEndSite(out, pad, joint.tailCm);
        out += pad + "}\n";
    };
    emit(0, 0);

    appendMotionHeader(out, clip);
    const Eigen::Vector3d rootOffset = sk.joints[0].offsetCm;
    for (const Pose& pose : clip.frames) {
        const Eigen::Vector3d root = pose.rootCm + rootOffset;
        appendf(out, "%.9f %.9f %.9f", root.x(), root.y(), root.z());
        for (int j : order) {
            const Joint& joint = sk.joints[j];
            const Eigen::Matrix3d local =
                joint.axis * eulerMatrix(pose.anglesDeg[j], joint.order) * joint.axis.transpose();
            const Eigen::Vector3d e = eulerZYXFromMatrix(local);  // (x, y, z)
            appendf(out, " %.9f %.9f %.9f", e.z(), e.y(), e.x());
        }
        out += "\n";
    }
    return out;
}

void writeBvh(const Clip& clip, const std::string& path) { writeFileAtomically(path, formatBvh(clip)); }

}  // namespace mgp
