// bench section "edit": span regeneration on real clips, the paper's per-frame solve (today's
// `edit --solver per-frame --no-contacts`) BEFORE and the span solver (the default) AFTER.
// Raise (+Y) and sideways (+X) edits of 10, 20 and 40 cm of the middle keys of a 43-frame span
// (keys 14 frames apart); for each: the span report (motion/motion_quality.h) and the median
// wall time of the regeneration over --repeats runs. Models: M = 200, T = 20 (quick: M = 100, T = 3).
#include "bench_registry.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "motion/motion_edit.h"
#include "motion_quality_json.h"

namespace mgp::app {
namespace {

struct EditCase {
    const char* clip;
    Effector effector;
    int firstKey;  // 1-based
    const char* why;
};

// 35_01 and 10_02 are where the span solver's weights were tuned; the others are held out.
const EditCase kEditCases[] = {
    {"10_03", Effector::kRFoot, 189, "held-out kick, left foot planted from 224"},
    {"16_01", Effector::kRFoot, 60, "held-out jump take-off, both feet planted"},
    {"09_01", Effector::kLFoot, 60, "held-out run"},
    {"35_01", Effector::kLFoot, 89, "tuning clip: walk, right foot planted 100..157"},
};

nlohmann::json runOne(const gp::ModelVersionPtr& version, const EditCase& c, const Eigen::Vector3d& offset, bool span,
                      int repeats) {
    MotionEditJob job;
    job.version = version;
    job.effector = c.effector;
    const int k = c.firstKey - 1;
    job.keyFrames = {k, k + 14, k + 28, k + 42};
    job.keyOffsetsCm = {Eigen::Vector3d::Zero(), offset, offset, Eigen::Vector3d::Zero()};
    job.solver = span ? EditSolver::kSpan : EditSolver::kPerFrame;
    job.mode = PathMode::kDirect;  // the paper's Hermite path: the rows' bars were set on it
    job.holdContacts = span;       // BEFORE: exactly today's per-frame regeneration
    job.threads = 1;               // one core each, comparable timings
    std::vector<double> seconds;
    for (int r = 0; r < repeats; ++r) seconds.push_back(secondsOf([&] { job.run(); }));
    nlohmann::json out{{"solver", editSolverName(job.solver)},
                       {"contacts_held", job.holdContacts},
                       {"seconds", summarizeSeconds(seconds)},
                       {"max_residual_cm", job.maxResidualCm},
                       {"quality", spanQualityJson(job.quality)}};
    // Contact travel is also reported for BEFORE (which holds nothing), over the same intervals.
    SpanQuality reported = job.quality;
    if (!span) {
        const ContactSet set = detectFootContacts(version->model->clip);
        std::vector<ContactInterval> intervals;
        for (const FootContact& f : set.contacts)
            if (f.foot != c.effector && f.last > job.keyFrames.front() && f.first < job.keyFrames.back())
                intervals.push_back({f.foot, f.first, f.last});
        std::vector<Eigen::Vector3d> path(job.pathCm);
        path.insert(path.begin(), job.capturedTrajectory()[job.keyFrames.front()]);
        reported = measureSpan(version->model->clip, job.frames, job.keyFrames.front(), job.keyFrames.back(),
                               c.effector, path, job.keyFrames, intervals);
        out["quality"] = spanQualityJson(reported);
    } else {
        out["stop"] = spanStopName(job.spanStop);
        out["iterations"] = job.spanIterations;
        out["max_held_residual_cm"] = job.maxHeldResidualCm;
    }
    out["meets_targets"] = motionBarsJson(reported);
    out["meets_targets"]["keys_0_5_cm"] = reported.worstKeyErrorCm <= 0.5;
    return out;
}

const BenchRegistration editBench(
    "edit", "Span regeneration vs per-frame: smoothness, keys, contacts, time (43-frame spans)",
    [](const BenchContext& ctx) {
        nlohmann::json out = nlohmann::json::object();
        if (ctx.mocapDir.empty()) return nlohmann::json{{"skipped", "no CMU mocap folder"}};
        const int clips = ctx.quick ? 2 : static_cast<int>(std::size(kEditCases));
        nlohmann::json rows = nlohmann::json::array();
        std::vector<double> spanMedians;
        for (int ci = 0; ci < clips; ++ci) {
            const EditCase& c = kEditCases[ci];
            gp::TrainOptions options;
            options.activeSize = ctx.quick ? 100 : 200;
            options.outerIterations = ctx.quick ? 3 : 20;
            const gp::ModelVersionPtr version = gp::ModelVersion::make(
                gp::trainOnClip(loadClip(ctx.mocapDir + "/asf_amc/" + c.clip + ".amc"), options).model);
            for (const char* dir : {"raise", "sideways"})
                for (double cm : {10.0, 20.0, 40.0}) {
                    const Eigen::Vector3d offset =
                        std::string(dir) == "raise" ? Eigen::Vector3d(0, cm, 0) : Eigen::Vector3d(cm, 0, 0);
                    nlohmann::json row{{"clip", c.clip},
                                       {"why", c.why},
                                       {"effector", effectorName(c.effector)},
                                       {"keys", {c.firstKey, c.firstKey + 14, c.firstKey + 28, c.firstKey + 42}},
                                       {"edit", dir},
                                       {"cm", cm}};
                    row["before_per_frame"] =
                        runOne(version, c, offset, false, ctx.quick ? 1 : std::min(ctx.repeats, 3));
                    row["after_span"] = runOne(version, c, offset, true, ctx.repeats);
                    spanMedians.push_back(row["after_span"]["seconds"]["median"].get<double>());
                    rows.push_back(row);
                }
        }
        out["rows"] = rows;
        out["span_seconds_over_rows"] = summarizeSeconds(spanMedians);
        out["frames_regenerated"] = 41;
        return out;
    });

}  // namespace
}  // namespace mgp::app
