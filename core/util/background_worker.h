#pragma once
// BackgroundWorker<Request, Result>: one worker thread that runs a job function on posted
// requests, so the UI thread never waits on slow work (docs/architecture.md §4, threads). It owns
// what every background job needs and nothing job-specific:
//   - the thread: started by the first post, stopped and joined by the destructor (which drops
//     queued requests and cancels the running one);
//   - scheduling: kLatestRequest (a newer post replaces a request not yet started; the running
//     job finishes) or kEveryRequest (every request runs, in posting order); startIfIdle() posts
//     only when nothing is queued or running (one run at a time);
//   - cancellation: cancel() sets the std::atomic<bool> the running job reads and marks the
//     queued requests cancelled, so a request posted later is never cancelled by an earlier call;
//   - the outcome: a result taken once and a message; an exception thrown by the job becomes the
//     message (failurePrefix + what()) and the worker goes on serving requests;
//   - waitIdle(): blocks until nothing is queued or running (tests, scripts, batch commands);
//   - priority: in the editor, jobs run below the UI thread (util/thread_priority.h).
// Progress reporting stays with each job: it is different for every one.
// A wrapper whose job function touches the wrapper's own members must declare its
// BackgroundWorker member last, so the thread is joined before those members are destroyed.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "util/thread_priority.h"

namespace mgp {

enum class WorkerPolicy {
    kLatestRequest,  // keep only the newest request not yet started
    kEveryRequest,   // run every request, first posted first
};

// What one job hands back: a result to take once (none: the previous result stays) and a message
// ("" when there is nothing to say). A new message always replaces the previous one.
template <class Result>
struct JobOutcome {
    std::optional<Result> result;
    std::string message;
};

template <class Request, class Result>
class BackgroundWorker {
public:
    using Outcome = JobOutcome<Result>;
    // Runs on the worker thread; may read `cancel` at any time and stop early.
    using Job = std::function<Outcome(Request& request, const std::atomic<bool>& cancel)>;

    BackgroundWorker(WorkerPolicy policy, Job job, std::string failurePrefix = "")
        : policy_(policy), job_(std::move(job)), failurePrefix_(std::move(failurePrefix)) {}

    ~BackgroundWorker() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stop_ = true;
            queue_.clear();
            cancel_.store(true);
        }
        wake_.notify_all();
        if (thread_.joinable()) thread_.join();
    }

    BackgroundWorker(const BackgroundWorker&) = delete;
    BackgroundWorker& operator=(const BackgroundWorker&) = delete;

    // Queues a request under the worker's policy.
    void post(Request request) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            enqueue(std::move(request));
        }
        wake_.notify_one();
    }

    // Posts only when nothing is queued or running, and then forgets the previous outcome (a new
    // run starts clean). Returns whether it posted.
    bool startIfIdle(Request request) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (working_ || !queue_.empty()) return false;
            result_.reset();
            message_.clear();
            enqueue(std::move(request));
        }
        wake_.notify_one();
        return true;
    }

    // Asks the running job to stop, and every queued request to stop as soon as it starts.
    void cancel() {
        std::lock_guard<std::mutex> lock(mutex_);
        for (Entry& e : queue_) e.cancelled = true;
        cancel_.store(true);
    }

    // While held, queued requests wait and none starts (the running one finishes); waitIdle()
    // would then wait for the release. Tests use it to look at a state that is otherwise a race.
    void hold(bool on) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            held_ = on;
        }
        wake_.notify_all();
    }

    // Drops the requests not yet started; the running job goes on.
    void dropQueued() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            queue_.clear();
        }
        idle_.notify_all();
    }

    bool busy() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return working_ || !queue_.empty();
    }

    // Requests queued plus the one running.
    int pending() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return static_cast<int>(queue_.size()) + (working_ ? 1 : 0);
    }

    void waitIdle() {
        std::unique_lock<std::mutex> lock(mutex_);
        idle_.wait(lock, [this] { return !working_ && queue_.empty(); });
    }

    // The latest finished result, once (none before the first, or when already taken).
    std::optional<Result> take() {
        std::lock_guard<std::mutex> lock(mutex_);
        std::optional<Result> out = std::move(result_);
        result_.reset();
        return out;
    }

    // The latest finished job's message; takeMessage() also clears it.
    std::string message() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return message_;
    }
    std::string takeMessage() {
        std::lock_guard<std::mutex> lock(mutex_);
        return std::exchange(message_, std::string());
    }

private:
    struct Entry {
        Request request;
        bool cancelled = false;
    };

    // Called with mutex_ held.
    void enqueue(Request request) {
        if (policy_ == WorkerPolicy::kLatestRequest) queue_.clear();
        queue_.push_back(Entry{std::move(request), false});
        if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
    }

    void run() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            wake_.wait(lock, [this] { return stop_ || (!held_ && !queue_.empty()); });
            if (stop_) return;
            Entry entry = std::move(queue_.front());
            queue_.pop_front();
            working_ = true;
            cancel_.store(entry.cancelled);
            lock.unlock();
            lowerThisThreadIfBackground();  // the editor's frame first (util/thread_priority.h)
            Outcome outcome = runJob(entry.request);
            lock.lock();
            if (outcome.result) result_ = std::move(outcome.result);
            message_ = std::move(outcome.message);
            working_ = false;
            idle_.notify_all();
        }
    }

    // An exception must not escape the thread (std::terminate): it becomes the outcome's message.
    Outcome runJob(Request& request) noexcept {
        try {
            return job_(request, cancel_);
        } catch (const std::exception& e) {
            return Outcome{std::nullopt, failurePrefix_ + e.what()};
        } catch (...) {
            return Outcome{std::nullopt, failurePrefix_ + "unknown error"};
        }
    }

    const WorkerPolicy policy_;
    const Job job_;
    const std::string failurePrefix_;
    mutable std::mutex mutex_;
    std::condition_variable wake_, idle_;
    std::deque<Entry> queue_;
    std::atomic<bool> cancel_{false};
    bool working_ = false, stop_ = false, held_ = false;
    std::optional<Result> result_;
    std::string message_;
    std::thread thread_;  // last: started lazily, joined before the members above go
};

}  // namespace mgp
