#pragma once
// Table 2's extra column (docs/maths.md §14): the same edit made by span regeneration
// (motion/motion_edit.h, kSpan) instead of one frame. Keys at the edited frame f − 21, f, f + 21
// (a 43-frame span), the middle one moved by δ·u; contacts held. The span range is the largest δ
// (1 cm steps) such that every δ' ≤ δ meets the key within 0.5 cm, keeps the span's largest
// per-frame joint-angle second difference within the capture's (p95 ≤ 1.5× + 2°, max ≤ 1.5× + 5°)
// and gives an edited-frame pose that passes the same naturalness tests. Not the paper's
// protocol: it shows what coherence costs or buys at the same edit.
#include <nlohmann/json.hpp>

#include "eval/naturalness.h"
#include "gp/model_version.h"

namespace mgp {

struct SpanRangeJob {
    gp::ModelVersionPtr version;
    int frame = 0;  // the edited clip frame (0-based)
    Effector effector = Effector::kRFoot;
    double direction = 1.0;  // +1 raise, −1 lower (along Y)
    const NaturalnessTests* tests = nullptr;
    int maxDeltaCm = 80;
    // {"combined", "first_failure", "steps", "keys" (1-based)}, or {"skipped": why} when the span
    // does not fit the clip.
    nlohmann::json run() const;
};

}  // namespace mgp
