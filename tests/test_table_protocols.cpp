// Smoke tests of the Table 1 and Table 2 protocols (docs/maths.md §14): `table1 --quick` and
// `table2 --quick` on the shipped clips, checked for the table's shape, finite numbers, the
// settings actually used and the protocol's invariants; plus the protocol pieces in core/eval.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "eval/claim_test.h"
#include "eval/clip_segments.h"
#include "eval/nearest_pose.h"
#include "eval/table1_protocol.h"
#include "eval/table2_protocol.h"
#include "test_support.h"

namespace mgp {
namespace {

nlohmann::json runJson(const std::string& args) {
    const test::CliResult r = test::runCli(args);
    INFO(test::describe(r) << "\n" << r.err);
    REQUIRE(r.exitCode == 0);
    return nlohmann::json::parse(r.out);
}

bool finiteNumber(const nlohmann::json& j) { return j.is_number() && std::isfinite(j.get<double>()); }

// Every number in j (recursively) is finite; nulls (a test never met) are allowed.
void checkAllFinite(const nlohmann::json& j, const std::string& where) {
    if (j.is_number()) {
        INFO(where);
        CHECK(std::isfinite(j.get<double>()));
    } else if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it) checkAllFinite(it.value(), where + "." + it.key());
    } else if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i) checkAllFinite(j[i], where + "[" + std::to_string(i) + "]");
    }
}

// No published figure is printed beside ours (docs/cli.md keeps those, labelled measured
// elsewhere).
bool mentionsPaperFigures(const nlohmann::json& j) {
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it)
            if (it.key() == "paper" || it.key().rfind("paper_fas", 0) == 0 || it.key().rfind("paper_sgplvm", 0) == 0 ||
                mentionsPaperFigures(it.value()))
                return true;
    } else if (j.is_array()) {
        for (const auto& x : j)
            if (mentionsPaperFigures(x)) return true;
    }
    return false;
}

}  // namespace

TEST_CASE("table1 --quick: shape, finite values, the settings used and the frozen-set control") {
    const nlohmann::json out = runJson("table1 --quick --json");
    const nlohmann::json& st = out["settings"];
    CHECK(st["quick"] == true);
    CHECK(st["scg_iterations"] == 30);
    CHECK(st["M"] == 60);
    CHECK(st["iters_scale"].get<double>() == doctest::Approx(0.1));
    CHECK(st["tolerance_C"].get<double>() == doctest::Approx(gp::TrainOptions{}.tolerance));
    CHECK(st["point_iterations"] == gp::TrainOptions{}.pointIterations);
    CHECK(st["prior"] == "none");
    CHECK_FALSE(mentionsPaperFigures(out));
    const auto& clips = table1QuickClips();
    REQUIRE(out["rows"].size() == clips.size());
    for (std::size_t i = 0; i < clips.size(); ++i) {
        const nlohmann::json& row = out["rows"][i];
        CHECK(row["kind"] == clips[i].kind);
        CHECK(row["clips"] == describeSegments(clips[i].segments));
        const int N = row["N"];
        CHECK(N == clips[i].segments[0].last - clips[i].segments[0].first + 1);
        CHECK(row["M"] == std::min(60, N));
        const int T = row["T_report"];
        CHECK(T == table1Iterations(clips[i].paperIterations, 0.1));
        CHECK(T >= 5);
        for (const char* model : {"fas", "sgplvm"}) {
            INFO(row["kind"].get<std::string>() << " " << model);
            const nlohmann::json& x = row[model];
            checkAllFinite(x, model);
            CHECK(x["T"] == T);
            REQUIRE(x["log"].size() == static_cast<std::size_t>(T));
            for (int t = 0; t < T; ++t) CHECK(x["log"][t]["iter"] == t + 1);
            for (const char* key : {"raw_max_delta", "log_max_delta", "abs_delta_L_fixed_active", "grad_inf"}) {
                REQUIRE(finiteNumber(x[key]));
                CHECK(x[key].get<double>() >= 0.0);
            }
            CHECK(x["active_overlap"].get<double>() >= 0.0);
            CHECK(x["active_overlap"].get<double>() <= 1.0);
            CHECK(x["L_final"] == x["log"][T - 1]["L"]);
            CHECK(x["w_min"].get<double>() > 0.0);
            // The control branches at T − 5 and keeps its active set: full overlap at T.
            CHECK(x["frozen_from"] == T - 4);
            CHECK(x["frozen_active_overlap"].get<double>() == 1.0);
            CHECK(x["frozen_raw_max_delta"].get<double>() >= 0.0);
        }
    }
}

