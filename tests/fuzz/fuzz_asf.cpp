// libFuzzer target: the ASF reader (io/asf_reader.h, in memory).
#include "fuzz_common.h"
#include "io/asf_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    mgp::fuzz::expectCleanFailure([&] { mgp::parseAsf("fuzz.asf", mgp::fuzz::text(data, size)); });
    return 0;
}
