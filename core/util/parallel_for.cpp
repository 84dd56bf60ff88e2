#include "util/parallel_for.h"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace mgp {

int resolveWorkers(int threads) {
    return threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void parallelFor(int workers, const std::function<void(int worker)>& body) {
    if (workers < 1) workers = 1;
    std::exception_ptr first;
    std::mutex firstMutex;
    auto guarded = [&](int w) {
        try {
            body(w);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(firstMutex);
            if (!first) first = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(static_cast<std::size_t>(workers - 1));
    for (int w = 1; w < workers; ++w) pool.emplace_back(guarded, w);
    guarded(0);
    for (auto& th : pool) th.join();
    if (first) std::rethrow_exception(first);
}

}  // namespace mgp