TEST_CASE("table2 --quick: shape, finite values, the settings used and prefix ranges that start at zero") {
    const nlohmann::json out = runJson("table2 --quick --json");
    const nlohmann::json& st = out["settings"];
    CHECK(st["quick"] == true);
    CHECK(st["outer_iterations"] == 2);
    CHECK(st["active"] == 100);
    CHECK(st["max_delta_cm"] == 30);
    CHECK(st["ik_iterations"] == Table2Settings{}.ikIterations);
    CHECK(st["lambda"].get<double>() == doctest::Approx(0.999));
    CHECK_FALSE(mentionsPaperFigures(out));
    const auto& rows = table2QuickRows();
    REQUIRE(out["rows"].size() == rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const nlohmann::json& e = out["rows"][i];
        INFO(rows[i].kind);
        CHECK(e["kind"] == rows[i].kind);
        CHECK(e["edited_frame"] == rows[i].frame);
        CHECK(e["reference_frames"].get<int>() > 0);
        CHECK(finiteNumber(e["tau_nn_cm"]));
        CHECK(finiteNumber(e["density_threshold"]));
        for (const char* cell : {"sgplvm_static", "sgplvm_adaptive", "fas_static", "fas_adaptive"}) {
            INFO(cell);
            const nlohmann::json& r = e[cell];
            checkAllFinite(r, cell);
            const int combined = r["combined"];
            const int perTest[5] = {r["reach"], r["joint_ranges"], r["nearest_real_pose"], r["density"],
                                    r["continuity"]};
            CHECK(combined == *std::min_element(perTest, perTest + 5));
            // δ = 0 is the captured frame itself: reached and natural. A range of −1 is a bug.
            CHECK(combined >= 0);
            CHECK(combined <= 30);
            CHECK(r["steps_solved"].get<int>() >= combined + 1);
            for (int d = 0; d <= combined; ++d) CHECK(r["steps"][d]["delta"] == d);
            if (std::string(cell).find("static") != std::string::npos) CHECK(r["adaptive_updates"] == 0);
        }
        for (const auto& c : e["learned_vs_plain"]) {
            CHECK(c["delta_cm"].get<int>() <= 30);
            CHECK(finiteNumber(c["learned"]["nn_rms_deg"]));
            CHECK(finiteNumber(c["plain"]["nn_rms_deg"]));
            CHECK(c["plain"]["nn_rms_deg"].get<double>() >= 0.0);
        }
        const nlohmann::json& span = e["fas_static_span"];
        REQUIRE(span.contains("combined"));
        CHECK(span["combined"].get<int>() >= -1);
        CHECK(span["keys"][1] == rows[i].frame);
    }
}

