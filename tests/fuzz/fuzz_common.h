#pragma once
// Shared by the libFuzzer targets: runs one loader on the input and lets only the loaders'
// documented failure (mgp::ParseError, a std::runtime_error) through. Anything else — another
// exception type (std::bad_alloc from a huge allocation, std::out_of_range, nlohmann::json's own
// exceptions, ...), a crash or a sanitizer report — aborts, so libFuzzer saves the input.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <typeinfo>

#include "io/parse_error.h"

namespace mgp::fuzz {

template <class F>
void expectCleanFailure(F&& load) {
    try {
        load();
    } catch (const mgp::ParseError&) {
    } catch (const std::runtime_error&) {
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz: unexpected exception %s: %s\n", typeid(e).name(), e.what());
        std::abort();
    } catch (...) {
        std::fprintf(stderr, "fuzz: unexpected non-std exception\n");
        std::abort();
    }
}

inline std::string text(const uint8_t* data, std::size_t size) {
    return std::string(reinterpret_cast<const char*>(data), size);
}

// The ASF the AMC target parses against: $MOTIONGP_FUZZ_ASF, else 35.asf of the shared mocap
// folder (compiled in). Never committed to the repository.
inline std::string asfPath() {
    if (const char* p = std::getenv("MOTIONGP_FUZZ_ASF")) return p;
#ifdef MOTIONGP_FUZZ_MOCAP
    return std::string(MOTIONGP_FUZZ_MOCAP) + "/asf_amc/35.asf";
#else
    return "../shared/mocap/asf_amc/35.asf";
#endif
}

}  // namespace mgp::fuzz
