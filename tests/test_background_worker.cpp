// BackgroundWorker (core/util/background_worker.h): the two scheduling policies, one run at a
// time, cancellation, exceptions as messages, take-once, waitIdle, the joining destructor and the
// editor's priority policy.
// Every ordering is forced with gates (promises), never with sleeps or timings.
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <future>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "util/background_worker.h"
#include "util/thread_priority.h"

using namespace mgp;

namespace {

// A job that records every request it runs. Request 1 announces it has started and then holds
// the worker until the test releases it, so the test knows what is running and what is queued.
struct Recorder {
    std::mutex mutex;
    std::vector<int> ran;
    std::promise<void> started;
    std::promise<void> releasePromise;
    std::shared_future<void> release = releasePromise.get_future().share();

    JobOutcome<int> operator()(int request, const std::atomic<bool>&) {
        if (request == 1) {
            started.set_value();
            release.wait();
        }
        const std::lock_guard<std::mutex> lock(mutex);
        ran.push_back(request);
        return {request * 10, "ran " + std::to_string(request)};
    }
    std::vector<int> order() {
        const std::lock_guard<std::mutex> lock(mutex);
        return ran;
    }
};

using IntWorker = BackgroundWorker<int, int>;

IntWorker::Job jobOf(Recorder& r) {
    return [&r](int& request, const std::atomic<bool>& cancel) { return r(request, cancel); };
}

// Waits, without sleeping, until the running job sees its cancel flag.
void waitForCancel(const std::atomic<bool>& cancel) {
    while (!cancel.load()) std::this_thread::yield();
}

}  // namespace

TEST_CASE("background worker, latest request: a newer post supersedes one not yet started") {
    Recorder r;
    IntWorker worker(WorkerPolicy::kLatestRequest, jobOf(r));
    worker.post(1);
    r.started.get_future().wait();  // 1 is running, the queue is empty
    worker.post(2);
    worker.post(3);  // replaces 2, which never started
    CHECK(worker.pending() == 2);
    CHECK(worker.busy());
    r.releasePromise.set_value();
    worker.waitIdle();
    CHECK(r.order() == std::vector<int>{1, 3});
    CHECK(worker.take() == 30);  // the latest finished result
    CHECK(worker.message() == "ran 3");
}

TEST_CASE("background worker, every request: all run in posting order") {
    Recorder r;
    IntWorker worker(WorkerPolicy::kEveryRequest, jobOf(r));
    worker.post(1);
    r.started.get_future().wait();
    for (int i = 2; i <= 5; ++i) worker.post(i);
    CHECK(worker.pending() == 5);
    r.releasePromise.set_value();
    worker.waitIdle();
    CHECK(r.order() == std::vector<int>{1, 2, 3, 4, 5});
    CHECK(worker.pending() == 0);
    CHECK_FALSE(worker.busy());
}

TEST_CASE("background worker: startIfIdle refuses while a run is in progress and starts clean") {
    Recorder r;
    IntWorker worker(WorkerPolicy::kLatestRequest, jobOf(r));
    REQUIRE(worker.startIfIdle(7));
    worker.waitIdle();
    CHECK(worker.message() == "ran 7");
    REQUIRE(worker.startIfIdle(1));
    r.started.get_future().wait();
    CHECK_FALSE(worker.startIfIdle(8));  // one run at a time
    CHECK_FALSE(worker.take());          // the untaken 70 was dropped by the new start
    CHECK(worker.message().empty());
    r.releasePromise.set_value();
    worker.waitIdle();
    CHECK(r.order() == std::vector<int>{7, 1});
    CHECK(worker.take() == 10);
}

TEST_CASE("background worker: take hands the result out once, takeMessage clears the message") {
    Recorder r;
    IntWorker worker(WorkerPolicy::kEveryRequest, jobOf(r));
    CHECK_FALSE(worker.take());  // nothing before the first job
    worker.post(4);
    worker.waitIdle();
    const std::optional<int> first = worker.take();
    REQUIRE(first);
    CHECK(*first == 40);
    CHECK_FALSE(worker.take());
    CHECK(worker.message() == "ran 4");
    CHECK(worker.takeMessage() == "ran 4");
    CHECK(worker.message().empty());
}

TEST_CASE("background worker: a running job observes cancel, a later request does not") {
    std::promise<void> started;
    std::vector<bool> sawCancel;  // written only on the worker thread, read after waitIdle
    BackgroundWorker<int, int> worker(WorkerPolicy::kEveryRequest, [&](int& request, const std::atomic<bool>& cancel) {
        if (request == 1) {
            started.set_value();
            waitForCancel(cancel);
        }
        sawCancel.push_back(cancel.load());
        return JobOutcome<int>{request, cancel.load() ? "cancelled" : "done"};
    });
    worker.post(1);
    started.get_future().wait();
    worker.cancel();
    worker.waitIdle();
    CHECK(worker.message() == "cancelled");
    worker.post(2);
    worker.waitIdle();
    CHECK(worker.message() == "done");
    CHECK(sawCancel == std::vector<bool>{true, false});
}

