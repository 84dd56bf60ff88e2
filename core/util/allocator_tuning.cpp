#include "util/allocator_tuning.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace mgp {

void keepFreedMemoryForReuse() {
#if defined(__GLIBC__)
    // Setting either one also turns off glibc's own adjustment of both (mallopt(3)).
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
    mallopt(M_TRIM_THRESHOLD, 128 * 1024 * 1024);
#endif
}

}  // namespace mgp
