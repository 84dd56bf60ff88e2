#pragma once
// The span report (motion/motion_quality.h) as JSON, shared by `edit --json` and the edit and falloff
// bench sections.
// Frame numbers are printed 1-based, like every CLI frame.
#include <cmath>
#include <nlohmann/json.hpp>

#include "motion/motion_quality.h"

namespace mgp::app {

inline nlohmann::json spanQualityJson(const SpanQuality& q) {
    nlohmann::json contacts = nlohmann::json::array();
    for (const ContactTravel& c : q.contacts)
        contacts.push_back({{"foot", effectorName(c.foot)},
                            {"first", c.first + 1},
                            {"last", c.last + 1},
                            {"travel_cm", c.editedCm},
                            {"captured_travel_cm", c.capturedCm}});
    return {{"first", q.first + 1},
            {"last", q.last + 1},
            {"second_difference_deg",
             {{"p95", q.edited.p95Deg}, {"max", q.edited.maxDeg}, {"max_frame", q.edited.maxFrame + 1}}},
            {"captured_second_difference_deg", {{"p95", q.captured.p95Deg}, {"max", q.captured.maxDeg}}},
            {"worst_key_error_cm", q.worstKeyErrorCm},
            {"worst_path_error_cm", q.worstPathErrorCm},
            {"worst_pose_change_deg", q.worstPoseChangeDeg},
            {"worst_pose_change_frame", q.worstPoseChangeFrame + 1},
            {"contacts", contacts}};
}

// The span against the motion bars (DESIGN's quality targets): second difference p95 ≤ 1.5 ×
// capture + 2°, max ≤ 1.5 × capture + 5°, every held contact's travel ≤ capture + 1 cm.
inline nlohmann::json motionBarsJson(const SpanQuality& q) {
    bool contactsOk = true;
    for (const ContactTravel& c : q.contacts) contactsOk = contactsOk && std::abs(c.editedCm - c.capturedCm) <= 1.0;
    return {{"p95", q.edited.p95Deg <= 1.5 * q.captured.p95Deg + 2.0},
            {"max", q.edited.maxDeg <= 1.5 * q.captured.maxDeg + 5.0},
            {"contacts_1_cm", contactsOk}};
}

}  // namespace mgp::app
