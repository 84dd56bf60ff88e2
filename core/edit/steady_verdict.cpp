#include "edit/steady_verdict.h"

#include <array>

namespace mgp {

VerdictClass verdictClass(const AdmissionVerdict& v) {
    if (!v.admitted) return VerdictClass::kRefused;
    return v.judgement == PoseJudgement::kNatural ? VerdictClass::kNatural : VerdictClass::kUnusual;
}

bool steadiable(PoseJudgement judgement) {
    return judgement == PoseJudgement::kNatural || judgement == PoseJudgement::kUnusual ||
           judgement == PoseJudgement::kUnlikeCapture;
}

VerdictClass steadyClass(const std::vector<VerdictClass>& classes, std::size_t self) {
    std::array<std::size_t, 3> count{};
    for (VerdictClass c : classes) ++count[static_cast<std::size_t>(c)];
    for (std::size_t c = 0; c < count.size(); ++c)
        if (2 * count[c] > classes.size()) return static_cast<VerdictClass>(c);
    return classes[self];
}

}  // namespace mgp
