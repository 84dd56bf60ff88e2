#include "ik/ik_types.h"

#include <algorithm>

namespace mgp {

bool anyBelowFloor(const std::vector<IkConstraintResult>& results) {
    return std::any_of(results.begin(), results.end(), [](const IkConstraintResult& r) { return r.belowFloor; });
}

std::vector<Effector> movedEffectors(const std::vector<IkConstraintResult>& results) {
    std::vector<Effector> out;
    for (const IkConstraintResult& r : results)
        if (!r.pin) out.push_back(r.effector);
    return out;
}

std::string validateConstraints(const Skeleton& skeleton, const std::vector<IkConstraint>& constraints) {
    bool seen[kEffectorCount] = {};
    for (const IkConstraint& c : constraints) {
        const int e = static_cast<int>(c.effector);
        if (e < 0 || e >= kEffectorCount) return "expected an effector, found index " + std::to_string(e);
        const std::string name = effectorName(c.effector);
        if (!skeleton.hasEffector(c.effector)) return "expected an effector this skeleton has, found " + name;
        if (!c.targetCm.allFinite()) return "expected a finite target for " + name + ", found NaN or Inf";
        if (!(c.strength > 0.0 && c.strength <= 1.0))
            return "expected a strength in (0, 1] for " + name + ", found " + std::to_string(c.strength);
        if (seen[e]) return "expected each effector once, found " + name + " twice";
        seen[e] = true;
    }
    return "";
}

}  // namespace mgp
