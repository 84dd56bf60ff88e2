#include "edit/regenerate_job.h"

#include <algorithm>
#include <utility>

namespace mgp {

RegenerateJob::RegenerateJob()
    : worker_(
          WorkerPolicy::kLatestRequest,
          [this](MotionEditJob& job, const std::atomic<bool>& cancel) { return run(job, cancel); },
          "regeneration failed: ") {}

std::string RegenerateJob::start(MotionEditJob job) {
    static const char* const kBusy = "a regeneration is already running";
    if (worker_.busy()) return kBusy;
    if (const std::string problem = job.validate(); !problem.empty()) return problem;
    done_ = 0;
    total_ = std::max(0, job.keyFrames.back() - job.keyFrames.front() - 1);
    if (!worker_.startIfIdle(std::move(job))) return kBusy;
    return "";
}

std::optional<MotionEditJob> RegenerateJob::take() {
    if (running()) return std::nullopt;
    return worker_.take();
}

JobOutcome<MotionEditJob> RegenerateJob::run(MotionEditJob& job, const std::atomic<bool>& cancel) {
    job.framesDone = &done_;
    job.cancel = &cancel;
    job.run();
    job.framesDone = nullptr;
    job.cancel = nullptr;
    if (job.cancelled) return {std::nullopt, "regeneration cancelled"};
    return {std::move(job), ""};
}

}  // namespace mgp
