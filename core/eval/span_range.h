#pragma once
// Table 2's extra column (docs/maths.md §14): the same edit made by span regeneration
// (motion/motion_edit.h, kSpan) instead of one frame. Keys at the edited frame f − 21, f, f + 21
// (a 43-frame span), the middle one moved by δ·u; contacts held. A span that would cross the join
// of two trials (`joins`) is skipped: the span solver would take the jump for motion. The span range is the largest δ
// (1 cm steps) such that every δ' ≤ δ meets the key within 0.5 cm, keeps the span's largest
// per-frame joint-angle second difference within the capture's (p95 ≤ 1.5× + 2°, max ≤ 1.5× + 5°)
// and gives an edited-frame pose that passes the same naturalness tests. Not the paper's
// protocol: it shows what coherence costs or buys at the same edit.
#include <vector>

#include <nlohmann/json.hpp>

#include "eval/naturalness.h"
#include "gp/model_version.h"

namespace mgp {

struct SpanRangeJob {
    gp::ModelVersionPtr version;
    int frame = 0;  // the edited clip frame (0-based)
    Effector effector = Effector::kRFoot;
    Eigen::Vector3d direction = Eigen::Vector3d::UnitY();  // unit
    const NaturalnessTests* tests = nullptr;
    int maxDeltaCm = 80;
    std::vector<int> joins;  // clip frames that start another trial (0-based)
    // {"combined", "first_failure", "steps", "keys" (1-based)}, or {"skipped": why} when the span
    // does not fit the clip.
    nlohmann::json run() const;
};

}  // namespace mgp
