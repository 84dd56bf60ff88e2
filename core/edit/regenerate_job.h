#pragma once
// RegenerateJob: runs a MotionEditJob (per-frame learned IK along an edited path) on a
// background thread with progress and cancellation, so the editor never blocks on it. The UI
// polls progress every frame and takes the finished job once.
#include <atomic>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "motion/motion_edit.h"

namespace mgp {

class RegenerateJob {
public:
    RegenerateJob() = default;
    ~RegenerateJob();  // cancels and joins
    RegenerateJob(const RegenerateJob&) = delete;
    RegenerateJob& operator=(const RegenerateJob&) = delete;

    // "" or why not (a job is running, the edit is invalid).
    std::string start(MotionEditJob job);
    void cancel();
    bool running() const { return running_.load(); }
    int framesDone() const { return done_.load(); }
    int framesTotal() const { return total_.load(); }
    // The finished job, once (none while running, after a cancel or an error).
    std::optional<MotionEditJob> take();
    // "" or the last job's outcome when it produced nothing (cancelled, failed), once.
    std::string takeMessage();
    void join();

private:
    std::thread thread_;
    std::atomic<bool> cancel_{false}, running_{false};
    std::atomic<int> done_{0}, total_{0};
    mutable std::mutex mutex_;
    std::optional<MotionEditJob> result_;
    std::string message_;
};

}  // namespace mgp
