#pragma once
// The C library's allocator, set up once at program start for the way this program allocates
// (docs/architecture.md, §4 "Memory"): many short-lived matrices of 0.1–30 MB in loops (the
// full-GP yardstick's N×N kernel matrices, training's N×M blocks, the span solver's bands).

namespace mgp {

// glibc's defaults give such blocks back to the kernel as soon as the free memory at the top of
// a heap passes twice the largest mapped block freed so far, and the next iteration takes them
// again as fresh zeroed pages: `motiongp evaluate` spent 40 % of its time in the kernel. This
// keeps up to 128 MB of freed memory per heap (the main one and each thread's) for reuse, and puts
// blocks under 32 MB (glibc's ceiling for the threshold on 64-bit) in the heaps. A no-op off glibc
// and under AddressSanitizer, whose allocator ignores these settings. Call it first thing in main().
void keepFreedMemoryForReuse();

}  // namespace mgp
