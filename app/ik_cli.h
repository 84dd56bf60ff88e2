#pragma once
// Parsing and JSON helpers shared by the IK verbs (pose, edit, table2).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "gp/model_version.h"
#include "ik/ik_types.h"
#include "motion/foot_contacts.h"
#include "skeleton/forward_kinematics.h"

namespace mgp::app {

// "dx,dy,dz" → vector (cm); throws UsageError naming the option.
Eigen::Vector3d parseOffset(const std::string& text, const std::string& option);
// "EFF=dx,dy,dz".
std::pair<Effector, Eigen::Vector3d> parseTarget(const std::string& text);
// "EFF=dx,dy,dz[@STRENGTH]", STRENGTH = exact (1, the default), paper (0.999) or a number in (0, 1].
struct TargetSpec {
    Effector effector = Effector::kRHand;
    Eigen::Vector3d offsetCm = Eigen::Vector3d::Zero();
    double strength = kStrengthExact;
};
TargetSpec parseTargetWithStrength(const std::string& text);
Effector parseEffectorOption(const std::string& text, const std::string& option);
// "89,103,117,131" (1-based) → clip indices.
std::vector<int> parseFrameList(const std::string& text, const std::string& option);
// Loads a model file as version 0 (throws ParseError for a bad file).
gp::ModelVersionPtr loadModelVersion(const std::string& path);
// The same with the clip named `clipName` (--clip NAME, a file stem; "" = the first clip) as the
// primary clip (gp::withPrimaryClip), so --frame counts within it. An unknown name is a
// UsageError listing the model's clips. clipIndex (if given) receives the clip's index in the
// file: withPrimaryClip(model, *clipIndex) restores the file's clip order before saving.
gp::ModelVersionPtr loadModelVersion(const std::string& path, const std::string& clipName, int* clipIndex = nullptr);
// One entry per constraint of that kind: effector, residual_cm, reached (targets also strength).
nlohmann::json constraintsJson(const std::vector<IkConstraintResult>& results, bool pins);

}  // namespace mgp::app
