#pragma once
// RegenerateJob: runs a MotionEditJob (motion/motion_edit.h) on a background thread with
// progress and cancellation, so the editor never blocks on it. The job is a path edit's span or
// the falloff that spreads a drag or a whole-pose change over its neighbours
// (motion/drag_falloff.h); its inner frames are solved as one problem (EditSolver::kSpan, the
// default and what the editor runs; motion/span_solver.h), or each alone by the learned IK if
// the job asks for kPerFrame. The UI polls progress every frame and takes the finished job once.
// The thread, the cancel flag and the take-once result are a BackgroundWorker's
// (core/util/background_worker.h), one run at a time.
#include <atomic>
#include <optional>
#include <string>

#include "motion/motion_edit.h"
#include "util/background_worker.h"

namespace mgp {

class RegenerateJob {
public:
    RegenerateJob();
    ~RegenerateJob() = default;  // the worker cancels and joins
    RegenerateJob(const RegenerateJob&) = delete;
    RegenerateJob& operator=(const RegenerateJob&) = delete;

    // "" or why not (a job is running, the edit is invalid).
    std::string start(MotionEditJob job);
    void cancel() { worker_.cancel(); }
    bool running() const { return worker_.busy(); }
    int framesDone() const { return done_.load(); }
    int framesTotal() const { return total_.load(); }
    // The finished job, once (none while running, after a cancel or an error).
    std::optional<MotionEditJob> take();
    // "" or the last job's outcome when it produced nothing (cancelled, failed), once.
    std::string takeMessage() { return worker_.takeMessage(); }
    void join() { worker_.waitIdle(); }

private:
    JobOutcome<MotionEditJob> run(MotionEditJob& job, const std::atomic<bool>& cancel);
    std::atomic<int> done_{0}, total_{0};
    BackgroundWorker<MotionEditJob, MotionEditJob> worker_;  // last: joined before the members above go
};

}  // namespace mgp
