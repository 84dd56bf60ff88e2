#include "io/bvh_conventions.h"

#include <algorithm>
#include <map>

#include "io/text_reader.h"
#include "skeleton/pose_layout.h"

namespace mgp {

namespace {

constexpr double kAsfUnitCm = 2.54 / 0.45;

using NameMap = std::map<std::string, std::string>;

// Left-side names; the right side is derived by the caller's mirror rules below.
const NameMap& dazMap() {
    static const NameMap m = {{"hip", "root"},           {"abdomen", "lowerback"}, {"chest", "thorax"},
                              {"neck", "lowerneck"},     {"head", "head"},         {"lcollar", "lclavicle"},
                              {"lshldr", "lhumerus"},    {"lforearm", "lradius"},  {"lhand", "lwrist"},
                              {"lbuttock", "lhipjoint"}, {"lthigh", "lfemur"},     {"lshin", "ltibia"},
                              {"lfoot", "lfoot"},        {"rcollar", "rclavicle"}, {"rshldr", "rhumerus"},
                              {"rforearm", "rradius"},   {"rhand", "rwrist"},      {"rbuttock", "rhipjoint"},
                              {"rthigh", "rfemur"},      {"rshin", "rtibia"},      {"rfoot", "rfoot"}};
    return m;
}

const NameMap& motionBuilderMap() {
    static const NameMap m = {{"hips", "root"},
                              {"lhipjoint", "lhipjoint"},
                              {"leftupleg", "lfemur"},
                              {"leftleg", "ltibia"},
                              {"leftfoot", "lfoot"},
                              {"lefttoebase", "ltoes"},
                              {"rhipjoint", "rhipjoint"},
                              {"rightupleg", "rfemur"},
                              {"rightleg", "rtibia"},
                              {"rightfoot", "rfoot"},
                              {"righttoebase", "rtoes"},
                              {"lowerback", "lowerback"},
                              {"spine", "upperback"},
                              {"spine1", "thorax"},
                              {"neck", "lowerneck"},
                              {"neck1", "upperneck"},
                              {"head", "head"},
                              {"leftshoulder", "lclavicle"},
                              {"leftarm", "lhumerus"},
                              {"leftforearm", "lradius"},
                              {"lefthand", "lwrist"},
                              {"leftfingerbase", "lhand"},
                              {"lefthandindex1", "lfingers"},
                              {"lthumb", "lthumb"},
                              {"rightshoulder", "rclavicle"},
                              {"rightarm", "rhumerus"},
                              {"rightforearm", "rradius"},
                              {"righthand", "rwrist"},
                              {"rightfingerbase", "rhand"},
                              {"righthandindex1", "rfingers"},
                              {"rthumb", "rthumb"}};
    return m;
}

const NameMap& maxMap() {
    static const NameMap m = {{"hips", "root"},
                              {"lhipjoint", "lhipjoint"},
                              {"lefthip", "lfemur"},
                              {"leftknee", "ltibia"},
                              {"leftankle", "lfoot"},
                              {"lefttoe", "ltoes"},
                              {"rhipjoint", "rhipjoint"},
                              {"righthip", "rfemur"},
                              {"rightknee", "rtibia"},
                              {"rightankle", "rfoot"},
                              {"righttoe", "rtoes"},
                              {"lowerback", "lowerback"},
                              {"chest", "upperback"},
                              {"chest2", "thorax"},
                              {"lowerneck", "lowerneck"},
                              {"neck", "upperneck"},
                              {"head", "head"},
                              {"leftcollar", "lclavicle"},
                              {"leftshoulder", "lhumerus"},
                              {"leftelbow", "lradius"},
                              {"leftwrist", "lwrist"},
                              {"lhand", "lhand"},
                              {"lfingers", "lfingers"},
                              {"lthumb", "lthumb"},
                              {"rightcollar", "rclavicle"},
                              {"rightshoulder", "rhumerus"},
                              {"rightelbow", "rradius"},
                              {"rightwrist", "rwrist"},
                              {"rhand", "rhand"},
                              {"rfingers", "rfingers"},
                              {"rthumb", "rthumb"}};
    return m;
}

// ASF names map to themselves; a few common aliases (ACCAD's Swagger) are added.
const NameMap& asfAliasMap() {
    static const NameMap m = {{"neck", "lowerneck"}, {"lshoulderjoint", "lclavicle"}, {"rshoulderjoint", "rclavicle"}};
    return m;
}

bool isAsfBoneName(const std::string& lower) {
    if (lower == "root" || isDroppedAsfBone(lower)) return true;
    const auto& names = modelBoneNames();
    return std::find(names.begin(), names.end(), lower) != names.end();
}

bool has(const std::vector<std::string>& lowerNames, const char* name) {
    return std::find(lowerNames.begin(), lowerNames.end(), name) != lowerNames.end();
}

}  // namespace

BvhConvention detectBvhConvention(const std::vector<std::string>& jointNames) {
    std::vector<std::string> lower;
    for (const auto& n : jointNames) lower.push_back(toLower(n));
    if (has(lower, "hip") && has(lower, "abdomen")) return {"cgspeed-daz", 1.0, true};
    if (has(lower, "hips") && has(lower, "leftupleg")) return {"cgspeed-motionbuilder", kAsfUnitCm, true};
    if (has(lower, "hips") && has(lower, "lefthip") && has(lower, "leftknee"))
        return {"cgspeed-3dsmax", kAsfUnitCm, false};
    if (has(lower, "lfemur") || has(lower, "lhumerus") || has(lower, "lowerback")) return {"asf-names", 1.0, false};
    return {"generic", 1.0, false};
}

std::string boneRoleFor(const std::string& convention, const std::string& jointName) {
    const std::string lower = toLower(jointName);
    const NameMap* map = nullptr;
    if (convention == "cgspeed-daz")
        map = &dazMap();
    else if (convention == "cgspeed-motionbuilder")
        map = &motionBuilderMap();
    else if (convention == "cgspeed-3dsmax")
        map = &maxMap();
    if (map) {
        const auto it = map->find(lower);
        return it == map->end() ? std::string() : it->second;
    }
    if (isAsfBoneName(lower)) return lower;
    const auto it = asfAliasMap().find(lower);
    return it == asfAliasMap().end() ? std::string() : it->second;
}

std::string mainChildRole(const std::string& role) {
    static const NameMap m = {
        {"lhipjoint", "lfemur"},    {"lfemur", "ltibia"},      {"ltibia", "lfoot"},       {"lfoot", "ltoes"},
        {"rhipjoint", "rfemur"},    {"rfemur", "rtibia"},      {"rtibia", "rfoot"},       {"rfoot", "rtoes"},
        {"lowerback", "upperback"}, {"upperback", "thorax"},   {"thorax", "lowerneck"},   {"lowerneck", "upperneck"},
        {"upperneck", "head"},      {"lclavicle", "lhumerus"}, {"lhumerus", "lradius"},   {"lradius", "lwrist"},
        {"lwrist", "lhand"},        {"lhand", "lfingers"},     {"rclavicle", "rhumerus"}, {"rhumerus", "rradius"},
        {"rradius", "rwrist"},      {"rwrist", "rhand"},       {"rhand", "rfingers"}};
    const auto it = m.find(role);
    return it == m.end() ? std::string() : it->second;
}

}  // namespace mgp