TEST_CASE("nearest-pose RMS: wrapped differences over the 44 non-root DOFs, the nearest candidate") {
    CHECK(wrap180(190.0) == doctest::Approx(-170.0));
    CHECK(wrap180(-350.0) == doctest::Approx(10.0));
    Eigen::VectorXd pose = Eigen::VectorXd::Zero(kAsfPoseDofs);
    pose.head(3).setConstant(1000.0);  // the root DOFs do not count
    Eigen::MatrixXd candidates = Eigen::MatrixXd::Zero(2, kAsfPoseDofs);
    candidates.row(0).setConstant(10.0);            // RMS 10
    candidates.row(1).tail(44).setConstant(358.0);  // −2 once wrapped: RMS 2
    CHECK(nearestPoseRmsDeg(pose, candidates) == doctest::Approx(2.0));
    candidates(1, 10) = 358.0 + 44.0;  // one DOF at 44 + (−2) → sqrt((43·4 + 42²)/44)
    CHECK(nearestPoseRmsDeg(pose, candidates) == doctest::Approx(std::sqrt((43.0 * 4.0 + 42.0 * 42.0) / 44.0)));
    CHECK(std::isinf(nearestPoseRmsDeg(pose, Eigen::MatrixXd(0, kAsfPoseDofs))));
    // Which row: the nearest one (row 1 here), the first of equals, none without candidates.
    const NearestPose n = nearestPose(pose, candidates);
    CHECK(n.row == 1);
    CHECK(n.rmsDeg == doctest::Approx(std::sqrt((43.0 * 4.0 + 42.0 * 42.0) / 44.0)));
    Eigen::MatrixXd twins(3, kAsfPoseDofs);
    twins << candidates.row(0), candidates.row(0) * 0.5, candidates.row(0) * 0.5;
    CHECK(nearestPose(pose, twins).row == 1);
    CHECK(nearestPose(pose, twins).rmsDeg == doctest::Approx(5.0));
    CHECK(nearestPose(pose, Eigen::MatrixXd(0, kAsfPoseDofs)).row == -1);
}

TEST_CASE("clip segments: joined in order, and a segment past the trial's end is a clear error") {
    TrialCache cache;
    const std::string dir =
        std::filesystem::path(test::mocap("asf_amc/16_35.amc")).parent_path().parent_path().string();
    const Clip joined = joinSegments(dir, {{"16_35", 1, 10}, {"16_35", 21, 25}}, cache);
    CHECK(joined.frameCount() == 15);
    CHECK(cache.size() == 1);
    CHECK(joined.frames[10].rootCm.isApprox(cache.at("16_35").frames[20].rootCm));
    CHECK(describeSegments({{"16_35", 1, 10}, {"16_35", 21, 25}}) == "16_35 [1:10] + 16_35 [21:25]");
    try {
        joinSegments(dir, {{"16_35", 100, 9999}}, cache);
        FAIL("expected an error");
    } catch (const std::invalid_argument& e) {
        CHECK(std::string(e.what()).find("16_35 frames 100..9999 within 1..") != std::string::npos);
    }
}

