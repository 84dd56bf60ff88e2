#pragma once
// AdaptiveWorker: runs adaptive updates (§5.3) on a background thread and publishes each new
// immutable model version. Posting never blocks on the update; readers take the latest version
// with current() (a shared_ptr copy under a short lock) and keep solving on whatever version
// they hold. Updates run in posting order; each starts from the latest published version.
// Disabled, it ignores posts (a static model, for comparison).
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

#include "gp/adaptive_update.h"

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
    int modelRows = 0;          // N after the update
    long sequence = 0;          // the sample's sequence number
    int frame = 0;              // the sample's clip frame
    gp::ModelVersionPtr published;  // the current version once this sample is done
};

class AdaptiveWorker {
public:
    explicit AdaptiveWorker(gp::ModelVersionPtr initial, int scgIterations = 100);
    ~AdaptiveWorker();  // finishes the update in progress, drops queued ones
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
    void waitIdle();
    int pending() const;

private:
    void run();
    mutable std::mutex mutex_;
    std::condition_variable wake_, idle_;
    std::deque<AdaptiveSample> queue_;
    gp::ModelVersionPtr current_;
    std::function<void(const AdaptiveReport&)> listener_;
    int scgIterations_;
    bool enabled_ = true, busy_ = false, stop_ = false;
    long nextSequence_ = 1;
    std::thread thread_;
};

}  // namespace mgp
