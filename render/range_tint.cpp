#include "render/range_tint.h"

#include <algorithm>
#include <cmath>

namespace mgp::render {

RangeTint rangeTint(const AdmissionVerdict& verdict) {
    RangeTint t;
    if (!verdict.admitted) {
        t.band = RangeBand::kOutOfRange;
        t.colour = kRangeRed;
        t.weight = 1.0f;
        return t;
    }
    if (verdict.judgement == PoseJudgement::kNatural) return t;
    t.band = RangeBand::kNearLimit;
    t.colour = kRangeAmber;
    t.weight = static_cast<float>(std::clamp(std::isfinite(verdict.unusual) ? verdict.unusual : 1.0, 0.0, 1.0));
    return t;
}

void applyRangeTint(Figure& figure, const RangeTint& tint) {
    figure.tint = tint.colour;
    figure.tintWeight = tint.weight;
}

}  // namespace mgp::render
