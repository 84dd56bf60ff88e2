#pragma once
// Honest skips: a test case that cannot run here says why and is reported by ctest as Skipped,
// never as Passed. markSkipped records the reason and prints "SKIPPED: <reason>"; when ctest runs
// the case alone (--test-case=NAME) and nothing failed, the runner (doctest_main.cpp) exits with
// kSkipExitCode, which the test registration maps to ctest's Skipped (SKIP_RETURN_CODE).
#include <sstream>
#include <string>

namespace mgp::test {

constexpr int kSkipExitCode = 77;
void markSkipped(const std::string& reason);

}  // namespace mgp::test

// Records the reason (stream syntax: MGP_MARK_SKIPPED("no folder at " << dir)) without leaving.
#define MGP_MARK_SKIPPED(streamed)                        \
    do {                                                  \
        std::ostringstream mgp_skip_reason_;              \
        mgp_skip_reason_ << streamed;                     \
        ::mgp::test::markSkipped(mgp_skip_reason_.str()); \
    } while (0)
// Skips the rest of the calling test case (use it in the TEST_CASE body itself).
#define MGP_SKIP(streamed)          \
    do {                            \
        MGP_MARK_SKIPPED(streamed); \
        return;                     \
    } while (0)
