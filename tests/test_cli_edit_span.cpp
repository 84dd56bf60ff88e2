// `motiongp edit` with the span solver (default) and the paper's per-frame solver: the --json span
// report, missed keys, the floor, and one clear error line for bad --solver / --pin values.
#include <nlohmann/json.hpp>

#include "gp/model_file.h"
#include "io/clip_loader.h"
#include "motion/foot_contacts.h"
#include "skeleton/forward_kinematics.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using nlohmann::json;
using namespace mgp;

TEST_CASE("motiongp edit --json: the span report, span by default, per-frame on request") {
    const std::string dir = test::scratchDir("cli_edit_span");
    const std::string base = "edit '" + test::walkModelPath() +
                             "' --effector lfoot --keys 89,103,117,131 --offset 0,20,0 --out '" + dir +
                             "/e.bvh' --json";
    auto r = test::runCli(base);
    REQUIRE(r.exitCode == 0);
    json j = json::parse(r.out);
    CHECK(j["solver"] == "span");
    CHECK(j["span"]["stop"] == "converged");
    const json& q = j["quality"];
    CHECK(q["first"] == 89);
    CHECK(q["last"] == 131);
    CHECK(q["worst_key_error_cm"].get<double>() < 0.5);
    CHECK(q["second_difference_deg"]["p95"].get<double>() <=
          1.5 * q["captured_second_difference_deg"]["p95"].get<double>() + 2.0);
    REQUIRE(q["contacts"].size() == 1);
    CHECK(q["contacts"][0]["foot"] == "rfoot");
    CHECK(std::abs(q["contacts"][0]["travel_cm"].get<double>() -
                   q["contacts"][0]["captured_travel_cm"].get<double>()) <= 1.0);
    CHECK(j["max_held_residual_cm"].get<double>() < 0.1);
    CHECK(j["reached"] == true);
    REQUIRE(j["keys"].size() == 2);  // the two moved keys
    CHECK(j["keys"][0]["frame"] == 103);
    CHECK(j["keys"][1]["frame"] == 117);
    for (const json& k : j["keys"]) CHECK(k["error_cm"].get<double>() < 0.5);
    CHECK(r.err.find("warning") == std::string::npos);

    r = test::runCli(base + " --solver per-frame --no-contacts");
    REQUIRE(r.exitCode == 0);
    j = json::parse(r.out);
    CHECK(j["solver"] == "per-frame");
    CHECK(j["quality"]["contacts"].empty());  // nothing held
    CHECK_FALSE(j.contains("span"));
}

TEST_CASE("motiongp edit: a key out of reach is reported missed, in the JSON and in one warning line") {
    // A right-hand key 150 cm above where the hand is: no arm reaches it with the feet held. The
    // solve stops when the missed distance stalls, well before the default 500-step cap.
    const std::string dir = test::scratchDir("cli_edit_missed");
    const auto r =
        test::runCli("edit '" + test::walkModelPath() +
                     "' --effector rhand --keys 89,103,117 --offset 0,150,0 --out '" + dir + "/e.bvh' --json");
    REQUIRE(r.exitCode == 0);
    const json j = json::parse(r.out);
    CHECK(j["span"]["stop"] == "stalled");
    MESSAGE("span iterations: " << j["span"]["iterations"].get<int>());
    CHECK(j["span"]["iterations"].get<int>() < 250);
    CHECK(j["reached"] == false);
    REQUIRE(j["keys"].size() == 1);
    CHECK(j["keys"][0]["frame"] == 103);
    CHECK(j["keys"][0]["reached"] == false);
    MESSAGE("the key was missed by " << j["keys"][0]["error_cm"].get<double>() << " cm");
    CHECK(j["keys"][0]["error_cm"].get<double>() > 20.0);
    CHECK(r.err.find("motiongp: warning: the key on frame 103 was missed by ") == 0);
}

TEST_CASE("motiongp edit: a foot path pushed below the floor stays on it, and its keys are reported missed") {
    const std::string dir = test::scratchDir("cli_edit_floor");
    const std::string out = dir + "/e.bvh";
    const auto r = test::runCli("edit '" + test::walkModelPath() +
                                "' --effector lfoot --keys 89,103,117,131 --offset 0,-30,0 --out '" + out + "' --json");
    REQUIRE(r.exitCode == 0);
    const json j = json::parse(r.out);
    CHECK(j["reached"] == false);
    REQUIRE(j["keys"].size() == 2);
    for (const json& k : j["keys"]) CHECK(k["reached"] == false);
    CHECK(r.err.find("below the floor") != std::string::npos);
    const gp::ModelVersionPtr version = test::walkModel35();
    const double floor = *detectFootContacts(version->model->clip).floorCm;
    const Clip written = loadClip(out);
    double lowest = 1e9;
    for (int t = 88; t <= 130; ++t)
        lowest = std::min(lowest, effectorCm(written.skeleton, written.frames[t], Effector::kLFoot).y());
    MESSAGE("the left foot's lowest point over the span: " << lowest - floor << " cm from the floor");
    CHECK(lowest >= floor - 0.5);
}

TEST_CASE("motiongp edit: bad --solver and --pin values are one error line") {
    const std::string base = "edit '" + test::walkModelPath() +
                             "' --effector lfoot --keys 89,103,117,131 --offset 0,20,0 --out '" +
                             test::scratchDir("cli_edit_span_bad") + "/e.bvh'";
    auto r = test::runCli(base + " --solver newton");
    CHECK(r.exitCode == 2);
    CHECK(r.err.find("expected --solver span or per-frame, found 'newton'") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    r = test::runCli(base + " --pin nose");
    CHECK(r.exitCode == 2);
    CHECK(r.err.find("--pin") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}
