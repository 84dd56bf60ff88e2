// libFuzzer target: the AMC reader (io/amc_reader.h, in memory) against one fixed, valid ASF
// (35.asf of the shared mocap folder, or $MOTIONGP_FUZZ_ASF), so inputs reach the motion parser.
#include <cstdio>
#include <cstdlib>

#include "fuzz_common.h"
#include "io/amc_reader.h"

namespace {
const mgp::AsfSkeleton& skeleton() {
    static const mgp::AsfSkeleton asf = [] {
        try {
            return mgp::readAsf(mgp::fuzz::asfPath());
        } catch (const std::exception& e) {
            std::fprintf(stderr, "fuzz_amc: cannot read the ASF (%s); set MOTIONGP_FUZZ_ASF\n", e.what());
            std::exit(2);
        }
    }();
    return asf;
}
}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    skeleton();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const mgp::AsfSkeleton& asf = skeleton();
    mgp::fuzz::expectCleanFailure([&] { mgp::parseAmc("fuzz.amc", mgp::fuzz::text(data, size), asf); });
    return 0;
}
