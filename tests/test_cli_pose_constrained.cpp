// `motiongp pose --json` with the constrained solver: converged/stop/iterations, target strength,
// contact pins and --release, the admission verdict, --locality, and --adaptive refusing a broken
// pose, the floor, and --out.
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "gp/model_file.h"
#include "ik/locality.h"
#include "io/clip_loader.h"
#include "skeleton/forward_kinematics.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using nlohmann::json;
using namespace mgp;

TEST_CASE("motiongp pose --json: converged, stop, iterations, strength, natural, contact pins") {
    const std::string model = test::walkModelPath();
    auto r = test::runCli("pose '" + model + "' --frame 101 --target rhand=0,10,5@0.9 --target lhand=0,5,0 --json");
    REQUIRE(r.exitCode == 0);
    json j = json::parse(r.out);
    CHECK(j["stop"].is_string());
    CHECK(j["converged"] == (j["stop"] == "converged"));
    CHECK(j["iterations"].get<int>() >= 1);
    CHECK(j["targets"][0]["strength"].get<double>() == 0.9);
    CHECK(j["targets"][1]["strength"].get<double>() == 1.0);
    CHECK(j["natural"]["percentile"].get<double>() == 99.0);
    CHECK(j["natural"]["admitted"].is_boolean());
    CHECK(j["natural"]["L_IK_limit"].get<double>() > 0.0);
    // The verdict in words and the capture's numbers behind it (eval/admission.h).
    const std::string words = j["natural"]["judgement"].get<std::string>();
    CHECK((words == "natural" || words == "unusual" || words == "unlike the captured data" || words == "out of reach"));
    CHECK(j["natural"]["admitted"] == (words == "natural" || words == "unusual"));
    CHECK(j["natural"]["nearest_captured_cm"].get<double>() >= 0.0);
    CHECK(j["natural"]["nearest_captured_limit_cm"].get<double>() >=
          j["natural"]["nearest_captured_median_cm"].get<double>());
    CHECK(j["natural"]["nearest_captured_frame"].get<int>() >= 1);
    CHECK(j["natural"]["nearest_captured_clip"] == "35_01");
    // Frame 101 of the walk has a planted foot; it is held unless released.
    REQUIRE(j["contact_pins"].size() >= 1);
    const std::string foot = j["contact_pins"][0];
    bool pinned = false;
    for (const auto& p : j["pins"]) pinned |= p["effector"] == foot && p["residual_cm"].get<double>() <= 0.05;
    CHECK(pinned);
    r = test::runCli("pose '" + model + "' --frame 101 --target rhand=0,10,5 --release " + foot + " --json");
    REQUIRE(r.exitCode == 0);
    j = json::parse(r.out);
    for (const auto& c : j["contact_pins"]) CHECK(c != foot);
    r = test::runCli("pose '" + model + "' --frame 101 --target rhand=0,10,5@2 --json");
    CHECK(r.exitCode == 2);
    CHECK(r.err ==
          "motiongp: error: expected --target strength after @ as exact, paper or a number in (0, 1], found '2'\n");
    r = test::runCli("pose '" + model + "' --frame 101 --target rhand=0,10,5 --release head --json");
    CHECK(r.exitCode == 2);
    CHECK(r.err == "motiongp: error: expected --release lfoot or rfoot, found 'head'\n");
}

TEST_CASE("motiongp pose --adaptive refuses an unreachable reach with pinned feet and says why") {
    const std::string model = test::walkModelPath();
    const std::string out = test::scratchDir("pose_adaptive_refused") + "/walk2.model";
    const auto r = test::runCli(
        "pose '" + model + "' --frame 61 --target rhand=120,120,0 --pin lfoot --pin rfoot --adaptive --out-model '" +
        out + "' --json");
    REQUIRE(r.exitCode == 0);
    const json j = json::parse(r.out);
    CHECK(j["reached"] == false);
    for (const auto& p : j["pins"]) CHECK(p["residual_cm"].get<double>() <= 0.05);
    CHECK(j["natural"]["admitted"] == false);
    CHECK(j["adaptive"]["refused"] == true);
    CHECK(j["adaptive"]["reason"] == "a target or pin was not reached");
    CHECK_FALSE(std::ifstream(out).good());  // nothing written
}

