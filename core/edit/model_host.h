#pragma once
// The document's model host: the adaptive worker on the latest model version, the adaptive
// switch, the history and status of updates the Model panel shows, and the version log that
// undo reads (which version a step's updates started from). The worker's listener runs on the
// worker thread, so everything it writes is under one mutex.
#include <chrono>
#include <climits>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "edit/adaptive_worker.h"
#include "edit/edit_history.h"
#include "gp/model_version.h"

namespace mgp {

// One adaptive update as the Model panel lists it (when, how long, how the active set changed).
struct AdaptiveHistoryEntry {
    std::chrono::system_clock::time_point when;  // when the update finished
    int frame = 0;                               // the edited clip frame (0-based)
    bool accepted = false;
    std::string diagnostic;                              // why it was rejected ("ok" if accepted)
    double seconds = 0.0;                                // how long the update took
    int versionBefore = 0, versionAfter = 0;             // equal when rejected
    int rowsAfter = 0;                                   // N after the update
    int activeSize = 0;                                  // M after the update
    int activeChanged = 0;                               // points that entered the active set
    bool newPointActive = false;                         // the edited pose itself entered it
    double objectiveBefore = 0.0, objectiveAfter = 0.0;  // L_GP around Step 6
};

class ModelHost {
public:
    // `onAccepted` runs on the worker thread after each accepted update (a change to save).
    explicit ModelHost(std::function<void()> onAccepted = nullptr);
    ~ModelHost();
    ModelHost(const ModelHost&) = delete;
    ModelHost& operator=(const ModelHost&) = delete;

    // A new model: the worker restarts on it; history, status and version log start over.
    void install(gp::ModelVersionPtr version);
    void clear();  // no model
    bool hasModel() const { return worker_ != nullptr; }
    gp::ModelVersionPtr current() const;  // the latest published version (null if none)

    // Returns whether the switch changed.
    bool setAdaptiveEnabled(bool on);
    bool adaptiveEnabled() const { return adaptive_; }
    bool updating() const { return worker_ && worker_->enabled(); }  // a model, adaptive on
    int pending() const { return worker_ ? worker_->pending() : 0; }
    // Posts a pose to learn; its sequence number (> 0) or 0 when nothing was posted.
    long post(AdaptiveSample sample);
    // A pose kept as an edit but not taught to the model: listed in the history, said in the status.
    void noteRefused(int frame, const gp::ModelVersion& solvedOn, const std::string& reason);

    std::string status() const;  // the last update's outcome, "" if none yet
    int updates() const;
    std::vector<AdaptiveHistoryEntry> history() const;  // oldest first
    // The history of an earlier sitting (a session reopened onto the model it saved): the
    // table lists those updates again; the status line stays empty until the next one.
    void restoreHistory(std::vector<AdaptiveHistoryEntry> entries);

    // Undo support: frees versions no step can ask for any more (`oldestUnresolvedSample` from
    // EditHistory), fills a step's model before/after once its updates have published, and
    // puts a version back (false when it is already current or there is no model).
    void pruneVersions(long oldestUnresolvedSample);
    void resolveStep(EditStep& step);
    bool restore(const gp::ModelVersionPtr& version);

    void waitIdle();  // every posted update finished
    // Holds posted updates back until released (tests; see BackgroundWorker::hold).
    void holdUpdates(bool on) {
        if (worker_) worker_->hold(on);
    }

private:
    std::function<void()> onAccepted_;
    std::unique_ptr<AdaptiveWorker> worker_;
    bool adaptive_ = true;
    mutable std::mutex mutex_;  // guards the three below (the worker's listener writes them)
    std::string status_;
    std::vector<AdaptiveHistoryEntry> history_;
    ModelVersionLog versionLog_;
};

}  // namespace mgp
