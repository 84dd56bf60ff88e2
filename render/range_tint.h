#pragma once
// How far a solved pose lies outside the model's training range, as a bone tint (no GL).
//
// With p = TrainingRange::sigma2Percentile and L = sigma2Limit (= 2p, what admitPose allows):
//   σ² ≤ p                    side colours (weight 0): the captured motion spans this much
//   p < σ² ≤ L                amber, weight (σ² − p) / (L − p): admissible but nearing the limit
//   σ² > L or L_IK > likLimit red, weight 1: admitPose refuses this pose
// A non-finite σ² or L_IK counts as out of range. Amber starts at p rather than at L so the user
// sees the limit coming while dragging, before the pose is refused.
#include <glm/glm.hpp>

#include "gp/training_range.h"
#include "scene.h"

namespace mgp::render {

inline constexpr glm::vec3 kRangeAmber{1.0f, 0.72f, 0.0f};
inline constexpr glm::vec3 kRangeRed{0.92f, 0.10f, 0.08f};

enum class RangeBand { kInRange, kNearLimit, kOutOfRange };

struct RangeTint {
    RangeBand band = RangeBand::kInRange;
    glm::vec3 colour{0.0f};
    float weight = 0.0f;  // 0: the side colours; 1: `colour` alone
};

RangeTint rangeTint(const gp::TrainingRange& range, double sigma2, double lik);
// Sets a figure's tint from rangeTint.
void applyRangeTint(Figure& figure, const RangeTint& tint);
const char* rangeBandLabel(RangeBand band);  // "sigma^2 in range", "near limit", "out of range"

}  // namespace mgp::render
