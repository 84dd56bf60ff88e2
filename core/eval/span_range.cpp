#include "eval/span_range.h"

#include <string>

#include "motion/motion_edit.h"

namespace mgp {

nlohmann::json SpanRangeJob::run() const {
    const Clip& clip = version->model->clip;
    const int f = frame, first = f - 21, last = f + 21;
    if (first - 1 < 0 || last + 1 >= clip.frameCount()) return {{"skipped", "the 43-frame span does not fit the clip"}};
    for (int j : joins)
        if (j > first - 1 && j <= last + 1) return {{"skipped", "the span crosses the join of two trials"}};
    const PoseLayout layout(clip.skeleton);
    Eigen::VectorXd previous;
    int range = -1;
    nlohmann::json steps = nlohmann::json::array();
    std::string failed;
    for (int delta = 0; delta <= maxDeltaCm; ++delta) {
        MotionEditJob job;
        job.version = version;
        job.effector = effector;
        job.keyFrames = {first, f, last};
        job.keyOffsetsCm = {Eigen::Vector3d::Zero(), direction * delta, Eigen::Vector3d::Zero()};
        job.mode = PathMode::kDirect;  // the paper's Hermite path, as the protocol was measured
        job.run();
        const SpanQuality& q = job.quality;
        const Eigen::VectorXd poseDeg = layout.extract(job.frames[f]);
        const NaturalnessVerdict v = tests->judge(clip.skeleton, poseDeg, delta == 0 ? nullptr : &previous);
        const bool smooth =
            q.edited.p95Deg <= 1.5 * q.captured.p95Deg + 2.0 && q.edited.maxDeg <= 1.5 * q.captured.maxDeg + 5.0;
        const bool reach = q.worstKeyErrorCm <= 0.5;
        if (delta % 10 == 0 || !(reach && smooth && v.all()))
            steps.push_back({{"delta", delta},
                             {"key_error_cm", q.worstKeyErrorCm},
                             {"p95_deg", q.edited.p95Deg},
                             {"max_deg", q.edited.maxDeg},
                             {"captured_p95_deg", q.captured.p95Deg},
                             {"captured_max_deg", q.captured.maxDeg},
                             {"ranges", v.ranges},
                             {"nearest", v.nearest},
                             {"density", v.density},
                             {"continuity", v.continuity}});
        if (!(reach && smooth && v.all())) {
            failed = !reach       ? "reach"
                     : !smooth    ? "smoothness"
                     : !v.ranges  ? "joint ranges"
                     : !v.nearest ? "nearest real pose"
                     : !v.density ? "density"
                                  : "continuity";
            break;
        }
        range = delta;
        previous = poseDeg;
    }
    return {{"combined", range},
            {"first_failure", failed.empty() ? "none up to max_delta" : failed},
            {"steps", steps},
            {"keys", {first + 1, f + 1, last + 1}}};
}

}  // namespace mgp
