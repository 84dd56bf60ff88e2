#include "edit/adaptive_worker.h"

#include <chrono>

namespace mgp {

AdaptiveWorker::AdaptiveWorker(gp::ModelVersionPtr initial, int scgIterations)
    : current_(std::move(initial)), scgIterations_(scgIterations), thread_([this] { run(); }) {}

AdaptiveWorker::~AdaptiveWorker() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
        queue_.clear();
    }
    wake_.notify_all();
    thread_.join();
}

void AdaptiveWorker::setEnabled(bool enabled) {
    std::lock_guard<std::mutex> lock(mutex_);
    enabled_ = enabled;
}

bool AdaptiveWorker::enabled() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return enabled_;
}

long AdaptiveWorker::post(AdaptiveSample sample) {
    long sequence = 0;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!enabled_) return 0;
        sequence = sample.sequence = nextSequence_++;
        queue_.push_back(std::move(sample));
    }
    wake_.notify_one();
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
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.clear();
    current_ = std::move(version);
}

void AdaptiveWorker::setListener(std::function<void(const AdaptiveReport&)> listener) {
    std::lock_guard<std::mutex> lock(mutex_);
    listener_ = std::move(listener);
}

void AdaptiveWorker::waitIdle() {
    std::unique_lock<std::mutex> lock(mutex_);
    idle_.wait(lock, [this] { return queue_.empty() && !busy_; });
}

int AdaptiveWorker::pending() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return static_cast<int>(queue_.size()) + (busy_ ? 1 : 0);
}

void AdaptiveWorker::run() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
        wake_.wait(lock, [this] { return stop_ || !queue_.empty(); });
        if (stop_) return;
        AdaptiveSample sample = std::move(queue_.front());
        queue_.pop_front();
        busy_ = true;
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
        if (listener) listener(report);
        lock.lock();
        // Idle only once the listener has seen the update: waitIdle() callers rely on it.
        busy_ = false;
        idle_.notify_all();
    }
}

}  // namespace mgp