TEST_CASE("clip specs: FILE or FILE:A:B, and a bad range or a bare name is a clear error") {
    const std::string file = test::mocap("asf_amc/16_35.amc");
    const ClipSegment whole = parseClipSpec(file);
    CHECK(whole.trial == file);
    CHECK(whole.first == 1);
    CHECK(whole.last == 0);
    const ClipSegment part = parseClipSpec(file + ":11:40");
    CHECK(part.trial == file);
    CHECK(part.first == 11);
    CHECK(part.last == 40);
    TrialCache cache;
    const int wholeFrames = joinSegments("", {whole}, cache).frameCount();
    CHECK(wholeFrames == cache.at(file).frameCount());
    const Clip stretch = joinSegments("", {part}, cache);
    CHECK(stretch.frameCount() == 30);
    CHECK(stretch.frames[0].rootCm.isApprox(cache.at(file).frames[10].rootCm));
    CHECK(cache.size() == 1);
    // A BVH converter's rest pose is not motion: a whole-file segment starts after it.
    const std::string bvh = test::mocap("bvh/49_04.bvh");
    const Clip motion = joinSegments("", {parseClipSpec(bvh)}, cache);
    REQUIRE(cache.at(bvh).restFrame);
    CHECK(motion.frameCount() == cache.at(bvh).frameCount() - 1);
    CHECK_FALSE(motion.restFrame);
    CHECK(describeSegments({parseClipSpec(bvh)}) == bvh + " [1:end]");
    CHECK_THROWS_WITH_AS(parseClipSpec(file + ":0:5"), doctest::Contains("1 ≤ A ≤ B"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(parseClipSpec(file + ":9:3"), doctest::Contains("1 ≤ A ≤ B"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(parseClipSpec("16_35"), doctest::Contains("expected a clip file"), std::invalid_argument);
    CHECK_THROWS_WITH_AS(joinSegments("", {parseClipSpec(file + ":1:99999")}, cache), doctest::Contains("within 1.."),
                         std::invalid_argument);
}

TEST_CASE("table2 rows from --clip/--edit: the effector, a unit direction, the frame, and bad edits named") {
    const std::string file = test::mocap("asf_amc/16_35.amc");
    const Table2Row row = table2RowFromSpec(file + ":1:100", "rhand:3,4,0", 0, {file + ":120:160"}, 100);
    CHECK(row.kind == "16_35");
    CHECK(row.effector == Effector::kRHand);
    CHECK(row.direction.isApprox(Eigen::Vector3d(0.6, 0.8, 0.0)));
    CHECK(row.frame == 50);  // the middle frame
    REQUIRE(row.reference.size() == 1);
    CHECK(row.reference[0].first == 120);
    CHECK(table2RowFromSpec(file, "head:0,-2,0", 7, {}, 100).direction.isApprox(-Eigen::Vector3d::UnitY()));
    CHECK(table2RowFromSpec(file, "head:0,-2,0", 7, {}, 100).frame == 7);
    for (const char* bad : {"hand:0,1,0", "head:0,0,0", "head:1,2", "head:1,2,3x", "head"}) {
        INFO(bad);
        CHECK_THROWS_WITH_AS(table2RowFromSpec(file, bad, 0, {}, 100), doctest::Contains("found '"),
                             std::invalid_argument);
    }
    CHECK_THROWS_WITH_AS(table2RowFromSpec(file, "head:0,1,0", 101, {}, 100),
                         doctest::Contains("--frame within 1..100"), std::invalid_argument);
}

TEST_CASE("table1 --clip --runs: each run's pair, mean ± sd per model, a verdict per claim") {
    const std::string clip = test::mocap("asf_amc/16_35.amc") + ":1:60";
    const nlohmann::json out =
        runJson("table1 --clip " + clip + " --iters 3 --active 30 --scg-iters 10 --runs 3 --threads 2 --json");
    CHECK(out["settings"]["runs"] == 3);
    CHECK(out["settings"]["perturbation"].get<std::string>().find("one in ten") != std::string::npos);
    REQUIRE(out["rows"].size() == 1u);
    const nlohmann::json& row = out["rows"][0];
    CHECK(row["kind"] == "16_35");
    CHECK(row["T_report"] == 3);
    REQUIRE(row["runs"].size() == 3u);
    std::vector<double> raw;
    for (int k = 0; k < 3; ++k) {
        CHECK(row["runs"][k]["run"] == k);
        CHECK(row["runs"][k]["N"] == 54);  // 60 frames, one in ten dropped
        raw.push_back(row["runs"][k]["fas"]["raw_max_delta"].get<double>());
        checkAllFinite(row["runs"][k]["fas"], "fas");
    }
    // The perturbations are real: the runs differ.
    CHECK(raw[0] != raw[1]);
    const Spread s = spreadOf(raw);
    CHECK(row["spread"]["fas"]["raw_max_delta"]["mean"].get<double>() == doctest::Approx(s.mean));
    CHECK(row["spread"]["fas"]["raw_max_delta"]["sd"].get<double>() == doctest::Approx(s.sd));
    CHECK(row["spread"]["fas"]["raw_max_delta"]["n"] == 3);
    REQUIRE(out["claims"].size() == 4u);
    for (const auto& c : out["claims"]) {
        CHECK(c["pooled"]["pairs"] == 3);
        const std::string v = c["verdict"];
        CHECK((v == "confirmed" || v == "refuted" || v == "inconclusive"));
        CHECK(v == "inconclusive");  // three pairs cannot reach p < 0.05 (smallest p = 0.25)
    }
}

TEST_CASE("table2 --clip --edit --runs: the row as asked, every cell per run with its binding tests, the claims") {
    const std::string clip = test::mocap("asf_amc/16_01.amc");
    const nlohmann::json out =
        runJson("table2 --clip " + clip + ":1:120 --frame 60 --edit rfoot:0,1,0 --reference " + clip +
                ":131:322 --iters 2 --active 60 --max-delta 6 --runs 2 --threads 2 --json");
    REQUIRE(out["rows"].size() == 1u);
    const nlohmann::json& e = out["rows"][0];
    CHECK(e["edited_frame"] == 60);
    CHECK(e["direction"][1].get<double>() == doctest::Approx(1.0));
    CHECK(e["captured_frame"].contains("ranges"));
    REQUIRE(e["runs"].size() == 2u);
    for (const auto& run : e["runs"]) {
        CHECK(run["frames_trained"] == 108);
        for (const auto& cellName : out["settings"]["cells"]) {
            const std::string cell = cellName;
            INFO(cell);
            REQUIRE(run.contains(cell));
            const nlohmann::json& r = run[cell];
            const int combined = r["combined"];
            CHECK(combined >= -1);
            CHECK(combined <= 6);
            // A range below the sweep's end names what bound it; one at the end names nothing.
            CHECK(r["binding"].empty() == (combined == 6));
        }
    }
    CHECK(e["spread"]["fas_static_drag"]["n"] == 2);
    CHECK(out["claims"].size() == 5u);
}

TEST_CASE("table1/table2 --clip: bad clips and edits are one clear error") {
    const std::string clip = test::mocap("asf_amc/16_01.amc");
    struct Case {
        std::string args, expect;
    };
    const Case cases[] = {
        {"table2 --clip " + clip + " --edit hand:0,1,0", "expected --edit EFFECTOR:dx,dy,dz"},
        {"table2 --clip " + clip, "expected --edit"},
        {"table2 --edit head:0,1,0", "found no --clip"},
        {"table2 --clip " + test::mocap("bvh/02_03.bvh") + " --edit head:0,1,0", "22 model bones"},
        {"table1 --clip " + clip + ":5:2", "1 ≤ A ≤ B"},
        {"table2 --clip " + test::mocap("asf_amc/35_01.amc") + ":1:120 --edit lhand:0,1,0 --reference " +
             test::mocap("bvh/49_04.bvh"),
         "pose layout"},
        {"table2 --clip " + test::mocap("asf_amc/16_35.amc") + ":1:25 --edit rfoot:0,1,0", "reference frames"},
        {"table2 --clip " + clip + " --edit rfoot:1e308,1e308,0", "non-zero, finite edit direction"},
    };
    for (const Case& c : cases) {
        const test::CliResult r = test::runCli(c.args);
        INFO(c.args << "\n" << r.err);
        CHECK(r.exitCode != 0);
        CHECK(r.err.find(c.expect) != std::string::npos);
        CHECK(r.err.find("terminate") == std::string::npos);
    }
}

TEST_CASE("table settings: bad values are rejected with the field's name") {
    Table1Settings t1;
    t1.itersScale = 0.0;
    CHECK_THROWS_WITH_AS(t1.validate(), doctest::Contains("iteration scale"), std::invalid_argument);
    Table2Settings t2;
    t2.maxDeltaCm = 0;
    CHECK_THROWS_WITH_AS(t2.validate(), doctest::Contains("largest displacement"), std::invalid_argument);
    Table1Settings runs;
    runs.runs = 0;
    CHECK_THROWS_WITH_AS(runs.validate(), doctest::Contains("1 to 50 runs"), std::invalid_argument);
}

}  // namespace mgp
