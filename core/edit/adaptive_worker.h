#pragma once
// AdaptiveWorker: runs adaptive updates (docs/maths.md §11) on a background thread and publishes
// each new immutable model version. Posting never blocks on the update; readers take the latest
// version with current() (a shared_ptr copy under a short lock) and keep solving on whatever
// version they hold. Updates run in posting order; each starts from the latest published version.
// Disabled, it ignores posts (a static model, for comparison). The thread and the FIFO are a
// BackgroundWorker's (core/util/background_worker.h) running every request in posting order.
#include <atomic>
#include <functional>
#include <mutex>
#include <variant>

#include "gp/train/adaptive_update.h"
#include "util/background_worker.h"

namespace mgp {

struct AdaptiveSample {
    Eigen::VectorXd x;
    Eigen::VectorXd yKept;
    int clipFrame = 0;
    long sequence = 0;  // set by post(): 1, 2, 3, … in posting order
};

struct AdaptiveReport {
    gp::AdaptiveUpdateResult result;
    int versionBefore = 0;
    double seconds = 0.0;
    int modelRows = 0;              // N after the update
    long sequence = 0;              // the sample's sequence number
    int frame = 0;                  // the sample's clip frame
    gp::ModelVersionPtr published;  // the current version once this sample is done
};

class AdaptiveWorker {
public:
    explicit AdaptiveWorker(gp::ModelVersionPtr initial, int scgIterations = 100);
    ~AdaptiveWorker() = default;  // the worker finishes the update in progress, drops queued ones
    AdaptiveWorker(const AdaptiveWorker&) = delete;
    AdaptiveWorker& operator=(const AdaptiveWorker&) = delete;

    void setEnabled(bool enabled);
    bool enabled() const;
    // Queues an update; returns the sample's sequence number (0 when disabled: nothing queued).
    long post(AdaptiveSample sample);
    long lastSequence() const;  // the latest number post() handed out (0 before the first)
    gp::ModelVersionPtr current() const;
    // Replace the published version (undo/redo, loading a model); pending updates are dropped.
    void reset(gp::ModelVersionPtr version);
    // Called on the worker thread after each update (accepted or rejected).
    void setListener(std::function<void(const AdaptiveReport&)> listener);
    // Blocks until every posted update has finished (tests, batch commands).
    void waitIdle() { worker_.waitIdle(); }
    // Holds queued updates back (tests: an update that is still pending, deterministically).
    void hold(bool on) { worker_.hold(on); }
    int pending() const { return worker_.pending(); }

private:
    struct Posted {
        AdaptiveSample sample;
        long generation = 0;  // reset() count at post: a sample posted before a reset never runs
    };
    JobOutcome<std::monostate> run(Posted& posted, const std::atomic<bool>& cancel);
    mutable std::mutex mutex_;  // guards the members below
    gp::ModelVersionPtr current_;
    std::function<void(const AdaptiveReport&)> listener_;
    int scgIterations_;
    bool enabled_ = true;
    long nextSequence_ = 1;
    long generation_ = 0;
    BackgroundWorker<Posted, std::monostate> worker_;  // last: joined before the members above go
};

}  // namespace mgp
