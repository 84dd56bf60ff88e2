// The doctest runner for every test binary. ctest runs each case alone as
// `--test-case=NAME`; a name ctest cannot pass through (one with ';', which CMake splits on)
// would match no case and "pass" without running anything. This main fails such a run instead.
// It also turns a skipped case (skip.h) into ctest's Skipped: exit code 77 when the case ran alone.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include "skip.h"
#include "util/allocator_tuning.h"

namespace {

// Remembers how many test cases passed the filters (the only thing it reports).
struct RunCounter : doctest::IReporter {
    explicit RunCounter(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats& stats) override { selected = int(stats.numTestCasesPassingFilters); }
    void test_case_start(const doctest::TestCaseData&) override {}
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats&) override {}
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
    static inline int selected = -1;
};

std::mutex skipMutex;
std::vector<std::string> skipReasons;

}  // namespace

void mgp::test::markSkipped(const std::string& reason) {
    std::printf("SKIPPED: %s\n", reason.c_str());
    std::fflush(stdout);
    const std::lock_guard<std::mutex> lock(skipMutex);
    skipReasons.push_back(reason);
}

REGISTER_LISTENER("run-counter", 1, RunCounter);

int main(int argc, char** argv) {
    mgp::keepFreedMemoryForReuse();  // as motiongp's main does, so the tests run the code as the program does
    doctest::Context context(argc, argv);
    const int rc = context.run();
    if (context.shouldExit()) return rc;
    bool filtered = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        filtered |= a.rfind("--test-case=", 0) == 0 || a.rfind("-tc=", 0) == 0;
    }
    if (rc == 0 && filtered && RunCounter::selected == 0) {
        std::fprintf(stderr, "no test case matched the --test-case filter (is there a ';' in a test name?)\n");
        return 1;
    }
    if (rc == 0 && !skipReasons.empty()) {
        std::printf("%zu skip(s): %s\n", skipReasons.size(), skipReasons.front().c_str());
        // One case run alone (ctest's way) is reported as Skipped; a whole-binary run stays 0.
        if (filtered && RunCounter::selected == 1) return mgp::test::kSkipExitCode;
    }
    return rc;
}