TEST_CASE("background worker: a request cancelled before it starts runs with the flag already set") {
    std::promise<void> started;
    std::promise<void> releasePromise;
    std::shared_future<void> release = releasePromise.get_future().share();
    std::vector<bool> sawCancel;
    BackgroundWorker<int, int> worker(WorkerPolicy::kEveryRequest, [&](int& request, const std::atomic<bool>& cancel) {
        if (request == 1) {
            started.set_value();
            release.wait();
        }
        sawCancel.push_back(cancel.load());
        return JobOutcome<int>{request, ""};
    });
    worker.post(1);
    started.get_future().wait();
    worker.post(2);
    worker.cancel();  // 1 is running, 2 is queued: both are cancelled
    worker.post(3);   // posted after the cancel: not cancelled
    releasePromise.set_value();
    worker.waitIdle();
    CHECK(sawCancel == std::vector<bool>{true, true, false});
}

TEST_CASE("background worker: an exception in the job becomes the message and the worker goes on") {
    BackgroundWorker<int, int> worker(
        WorkerPolicy::kEveryRequest,
        [](int& request, const std::atomic<bool>&) -> JobOutcome<int> {
            if (request < 0) throw std::runtime_error("expected a request >= 0, found " + std::to_string(request));
            if (request == 0) throw 42;  // not a std::exception
            return {request, ""};
        },
        "job failed: ");
    worker.post(5);
    worker.waitIdle();
    worker.post(-1);
    worker.waitIdle();
    CHECK(worker.message() == "job failed: expected a request >= 0, found -1");
    CHECK(worker.take() == 5);  // a failed job leaves the previous result
    CHECK_FALSE(worker.take());
    worker.post(0);
    worker.waitIdle();
    CHECK(worker.message() == "job failed: unknown error");
    worker.post(6);
    worker.waitIdle();
    CHECK(worker.message().empty());
    CHECK(worker.take() == 6);
}

TEST_CASE("background worker: the destructor cancels the running job, drops the queue and joins") {
    std::promise<void> started;
    std::vector<int> ran;
    bool finished = false;
    {
        BackgroundWorker<int, int> worker(WorkerPolicy::kEveryRequest,
                                          [&](int& request, const std::atomic<bool>& cancel) {
                                              if (request == 1) {
                                                  started.set_value();
                                                  waitForCancel(cancel);  // only the destructor's cancel ends this job
                                              }
                                              ran.push_back(request);
                                              finished = true;
                                              return JobOutcome<int>{request, ""};
                                          });
        worker.post(1);
        started.get_future().wait();
        worker.post(2);
        worker.post(3);
    }  // joins here: the job has finished, the queued 2 and 3 never ran
    CHECK(finished);
    CHECK(ran == std::vector<int>{1});
}

TEST_CASE("background worker: waitIdle returns at once when nothing was posted, and after the last job otherwise") {
    std::atomic<int> done{0};
    BackgroundWorker<int, int> worker(WorkerPolicy::kEveryRequest, [&](int& request, const std::atomic<bool>&) {
        ++done;
        return JobOutcome<int>{request, ""};
    });
    worker.waitIdle();  // no thread yet: nothing to wait for
    CHECK_FALSE(worker.busy());
    for (int i = 0; i < 20; ++i) worker.post(i);
    worker.waitIdle();
    CHECK(done.load() == 20);
    CHECK(worker.pending() == 0);
    CHECK(worker.take() == 19);
}

TEST_CASE("background worker: dropQueued forgets requests not yet started, the running one finishes") {
    Recorder r;
    IntWorker worker(WorkerPolicy::kEveryRequest, jobOf(r));
    worker.post(1);
    r.started.get_future().wait();
    worker.post(2);
    worker.post(3);
    worker.dropQueued();
    CHECK(worker.pending() == 1);
    r.releasePromise.set_value();
    worker.waitIdle();
    CHECK(r.order() == std::vector<int>{1});
}

TEST_CASE("background worker: held, no queued request starts until released") {
    Recorder r;
    IntWorker worker(WorkerPolicy::kEveryRequest, jobOf(r));
    worker.hold(true);
    worker.post(2);
    worker.post(3);
    CHECK(worker.pending() == 2);
    worker.dropQueued();  // had either started, it would have run: held, neither did
    worker.post(4);
    worker.hold(false);
    worker.waitIdle();
    CHECK(r.order() == std::vector<int>{4});
    CHECK(worker.take() == 40);
}

TEST_CASE("background worker: with the editor's priority policy on, a job runs niced above its poster") {
    const auto niceOfAJob = [] {
        BackgroundWorker<int, int> worker(WorkerPolicy::kEveryRequest, [](int&, const std::atomic<bool>&) {
            // A thread the job starts inherits the worker's value (the Step-8 and regeneration pools).
            int inherited = 0;
            std::thread([&] { inherited = thisThreadNice(); }).join();
            return JobOutcome<int>{thisThreadNice() * 100 + inherited, ""};
        });
        worker.post(0);
        worker.waitIdle();
        return *worker.take();
    };
    const int poster = thisThreadNice();
    setBackgroundWorkersYield(false);
    CHECK(niceOfAJob() == poster * 100 + poster);
#if defined(__linux__)
    setBackgroundWorkersYield(true);
    const int niced = std::min(19, poster + kBackgroundNice);  // capped when the test runs under `nice`
    CHECK(niceOfAJob() == niced * 100 + niced);
    setBackgroundWorkersYield(false);
    CHECK(thisThreadNice() == poster);  // the poster itself is never lowered
#else
    MESSAGE("SKIPPED: per-thread nice values are Linux's");
#endif
}
