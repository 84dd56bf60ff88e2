#pragma once
// The span report (eval/motion_quality.h) as JSON, shared by `edit --json` and `bench --only edit`.
// Frame numbers are printed 1-based, like every CLI frame.
#include <nlohmann/json.hpp>

#include "eval/motion_quality.h"

namespace mgp::app {

inline nlohmann::json spanQualityJson(const SpanQuality& q) {
    nlohmann::json contacts = nlohmann::json::array();
    for (const ContactTravel& c : q.contacts)
        contacts.push_back({{"foot", effectorName(c.foot)}, {"first", c.first + 1}, {"last", c.last + 1},
                            {"travel_cm", c.editedCm}, {"captured_travel_cm", c.capturedCm}});
    return {{"first", q.first + 1}, {"last", q.last + 1},
            {"second_difference_deg", {{"p95", q.edited.p95Deg}, {"max", q.edited.maxDeg}, {"max_frame", q.edited.maxFrame + 1}}},
            {"captured_second_difference_deg", {{"p95", q.captured.p95Deg}, {"max", q.captured.maxDeg}}},
            {"worst_key_error_cm", q.worstKeyErrorCm}, {"worst_path_error_cm", q.worstPathErrorCm},
            {"worst_pose_change_deg", q.worstPoseChangeDeg}, {"worst_pose_change_frame", q.worstPoseChangeFrame + 1},
            {"contacts", contacts}};
}

}  // namespace mgp::app
