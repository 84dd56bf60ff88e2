// libFuzzer target: the BVH reader (io/bvh_reader.h, in memory).
#include "fuzz_common.h"
#include "io/bvh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    mgp::fuzz::expectCleanFailure([&] { mgp::parseBvh("fuzz.bvh", mgp::fuzz::text(data, size)); });
    return 0;
}
