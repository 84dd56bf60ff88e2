#include "range_tint.h"

#include <algorithm>
#include <cmath>

namespace mgp::render {

RangeTint rangeTint(const gp::TrainingRange& range, double sigma2, double lik) {
    RangeTint t;
    if (!std::isfinite(sigma2) || !std::isfinite(lik) || sigma2 > range.sigma2Limit || lik > range.likLimit) {
        t.band = RangeBand::kOutOfRange;
        t.colour = kRangeRed;
        t.weight = 1.0f;
        return t;
    }
    if (sigma2 <= range.sigma2Percentile) return t;
    t.band = RangeBand::kNearLimit;
    t.colour = kRangeAmber;
    const double span = range.sigma2Limit - range.sigma2Percentile;
    // A degenerate range (limit at the percentile) has no ramp: anything above is at the limit.
    t.weight = span > 0.0 ? static_cast<float>(std::clamp((sigma2 - range.sigma2Percentile) / span, 0.0, 1.0)) : 1.0f;
    return t;
}

void applyRangeTint(Figure& figure, const RangeTint& tint) {
    figure.tint = tint.colour;
    figure.tintWeight = tint.weight;
}

const char* rangeBandLabel(RangeBand band) {
    switch (band) {
        case RangeBand::kNearLimit: return "near limit";
        case RangeBand::kOutOfRange: return "out of range";
        case RangeBand::kInRange: break;
    }
    return "sigma^2 in range";  // ASCII: the UI font has no Greek
}

}  // namespace mgp::render
