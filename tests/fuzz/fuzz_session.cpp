// libFuzzer target: the session loader (edit/session_file.h: sessionFromJsonText, in memory).
#include "edit/session_file.h"
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    mgp::fuzz::expectCleanFailure([&] { mgp::sessionFromJsonText(mgp::fuzz::text(data, size), "fuzz.mgsession"); });
    return 0;
}
