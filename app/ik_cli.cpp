#include "ik_cli.h"

#include <sstream>

#include "cli_common.h"
#include "gp/model_file.h"
#include "io/parse_error.h"
#include "io/text_reader.h"

namespace mgp::app {

Eigen::Vector3d parseOffset(const std::string& text, const std::string& option) {
    Eigen::Vector3d v;
    std::stringstream ss(text);
    std::string part;
    int i = 0;
    while (std::getline(ss, part, ',')) {
        if (i >= 3 || !parseDouble(trim(part), v[i]))
            throw UsageError("expected " + option + " as dx,dy,dz in cm, found '" + text + "'");
        ++i;
    }
    if (i != 3) throw UsageError("expected " + option + " as dx,dy,dz in cm, found '" + text + "'");
    return v;
}

Effector parseEffectorOption(const std::string& text, const std::string& option) {
    Effector e;
    if (!parseEffector(text, e))
        throw UsageError("expected " + option + " to be one of lhand, rhand, lfoot, rfoot, head, found '" + text + "'");
    return e;
}

std::pair<Effector, Eigen::Vector3d> parseTarget(const std::string& text) {
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) throw UsageError("expected --target EFF=dx,dy,dz, found '" + text + "'");
    return {parseEffectorOption(text.substr(0, eq), "--target"), parseOffset(text.substr(eq + 1), "--target")};
}

TargetSpec parseTargetWithStrength(const std::string& text) {
    const std::size_t at = text.find('@');
    TargetSpec spec;
    const auto [eff, offset] = parseTarget(text.substr(0, at));
    spec.effector = eff;
    spec.offsetCm = offset;
    if (at == std::string::npos) return spec;
    const std::string s(trim(text.substr(at + 1)));
    if (s == "exact") {
        spec.strength = kStrengthExact;
    } else if (s == "paper") {
        spec.strength = kStrengthPaper;
    } else if (!parseDouble(s, spec.strength) || !(spec.strength > 0.0 && spec.strength <= 1.0)) {
        throw UsageError("expected --target strength after @ as exact, paper or a number in (0, 1], found '" + s + "'");
    }
    return spec;
}

std::vector<int> parseFrameList(const std::string& text, const std::string& option) {
    std::vector<long long> frames;
    if (!parseIntList(text, 1, 100000000, frames))
        throw UsageError("expected " + option + " as frame numbers counted from 1 (e.g. 89,103,117,131), found '" +
                         text + "'");
    std::vector<int> out;
    for (long long f : frames) out.push_back(static_cast<int>(f - 1));
    return out;
}

gp::ModelVersionPtr loadModelVersion(const std::string& path) {
    gp::GpModel model = gp::loadModel(path);
    try {
        return gp::ModelVersion::make(std::move(model));
    } catch (const std::runtime_error&) {  // K could not be factored: a bad file, said as one
        throwParseError(path, 0, "a model whose kernel matrix K is positive definite", "a K that cannot be factored");
    }
}

gp::ModelVersionPtr loadModelVersion(const std::string& path, const std::string& clipName, int* clipIndex) {
    gp::GpModel model = gp::loadModel(path);
    int index = 0;
    if (!clipName.empty()) {
        index = model.findClip(clipName);
        if (index < 0)
            throw UsageError("expected --clip one of the model's clips (" + model.clipNames() + "), found '" +
                             clipName + "'");
    }
    if (clipIndex) *clipIndex = index;
    model = gp::withPrimaryClip(std::move(model), index);
    try {
        return gp::ModelVersion::make(std::move(model));
    } catch (const std::runtime_error&) {
        throwParseError(path, 0, "a model whose kernel matrix K is positive definite", "a K that cannot be factored");
    }
}

nlohmann::json constraintsJson(const std::vector<IkConstraintResult>& results, bool pins) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& r : results)
        if (r.pin == pins) {
            nlohmann::json e{
                {"effector", effectorName(r.effector)}, {"residual_cm", r.residualCm}, {"reached", r.reached}};
            if (!pins) e["strength"] = r.strength;
            if (r.belowFloor) e["below_floor"] = true;
            out.push_back(std::move(e));
        }
    return out;
}

}  // namespace mgp::app
