#include "edit/adaptive_worker.h"

#include <chrono>

namespace mgp {

AdaptiveWorker::AdaptiveWorker(gp::ModelVersionPtr initial, int scgIterations)
    : current_(std::move(initial)),
      scgIterations_(scgIterations),
      worker_(WorkerPolicy::kEveryRequest,
              [this](Posted& posted, const std::atomic<bool>& cancel) { return run(posted, cancel); }) {}

void AdaptiveWorker::setEnabled(bool enabled) {
    std::lock_guard<std::mutex> lock(mutex_);
    enabled_ = enabled;
}

bool AdaptiveWorker::enabled() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return enabled_;
}

long AdaptiveWorker::post(AdaptiveSample sample) {
    // Numbered and queued under one lock, so sequence numbers follow the queue's order.
    std::lock_guard<std::mutex> lock(mutex_);
    if (!enabled_) return 0;
    const long sequence = sample.sequence = nextSequence_++;
    worker_.post(Posted{std::move(sample), generation_});
    return sequence;
}

long AdaptiveWorker::lastSequence() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return nextSequence_ - 1;
}

gp::ModelVersionPtr AdaptiveWorker::current() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return current_;
}

void AdaptiveWorker::reset(gp::ModelVersionPtr version) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        ++generation_;
        current_ = std::move(version);
    }
    worker_.dropQueued();
}

void AdaptiveWorker::setListener(std::function<void(const AdaptiveReport&)> listener) {
    std::lock_guard<std::mutex> lock(mutex_);
    listener_ = std::move(listener);
}

JobOutcome<std::monostate> AdaptiveWorker::run(Posted& posted, const std::atomic<bool>&) {
    const AdaptiveSample& sample = posted.sample;
    std::unique_lock<std::mutex> lock(mutex_);
    if (posted.generation != generation_) return {};  // reset() dropped it while it was being dequeued
    const gp::ModelVersionPtr base = current_;
    lock.unlock();
    const auto t0 = std::chrono::steady_clock::now();
    AdaptiveReport report;
    report.versionBefore = base->number;
    report.sequence = sample.sequence;
    report.frame = sample.clipFrame;
    report.result = gp::adaptiveUpdate(*base, sample.x, sample.yKept, sample.clipFrame, scgIterations_);
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    lock.lock();
    // Publish only if nobody replaced the version meanwhile (undo/redo, a new model).
    if (report.result.accepted && current_ == base) current_ = report.result.version;
    report.modelRows = current_->model->N();
    report.published = current_;
    const auto listener = listener_;
    lock.unlock();
    // The worker is idle only once the listener has seen the update: waitIdle() callers rely on it.
    if (listener) listener(report);
    return {};
}

}  // namespace mgp
