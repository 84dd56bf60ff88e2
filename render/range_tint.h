#pragma once
// How a solved pose is judged (eval/admission.h), as a bone tint (no GL):
//   natural                         side colours (weight 0)
//   unusual                         amber, weight = AdmissionVerdict::unusual: from the capture's
//                                   median nearest-frame distance (0) to its limit (1); still taught
//   unlike the captured data, out   red, weight 1: the adaptive update refuses this pose
//   of reach, through the floor
// Amber starts at the capture's median rather than at the limit, so the animator sees the limit
// coming while dragging, before the pose is refused.
#include <glm/glm.hpp>

#include "eval/admission.h"
#include "render/scene.h"

namespace mgp::render {

inline constexpr glm::vec3 kRangeAmber{1.0f, 0.72f, 0.0f};
inline constexpr glm::vec3 kRangeRed{0.92f, 0.10f, 0.08f};

enum class RangeBand { kInRange, kNearLimit, kOutOfRange };

struct RangeTint {
    RangeBand band = RangeBand::kInRange;
    glm::vec3 colour{0.0f};
    float weight = 0.0f;  // 0: the side colours; 1: `colour` alone
};

RangeTint rangeTint(const AdmissionVerdict& verdict);
// Sets a figure's tint from rangeTint.
void applyRangeTint(Figure& figure, const RangeTint& tint);

}  // namespace mgp::render
