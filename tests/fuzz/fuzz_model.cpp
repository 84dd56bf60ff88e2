// libFuzzer target: the model loader (gp/model_file.h: modelFromJsonText, in memory).
#include "fuzz_common.h"
#include "gp/model_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    mgp::fuzz::expectCleanFailure([&] { mgp::gp::modelFromJsonText(mgp::fuzz::text(data, size), "fuzz.json"); });
    return 0;
}