TEST_CASE("motiongp pose --locality: reported, the body keeps its pose, bad values are errors") {
    const std::string model = test::walkModelPath();
    const std::string base = "pose '" + model + "' --frame 101 --target rhand=0,20,0 --json";
    auto off = test::runCli(base + " --locality 0");
    auto stiff = test::runCli(base);  // the default
    REQUIRE(off.exitCode == 0);
    REQUIRE(stiff.exitCode == 0);
    const json a = json::parse(off.out), b = json::parse(stiff.out);
    CHECK(a["locality"] == 0.0);
    CHECK(b["locality"] == kDefaultLocality);
    CHECK(b["reached"] == true);
    // The head's distance from where the captured frame has it (the plain solver with no offset
    // keeps the captured pose) shrinks with the term.
    const json captured =
        json::parse(test::runCli("pose '" + model + "' --frame 101 --solver plain --target rhand=0,0,0 --json").out);
    const auto headMove = [&](const json& j) {
        double s = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double d =
                j["positions_cm"]["head"][i].get<double>() - captured["positions_cm"]["head"][i].get<double>();
            s += d * d;
        }
        return std::sqrt(s);
    };
    MESSAGE("head moves " << headMove(a) << " cm without the term, " << headMove(b) << " cm at 100; the centre of mass "
                          << a["com_shift_cm"].get<double>() << " and " << b["com_shift_cm"].get<double>() << " cm");
    CHECK(headMove(b) < headMove(a));
    // The centre of mass moved 4.7 cm over the ground without the term, 0.8 cm with it.
    CHECK(b["com_shift_cm"].get<double>() <= 2.0);
    CHECK(b["com_shift_cm"].get<double>() < a["com_shift_cm"].get<double>());
    auto r = test::runCli(base + " --locality -1");
    CHECK(r.exitCode == 2);
    CHECK(r.err == "motiongp: error: expected a locality ≥ 0, found -1.000000\n");
    r = test::runCli(base + " --locality 3 --solver plain");
    CHECK(r.exitCode == 2);
    CHECK(r.err == "motiongp: error: expected --solver learned with --locality, found --solver plain\n");
    // The default's own value is refused too: the plain solver has no such term to weigh.
    r = test::runCli(base + " --locality 100 --solver plain");
    CHECK(r.exitCode == 2);
    CHECK(r.err == "motiongp: error: expected --solver learned with --locality, found --solver plain\n");
}

TEST_CASE("motiongp pose --balance: a hand pulled far forward stays over the planted foot, 0 turns it off") {
    // The walk's frame 200 stands balanced on its planted foot; the right hand 60 cm forward tips
    // the centre of mass 6.2 cm out of the support without the term (docs/maths-ik.md §1).
    const std::string model = test::walkModelPath();
    const std::string base = "pose '" + model + "' --frame 200 --target rhand=0,0,60 --json";
    auto off = test::runCli(base + " --balance 0");
    auto on = test::runCli(base);
    REQUIRE(off.exitCode == 0);
    REQUIRE(on.exitCode == 0);
    const json a = json::parse(off.out), b = json::parse(on.out);
    CHECK(a["balance_asked"] == false);
    CHECK(b["balance_asked"] == true);
    CHECK(a["reached"] == true);
    CHECK(b["reached"] == true);
    const double outA = a["natural"]["com_outside_support_cm"].get<double>();
    const double outB = b["natural"]["com_outside_support_cm"].get<double>();
    MESSAGE("centre of mass outside the support: " << outA << " cm without the term, " << outB << " cm with it");
    CHECK(a["natural"]["judgement"] == "off balance");
    CHECK(b["natural"]["judgement"] != "off balance");
    CHECK(outB < 0.25 * outA);
    auto r = test::runCli(base + " --balance -1");
    CHECK(r.exitCode == 2);
    CHECK(r.err == "motiongp: error: expected a balance weight ≥ 0, found -1.000000\n");
    r = test::runCli(base + " --balance 3 --solver plain");
    CHECK(r.exitCode == 2);
    CHECK(r.err == "motiongp: error: expected --solver learned with --balance, found --solver plain\n");
    r = test::runCli(base + " --balance 100000 --solver lbfgs");
    CHECK(r.exitCode == 2);
    CHECK(r.err == "motiongp: error: expected --solver learned with --balance, found --solver lbfgs\n");
}

TEST_CASE(
    "motiongp pose: a foot target below the floor ends on it and is refused, and --out writes the clip with the pose "
    "in place") {
    const std::string model = test::walkModelPath();
    const std::string out = test::scratchDir("pose_floor") + "/posed.bvh";
    const auto r = test::runCli("pose '" + model + "' --frame 101 --target lfoot=0,-20,0 --out '" + out + "' --json");
    REQUIRE(r.exitCode == 0);
    const json j = json::parse(r.out);
    const double floor = j["floor_cm"].get<double>();
    const double foot = j["positions_cm"]["lfoot"][1].get<double>();
    MESSAGE("floor " << floor << " cm, the left foot ends " << foot - floor << " cm above it");
    CHECK(foot >= floor - 0.5);
    CHECK(j["reached"] == false);
    CHECK(j["targets"][0]["below_floor"] == true);
    CHECK(j["targets"][0]["residual_cm"].get<double>() > 10.0);
    CHECK(j["natural"]["admitted"] == false);
    CHECK(j["natural"]["reason"] == "a target is below the floor: the effector was held on it");
    CHECK(j["out"] == out);
    // The written clip: every frame, the solved one in place (its left foot where the JSON says).
    const Clip written = loadClip(out);
    const gp::ModelVersionPtr version = test::walkModel35();
    REQUIRE(written.frameCount() == version->model->clip.frameCount());
    CHECK(effectorCm(written.skeleton, written.frames[100], Effector::kLFoot).y() ==
          doctest::Approx(foot).epsilon(1e-4));
    // The other frames are the capture's (to the BVH file's printed precision).
    const Skeleton& sk = version->model->clip.skeleton;
    for (int f : {0, 99, 101})
        CHECK((effectorCm(written.skeleton, written.frames[f], Effector::kLFoot) -
               effectorCm(sk, version->model->clip.frames[f], Effector::kLFoot))
                  .norm() < 0.01);
    const auto bad = test::runCli("pose '" + model + "' --frame 101 --target lfoot=0,5,0 --out posed.txt");
    CHECK(bad.exitCode == 2);
    CHECK(bad.err.find("expected --out") != std::string::npos);
}
