// parallelFor (core/util/parallel_for.h): every worker runs once, on distinct threads, and an
// exception thrown in a worker reaches the caller after every worker finished.
#include <doctest/doctest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "util/parallel_for.h"

using namespace mgp;

TEST_CASE("parallelFor: each worker index runs once, worker 0 on the caller's thread") {
    std::vector<int> runs(4, 0);
    std::mutex mutex;
    std::set<std::thread::id> ids;
    std::thread::id zero;
    parallelFor(4, [&](int w) {
        const std::lock_guard<std::mutex> lock(mutex);
        ++runs[w];
        ids.insert(std::this_thread::get_id());
        if (w == 0) zero = std::this_thread::get_id();
    });
    CHECK(runs == std::vector<int>{1, 1, 1, 1});
    CHECK(ids.size() == 4);
    CHECK(zero == std::this_thread::get_id());
    int calls = 0;
    parallelFor(0, [&](int w) { calls += 1 + w; });  // fewer than 1 worker: one, on the caller
    CHECK(calls == 1);
}

TEST_CASE("parallelFor: an exception in a worker reaches the caller after every worker finished") {
    for (int thrower : {0, 2}) {
        std::atomic<int> finished{0};
        try {
            parallelFor(3, [&](int w) {
                if (w == thrower) throw std::runtime_error("worker " + std::to_string(w) + " failed");
                std::this_thread::sleep_for(std::chrono::milliseconds(20));
                ++finished;
            });
            FAIL("expected the worker's exception");
        } catch (const std::runtime_error& e) {
            CHECK(std::string(e.what()) == "worker " + std::to_string(thrower) + " failed");
        }
        CHECK(finished == 2);  // the others ran to the end and were joined
    }
}
