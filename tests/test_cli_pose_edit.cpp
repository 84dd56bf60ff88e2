// The pose and edit verbs on a real model file (the 35_01 fixture saved to disk).
#include <nlohmann/json.hpp>

#include "gp/model_file.h"
#include "io/bvh_reader.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/rotation.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using nlohmann::json;
using namespace mgp;

TEST_CASE("motiongp pose --json: learned and plain solvers, pins, offsets from the frame's position") {
    const std::string model = test::walkModelPath();
    auto r = test::runCli("pose '" + model + "' --frame 101 --target rfoot=0,10,0 --pin lfoot --json");
    REQUIRE(r.exitCode == 0);
    json j = json::parse(r.out);
    CHECK(j["reached"] == true);
    CHECK(j["targets"].size() == 1);
    CHECK(j["targets"][0]["effector"] == "rfoot");
    CHECK(j["targets"][0]["residual_cm"].get<double>() < 0.5);
    CHECK(j["pins"][0]["effector"] == "lfoot");
    CHECK(j["pins"][0]["residual_cm"].get<double>() < 0.5);
    CHECK(j["x"].size() == 2);
    CHECK(j["sigma2"].get<double>() > 0.0);
    CHECK(j["pose_deg"].size() == 47);
    // The foot is where FK of the returned pose puts it: 10 cm above frame 101's foot.
    auto fk = test::runCli("fk '" + test::mocap("asf_amc/35_01.amc") + "' --frame 101 --json");
    const double y0 = json::parse(fk.out)["positions_cm"]["rfoot"][1].get<double>();
    CHECK(std::abs(j["positions_cm"]["rfoot"][1].get<double>() - (y0 + 10.0)) < 0.5);

    r = test::runCli("pose '" + model + "' --frame 101 --target rfoot=0,10,0 --solver plain --json");
    REQUIRE(r.exitCode == 0);
    j = json::parse(r.out);
    CHECK(j["reached"] == true);
    CHECK(j["x"].is_null());
    CHECK(j["sigma2"].is_null());
    CHECK(j["L_IK"].is_null());
}

TEST_CASE("motiongp pose --json: nearest names the captured frame closest to the solved pose") {
    const std::string model = test::walkModelPath();
    const auto r = test::runCli("pose '" + model + "' --frame 61 --target rhand=0,0,0 --json");
    REQUIRE(r.exitCode == 0);
    const json j = json::parse(r.out);
    REQUIRE(j.contains("nearest"));
    CHECK(j["nearest"]["clip"] == "35_01");
    const int frame = j["nearest"]["frame"].get<int>();  // counted from 1, as --frame
    const double rms = j["nearest"]["rms_deg"].get<double>();
    // The hand stays where it is: the solve stays next to frame 61 of the capture.
    CHECK(std::abs(frame - 61) <= 2);
    CHECK(rms <= 0.5);
    // Recomputed from pose_deg against every captured frame: that frame, that distance, and none nearer.
    const Clip clip = gp::loadModel(model).clip;
    const Eigen::MatrixXd captured = poseMatrix(clip);
    const std::vector<double> y = j["pose_deg"].get<std::vector<double>>();
    auto rmsTo = [&](int row) {
        double sum = 0.0;
        for (int k = 3; k < kAsfPoseDofs; ++k) sum += std::pow(wrap180(y[k] - captured(row, k)), 2);
        return std::sqrt(sum / (kAsfPoseDofs - 3));
    };
    CHECK(rmsTo(frame - 1) == doctest::Approx(rms).epsilon(1e-9));
    for (int row = 0; row < captured.rows(); ++row) CHECK(rmsTo(row) >= rms - 1e-12);
    // The text output says the same.
    const auto text = test::runCli("pose '" + model + "' --frame 61 --target rhand=0,0,0");
    CHECK(text.out.find("nearest captured frame: 35_01 frame " + std::to_string(frame)) != std::string::npos);
}

TEST_CASE("motiongp pose: an unreachable target is a result, bad options are errors") {
    const std::string model = test::walkModelPath();
    auto r = test::runCli("pose '" + model + "' --frame 5 --target head=0,400,0 --json");
    CHECK(r.exitCode == 0);
    CHECK(json::parse(r.out)["reached"] == false);
    r = test::runCli("pose '" + model + "' --frame 5 --target nose=0,1,0");
    CHECK(r.exitCode == 2);
    CHECK(r.err == "motiongp: error: expected --target to be one of lhand, rhand, lfoot, rfoot, head, found 'nose'\n");
    r = test::runCli("pose '" + model + "' --frame 5 --target head=0,1");
    CHECK(r.err == "motiongp: error: expected --target as dx,dy,dz in cm, found '0,1'\n");
    r = test::runCli("pose '" + model + "' --frame 359 --target head=0,1,0");
    CHECK(r.err == "motiongp: error: expected --frame in 1..358 (clip frames counted from 1), found 359\n");
}

TEST_CASE("motiongp pose --adaptive writes a model with one more row") {
    const std::string model = test::walkModelPath();
    const std::string out = test::scratchDir("pose_adaptive") + "/walk2.model";
    const auto r = test::runCli("pose '" + model + "' --frame 101 --target rfoot=0,5,0 --adaptive --out-model '" + out +
                                "' --json");
    REQUIRE(r.exitCode == 0);
    CHECK(json::parse(r.out)["adaptive"]["rows"] == 359);
    CHECK(gp::loadModel(out).N() == 359);
}

TEST_CASE("motiongp edit: the paper's keys, a BVH with every frame, untouched frames unchanged") {
    const std::string model = test::walkModelPath();
    const std::string dir = test::scratchDir("cli_edit");
    const auto r = test::runCli("edit '" + model + "' --effector rfoot --keys 89,103,117,131 --offset 0,20,0 --out '" +
                                dir + "/edited.bvh' --adaptive --out-model '" + dir + "/adapted.model' --json");
    REQUIRE(r.exitCode == 0);
    const json j = json::parse(r.out);
    CHECK(j["frames_solved"] == 41);
    CHECK(j["max_residual_cm"].get<double>() < 0.5);
    CHECK(j["adaptive"]["samples_added"] == 2);  // the two moved keys, not the in-betweens
    CHECK(gp::loadModel(dir + "/adapted.model").N() == 360);
    const Clip edited = readBvh(dir + "/edited.bvh");
    const Clip& source = test::walkModel35()->model->clip;
    REQUIRE(edited.frameCount() == source.frameCount());
    FkState a, b;
    double untouched = 0.0, moved = 0.0;
    for (int t = 0; t < source.frameCount(); ++t) {
        forwardKinematics(edited.skeleton, edited.frames[t], a);
        forwardKinematics(source.skeleton, source.frames[t], b);
        const double gap =
            (effectorCm(edited.skeleton, a, Effector::kRFoot) - effectorCm(source.skeleton, b, Effector::kRFoot))
                .norm();
        if (t > 88 && t < 130)
            moved = std::max(moved, gap);
        else
            untouched = std::max(untouched, gap);
    }
    CHECK(untouched < 1e-6);
    CHECK(moved > 15.0);
}
