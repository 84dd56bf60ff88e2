// Every input a fuzz target ever crashed on (tests/fuzz/regressions/<target>/, see
// tests/fuzz/run_fuzz.sh) goes through its loader again here, in the normal build: each must
// load or fail with a ParseError — never crash, hang, allocate without bound or throw anything
// else.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "gp/model_file.h"
#include "io/amc_reader.h"
#include "io/asf_reader.h"
#include "io/bvh_reader.h"
#include "io/parse_error.h"
#include "session/session_file.h"
#include "skip.h"
#include "test_support.h"

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> regressionInputs(const std::string& target) {
    const fs::path dir = fs::path(MOTIONGP_TEST_SOURCE_DIR) / "fuzz" / "regressions" / target;
    std::vector<fs::path> files;
    std::error_code ec;
    if (fs::is_directory(dir, ec))
        for (const auto& e : fs::directory_iterator(dir))
            if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::string bytesOf(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

// Loads every regression input of `target`; a load or a ParseError is fine. Returns how many.
std::size_t checkAll(const std::string& target, const std::function<void(const std::string&)>& load) {
    const std::vector<fs::path> inputs = regressionInputs(target);
    for (const fs::path& p : inputs) {
        INFO("regression input ", p.string());
        const std::string text = bytesOf(p);
        try {
            load(text);
        } catch (const mgp::ParseError& e) {
            // The loaders' one documented failure; it must say where and what.
            CHECK(std::string(e.what()).find("expected") != std::string::npos);
        }
    }
    return inputs.size();
}

#define MGP_NONE_YET(target) \
    MGP_SKIP("no " target " inputs in tests/fuzz/regressions/" target " yet (the fuzzer has not broken that loader)")

}  // namespace

TEST_CASE("fuzz regressions: ASF inputs load or give a ParseError") {
    if (checkAll("asf", [](const std::string& t) { mgp::parseAsf("fuzz.asf", t); }) == 0) MGP_NONE_YET("asf");
}

TEST_CASE("fuzz regressions: AMC inputs (against 35.asf) load or give a ParseError") {
    const mgp::AsfSkeleton asf = mgp::readAsf(mgp::test::mocap("asf_amc/35.asf"));
    if (checkAll("amc", [&](const std::string& t) { mgp::parseAmc("fuzz.amc", t, asf); }) == 0) MGP_NONE_YET("amc");
}

TEST_CASE("fuzz regressions: BVH inputs load or give a ParseError") {
    if (checkAll("bvh", [](const std::string& t) { mgp::parseBvh("fuzz.bvh", t); }) == 0) MGP_NONE_YET("bvh");
}

TEST_CASE("fuzz regressions: model files load or give a ParseError") {
    if (checkAll("model", [](const std::string& t) { mgp::gp::modelFromJsonText(t, "fuzz.json"); }) == 0)
        MGP_NONE_YET("model");
}

TEST_CASE("fuzz regressions: session files load or give a ParseError") {
    // As tests/fuzz/fuzz_session.cpp: a synthetic-walk session's clip is built too.
    const std::size_t n = checkAll("session", [](const std::string& t) {
        const mgp::SessionData s = mgp::sessionFromJsonText(t, "fuzz.mgsession");
        if (s.syntheticClip && !s.model) mgp::loadSessionClip(s, "fuzz.mgsession");
    });
    if (n == 0) MGP_NONE_YET("session");
}
