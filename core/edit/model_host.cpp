#include "edit/model_host.h"

#include <cstdio>

namespace mgp {

ModelHost::ModelHost(std::function<void()> onAccepted) : onAccepted_(std::move(onAccepted)) {}

ModelHost::~ModelHost() { worker_.reset(); }  // joins the worker before the state its listener writes goes

void ModelHost::install(gp::ModelVersionPtr version) {
    worker_.reset();
    worker_ = std::make_unique<AdaptiveWorker>(version);
    worker_->setEnabled(adaptive_);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        status_.clear();
        history_.clear();
        versionLog_.reset(version, 0);
    }
    worker_->setListener([this](const AdaptiveReport& r) {
        std::lock_guard<std::mutex> lock(mutex_);
        versionLog_.record(r.sequence, r.published);
        if (r.result.accepted && onAccepted_) onAccepted_();
        AdaptiveHistoryEntry h;
        h.when = std::chrono::system_clock::now();
        h.frame = r.frame;
        h.accepted = r.result.accepted;
        h.diagnostic = r.result.diagnostic;
        h.seconds = r.seconds;
        h.versionBefore = r.versionBefore;
        h.versionAfter = r.published->number;
        h.rowsAfter = r.modelRows;
        h.activeSize = static_cast<int>(r.published->model->active.size());
        h.activeChanged = r.result.activeChanged;
        h.newPointActive = r.result.newPointActive;
        h.objectiveBefore = r.result.objectiveBefore;
        h.objectiveAfter = r.result.objectiveAfter;
        history_.push_back(std::move(h));
        char buf[160];
        std::snprintf(buf, sizeof buf, "update %s in %.2f s (N = %d)", r.result.accepted ? "accepted" : "rejected",
                      r.seconds, r.modelRows);
        status_ = buf;
        if (!r.result.accepted && !r.result.diagnostic.empty()) status_ += ": " + r.result.diagnostic;
    });
}

void ModelHost::clear() { worker_.reset(); }

gp::ModelVersionPtr ModelHost::current() const { return worker_ ? worker_->current() : nullptr; }

bool ModelHost::setAdaptiveEnabled(bool on) {
    const bool changed = adaptive_ != on;
    adaptive_ = on;
    if (worker_) worker_->setEnabled(on);
    return changed;
}

long ModelHost::post(AdaptiveSample sample) {
    if (!worker_) return 0;
    const long seq = worker_->post(std::move(sample));
    return seq > 0 ? seq : 0;
}

void ModelHost::noteRefused(int frame, const gp::ModelVersion& solvedOn, const std::string& reason) {
    std::lock_guard<std::mutex> lock(mutex_);
    AdaptiveHistoryEntry h;
    h.when = std::chrono::system_clock::now();
    h.frame = frame;
    h.accepted = false;
    h.diagnostic = "refused: " + reason;
    h.versionBefore = h.versionAfter = solvedOn.number;
    h.rowsAfter = solvedOn.model->N();
    h.activeSize = static_cast<int>(solvedOn.model->active.size());
    history_.push_back(std::move(h));
    status_ = "pose kept as an edit, not added to the model: " + reason;
}

std::string ModelHost::status() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return status_;
}

int ModelHost::updates() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return static_cast<int>(history_.size());
}

std::vector<AdaptiveHistoryEntry> ModelHost::history() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return history_;
}

void ModelHost::pruneVersions(long oldestUnresolvedSample) {
    // Samples still queued have higher sequence numbers than any entry pruned here, so the log
    // keeps what they will need.
    const long oldest = std::min(oldestUnresolvedSample, worker_ ? worker_->lastSequence() + 1 : LONG_MAX);
    std::lock_guard<std::mutex> lock(mutex_);
    versionLog_.pruneBefore(oldest);
}

void ModelHost::resolveStep(EditStep& step) {
    if (step.modelResolved) return;
    step.modelResolved = true;
    if (step.samples.empty() || !worker_) return;
    worker_->waitIdle();  // the step's own updates must have published before we can undo them
    std::lock_guard<std::mutex> lock(mutex_);
    step.modelBefore = versionLog_.before(step.samples.front());
    step.modelAfter = worker_->current();
    if (!step.modelBefore) step.modelAfter = nullptr;  // unknown: leave the model alone
}

void ModelHost::restoreHistory(std::vector<AdaptiveHistoryEntry> entries) {
    std::lock_guard<std::mutex> lock(mutex_);
    history_ = std::move(entries);
}

bool ModelHost::restore(const gp::ModelVersionPtr& version) {
    if (!version || !worker_ || worker_->current() == version) return false;
    worker_->waitIdle();
    worker_->reset(version);
    // Samples posted from now on start from this version.
    std::lock_guard<std::mutex> lock(mutex_);
    versionLog_.record(worker_->lastSequence(), version);
    return true;
}

void ModelHost::waitIdle() {
    if (worker_) worker_->waitIdle();
}

}  // namespace mgp
