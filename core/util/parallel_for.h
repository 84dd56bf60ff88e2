#pragma once
// One way to run work on several threads (docs/architecture.md, threads): body(w) for every
// worker w in [0, workers), w = 0 on the calling thread, the others on threads joined before
// return. How work is split among the workers is the body's business (a shared counter, or a
// fixed stride for determinism). An exception thrown by any worker reaches the caller (the first
// one thrown; the others are dropped) after every worker has finished.
#include <functional>

namespace mgp {

void parallelFor(int workers, const std::function<void(int worker)>& body);

// A thread-count option as workers: `threads` itself if > 0, else the hardware's thread count
// (at least 1).
int resolveWorkers(int threads);

}  // namespace mgp
