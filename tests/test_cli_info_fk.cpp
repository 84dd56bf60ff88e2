// The `info` and `fk` verbs: one JSON object on stdout, errors on stderr with a non-zero exit; and
// the --json contract over every verb.
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "test_support.h"

using nlohmann::json;

TEST_CASE("motiongp info --json on 35_01") {
    const auto r = mgp::test::runCli("info '" + mgp::test::mocap("asf_amc/35_01.amc") + "' --json");
    REQUIRE(r.exitCode == 0);
    const json j = json::parse(r.out);
    CHECK(j["format"] == "amc");
    CHECK(j["frames"] == 358);
    CHECK(j["fps"] == 120.0);
    CHECK(j["bones"] == 22);
    CHECK(j["dof"] == 50);
    CHECK(j["rot_dof"] == 47);
    CHECK(j["constant_dofs"] == json::array({33, 34, 40, 41}));
    CHECK(j["unmapped"] == json::array());
    CHECK(j["rest_frame"] == false);
}

TEST_CASE("motiongp info --json on a Daz BVH says rest_frame and lists unmapped joints") {
    const auto r = mgp::test::runCli("info '" + mgp::test::mocap("bvh/02_03.bvh") + "' --json");
    REQUIRE(r.exitCode == 0);
    const json j = json::parse(r.out);
    CHECK(j["format"] == "bvh");
    CHECK(j["frames"] == 174);
    CHECK(j["rest_frame"] == true);
    CHECK(j["unmapped"].size() == 22);
    CHECK(j["missing_bones"] == json::array({"upperback", "upperneck"}));
}

TEST_CASE("motiongp fk --json: frame counted from 1, cm, Y up, whatever the file's labels") {
    auto r = mgp::test::runCli("fk '" + mgp::test::mocap("asf_amc/35_01.amc") + "' --frame 1 --json");
    REQUIRE(r.exitCode == 0);
    json j = json::parse(r.out);
    CHECK(j["frame"] == 1);
    const json& p = j["positions_cm"];
    for (const char* key : {"root", "head", "lhand", "rhand", "lfoot", "rfoot"}) CHECK(p[key].size() == 3);
    CHECK(std::abs(p["root"][1].get<double>() - 101.0) <= 0.1);
    CHECK(std::abs(p["head"][1].get<double>() - 164.2) <= 0.1);
    CHECK(std::abs(p["rfoot"][1].get<double>() - 3.4) <= 0.1);
    CHECK(std::abs(p["lfoot"][1].get<double>() - 8.9) <= 0.1);

    r = mgp::test::runCli("fk '" + mgp::test::mocap("asf_amc/35_01.amc") + "' --frame 359 --json");
    CHECK(r.exitCode == 2);
    CHECK(r.out.empty());
    CHECK(r.err == "motiongp: error: expected --frame in 1..358 (clip frames counted from 1), found 359\n");

    // 124_03 (full CMU set only) is labelled 700-1319 in the file: its frames are still 1..620.
    const auto labelled = mgp::test::sharedMocap("asf_amc/124_03.amc");
    if (!labelled) {
        MESSAGE("124_03.amc (../shared/mocap) is absent: the relabelled-file half is not checked here");
        return;
    }
    r = mgp::test::runCli("fk '" + *labelled + "' --frame 620 --json");
    CHECK(r.exitCode == 0);
    r = mgp::test::runCli("fk '" + *labelled + "' --frame 700 --json");
    CHECK(r.exitCode == 2);
    CHECK(r.out.empty());
    CHECK(r.err == "motiongp: error: expected --frame in 1..620 (clip frames counted from 1), found 700\n");
}

TEST_CASE("CLI errors: a bad file gives one line on stderr and exit 2") {
    const std::string dir = mgp::test::scratchDir("cli_errors");
    mgp::test::writeText(dir + "/bad.bvh", "HIERARCHY\nROOT x\n{\n OFFSET 0 0 zero\n");
    const auto r = mgp::test::runCli("info '" + dir + "/bad.bvh' --json");
    CHECK(r.exitCode == 2);
    CHECK(r.out.empty());
    CHECK(r.err == "motiongp: error: " + dir + "/bad.bvh:4: expected a finite number, found 'zero'\n");
}

TEST_CASE("motiongp with no verb summarises the default clip (a kick)") {
    const auto r = mgp::test::runCli("--data '" + std::string(MOTIONGP_TEST_MOCAP) + "'");
    CHECK(r.exitCode == 0);
    CHECK(r.out.find("10_02: amc (cmu-asf), 590 frames") != std::string::npos);
    const auto none = mgp::test::runCli("--data /nonexistent");
    CHECK(none.exitCode == 2);
    CHECK(none.err.find("expected --data to name a folder holding asf_amc/ or bvh/") != std::string::npos);
}

TEST_CASE("every verb accepts --json: each one that `motiongp --help` lists offers it") {
    const auto help = mgp::test::runCli("--help");
    REQUIRE(help.exitCode == 0);
    const std::size_t at = help.out.find("Subcommands:\n");
    REQUIRE(at != std::string::npos);
    std::istringstream lines(help.out.substr(at + 13));
    std::vector<std::string> verbs;
    for (std::string line; std::getline(lines, line) && line.rfind("  ", 0) == 0;) {
        std::istringstream words(line);
        std::string verb;
        words >> verb;
        verbs.push_back(verb);
    }
    CHECK(verbs.size() >= 13);  // the thirteen verbs the command line had when this test was written
    for (const std::string& verb : verbs) {
        INFO(verb);
        const auto r = mgp::test::runCli(verb + " --help");
        CHECK(r.exitCode == 0);
        CHECK(r.out.find("--json") != std::string::npos);
    }
}
