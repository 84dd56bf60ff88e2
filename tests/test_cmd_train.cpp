// `motiongp train` end to end: JSON contract, BVH refusal, usage errors, byte-identical models.
#include <doctest/doctest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "test_support.h"

namespace {

// The shared CLI runner (stdout, stderr, exit code) of test_support.
struct Run {
    int status = -1;
    std::string out, err;
};

Run run(const std::string& args) {
    const mgp::test::CliResult r = mgp::test::runCli(args);
    return {r.exitCode, r.out, r.err};
}

const std::string kMocap = MOTIONGP_TEST_MOCAP;

}  // namespace

TEST_CASE("cmd train: --json contract and deterministic model files") {
    const std::string dir = mgp::test::scratchDir("cmd_train");
    std::filesystem::create_directories(dir);
    const std::string args =
        kMocap + "/asf_amc/16_35.amc --frames 11:130 --step 3 --active 25 --iters 2 --scg-iters 20 --json";
    const Run a = run("train " + args + " --out " + dir + "/a.json");
    REQUIRE(a.status == 0);
    const auto j = nlohmann::json::parse(a.out);
    CHECK(j["model"] == "fas");
    CHECK(j["N"] == 40);
    CHECK(j["D"].get<int>() > 0);
    CHECK(j["M"] == 25);
    CHECK(j["iterations"] == 2);
    CHECK(j["converged"].is_boolean());
    CHECK(j["L_init"].is_number());
    for (const char* p : {"alpha", "beta", "gamma", "eta"}) CHECK(j["params"][p].is_number());
    REQUIRE(j["log"].size() == 2);
    for (const char* k : {"iter", "L", "max_delta_raw", "max_delta_log", "active_overlap"})
        CHECK(j["log"][0].contains(k));
    CHECK(j["log"][0]["L"].get<double>() < j["L_init"].get<double>());
    CHECK(j["seconds"].is_number());
    CHECK(a.err.find("iter 2/2") != std::string::npos);  // the progress bar

    const Run b = run("train " + args + " --threads 1 --out " + dir + "/b.json");
    REQUIRE(b.status == 0);
    CHECK(mgp::test::readText(dir + "/a.json") == mgp::test::readText(dir + "/b.json"));

    const Run s = run("train " + kMocap +
                      "/asf_amc/16_35.amc --model sgplvm --step 6 --active 10 --iters 1 --scg-iters 5 --json --out " +
                      dir + "/s.json");
    REQUIRE(s.status == 0);
    const auto js = nlohmann::json::parse(s.out);
    CHECK(js["model"] == "sgplvm");
    CHECK(js["params"]["eta"].is_null());
    const auto model = nlohmann::json::parse(mgp::test::readText(dir + "/s.json"));
    CHECK(model["format"] == "motiongp-model");
    CHECK(model["version"] == 1);
    CHECK(model["source"]["file"] == "16_35.amc");
    CHECK(model["training_frames"][1] == 6);
}

TEST_CASE("cmd train: an AMC with a BVH and bad values give clear errors and a non-zero exit") {
    const std::string dir = mgp::test::scratchDir("cmd_train");
    std::filesystem::create_directories(dir);
    const Run mixed =
        run("train " + kMocap + "/asf_amc/02_03.amc " + kMocap + "/bvh/02_03.bvh --out " + dir + "/x.json");
    CHECK(mixed.status != 0);
    CHECK(mixed.err.find("expected clips of one skeleton (retargeting is not supported)") != std::string::npos);
    CHECK(!std::filesystem::exists(dir + "/x.json"));
    const Run frames = run("train " + kMocap + "/asf_amc/16_35.amc --frames 100:5000 --out " + dir + "/x.json");
    CHECK(frames.status != 0);
    CHECK(frames.err.find("--frames") != std::string::npos);
    const Run model = run("train " + kMocap + "/asf_amc/16_35.amc --model gplvm --out " + dir + "/x.json");
    CHECK(model.status != 0);
    CHECK(model.err.find("fas or sgplvm") != std::string::npos);
}

TEST_CASE("cmd table1: bad option values are usage errors") {
    const Run a = run("table1 --iters-scale 2");
    CHECK(a.status != 0);
    CHECK(a.err.find("--iters-scale") != std::string::npos);
    const Run b = run("table1 --scg-iters 0");
    CHECK(b.status != 0);
    CHECK(b.err.find("--scg-iters") != std::string::npos);
}
