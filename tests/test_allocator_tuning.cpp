// keepFreedMemoryForReuse (core/util/allocator_tuning.h), which this runner's main() calls as
// motiongp's does: a freed 8 MB block stays in the process for the next allocation instead of
// going back to the kernel (glibc's default for a block that size: mmap on malloc, munmap on free).
// It needs a process of its own (ctest runs each case alone): earlier cases may have raised glibc's
// own threshold or left the heap with that much free memory.
#include <cstdlib>
#include <cstring>

#include "skip.h"
#include "test_support.h"
#include "util/address_sanitizer.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

TEST_CASE("allocator: a freed 8 MB block is kept for reuse, not given back to the kernel") {
#if !defined(__GLIBC__) || (__GLIBC__ == 2 && __GLIBC_MINOR__ < 33)
    MGP_SKIP("the setting is glibc's (mallopt), measured with mallinfo2 (glibc 2.33 or newer)");
#else
    if (MGP_ADDRESS_SANITIZER) MGP_SKIP("AddressSanitizer's allocator ignores mallopt");
    constexpr std::size_t kBytes = 8u << 20;
    const struct mallinfo2 before = mallinfo2();
    if (before.fordblks >= kBytes) MGP_SKIP("the heap already holds 8 MB free: run this case alone, as ctest does");
    char* block = static_cast<char*>(std::malloc(kBytes));
    REQUIRE(block != nullptr);
    std::memset(block, 1, kBytes);  // touch every page, as a matrix would
    const struct mallinfo2 held = mallinfo2();
    // From the heap (arena), not a separate mapping: glibc's default would map it (hblkhd).
    CHECK(held.hblkhd == before.hblkhd);
    CHECK(held.uordblks >= before.uordblks + kBytes);
    std::free(block);
    const struct mallinfo2 after = mallinfo2();
    // Freed into the heap and kept there: the next 8 MB comes without new pages.
    CHECK(after.fordblks >= kBytes);
#endif
}
