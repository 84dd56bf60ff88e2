#include "skeleton/skeleton.h"

#include <stdexcept>

namespace mgp {

namespace {
constexpr const char* kEffectorNames[kEffectorCount] = {"lhand", "rhand", "lfoot", "rfoot", "head"};
}

const char* effectorName(Effector e) { return kEffectorNames[static_cast<int>(e)]; }

bool parseEffector(const std::string& name, Effector& out) {
    for (int i = 0; i < kEffectorCount; ++i)
        if (name == kEffectorNames[i]) {
            out = static_cast<Effector>(i);
            return true;
        }
    return false;
}

int Skeleton::findJoint(const std::string& name) const {
    for (int i = 0; i < jointCount(); ++i)
        if (joints[i].name == name) return i;
    return -1;
}

int Skeleton::findBone(const std::string& bone) const {
    for (int i = 0; i < jointCount(); ++i)
        if (joints[i].bone == bone) return i;
    return -1;
}

bool Skeleton::isAncestorOrSelf(int ancestor, int joint) const {
    for (int j = joint; j >= 0; j = joints[j].parent)
        if (j == ancestor) return true;
    return false;
}

std::vector<Effector> Skeleton::resolveEffectors() {
    struct Rule {
        Effector effector;
        const char* endOf;
        const char* startOf;
    };
    static const Rule rules[] = {{Effector::kLHand, "lwrist", "lhand"},
                                 {Effector::kRHand, "rwrist", "rhand"},
                                 {Effector::kLFoot, "lfoot", "ltoes"},
                                 {Effector::kRFoot, "rfoot", "rtoes"},
                                 {Effector::kHead, "head", nullptr}};
    std::vector<Effector> missing;
    for (const Rule& rule : rules) {
        EffectorSite site;
        if (int j = findBone(rule.endOf); j >= 0) {
            site.joint = j;
            site.localCm = joints[j].tailCm;
        } else if (int k = rule.startOf ? findBone(rule.startOf) : -1; k >= 0) {
            site.joint = k;
        } else {
            missing.push_back(rule.effector);
        }
        sites_[static_cast<int>(rule.effector)] = site;
    }
    return missing;
}

void Skeleton::validate() const {
    if (joints.empty()) throw std::logic_error("skeleton has no joints");
    if (joints[0].parent != -1) throw std::logic_error("joint 0 must be the root");
    for (int i = 1; i < jointCount(); ++i)
        if (joints[i].parent < 0 || joints[i].parent >= i)
            throw std::logic_error("joint " + joints[i].name + " does not follow its parent");
}

}  // namespace mgp
