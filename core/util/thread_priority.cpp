#include "util/thread_priority.h"

#include <algorithm>
#include <atomic>
#include <cerrno>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace mgp {

namespace {
std::atomic<bool> yieldOn{false};
thread_local bool lowered = false;
}  // namespace

void setBackgroundWorkersYield(bool on) { yieldOn.store(on); }
bool backgroundWorkersYield() { return yieldOn.load(); }

#if defined(__linux__)
// Linux keeps a nice value per thread: PRIO_PROCESS with a thread id names that thread only.
static id_t thisThreadId() { return static_cast<id_t>(syscall(SYS_gettid)); }

int thisThreadNice() {
    errno = 0;
    const int n = getpriority(PRIO_PROCESS, thisThreadId());
    return errno == 0 ? n : 0;
}

bool lowerThisThreadIfBackground() {
    if (lowered || !yieldOn.load()) return lowered;
    // Relative to what the thread inherited from the one that started it (a process started under
    // `nice` keeps its offset). Raising a nice value needs no privilege; a failure leaves it as it was.
    const int target = std::min(19, thisThreadNice() + kBackgroundNice);
    lowered = setpriority(PRIO_PROCESS, thisThreadId(), target) == 0;
    return lowered;
}
#else
int thisThreadNice() { return 0; }
bool lowerThisThreadIfBackground() { return false; }
#endif

}  // namespace mgp
