// Session files: bit-exact round trip (model, edits, pins, camera, path edit, UI state), the
// synthetic clip, clip paths relative to the session, a changed clip, and one exact error per
// kind of damage.
#include <doctest/doctest.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "gp/model_file.h"
#include "gp/sha256.h"
#include "io/clip_loader.h"
#include "io/parse_error.h"
#include "session/session_file.h"
#include "skeleton/synthetic_clip.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// An edit: the clip's pose at `frame` nudged by values with long binary expansions.
EditRecord nudgedEdit(const Clip& clip, int frame, Eigen::VectorXd x) {
    EditRecord e{clip.frames[frame], std::move(x), {}};
    e.pose.rootCm += Eigen::Vector3d(0.1, 1.0 / 3.0, -2.0 / 7.0);
    for (auto& a : e.pose.anglesDeg) a += Eigen::Vector3d(1e-13, M_PI, -1.0 / 9.0);
    return e;
}

std::string normal(const std::string& path) { return fs::absolute(path).lexically_normal().string(); }

SessionData clipSession(const std::string& amc) {
    SessionData s;
    s.clipPath = amc;
    s.clipSha256 = gp::sha256OfFile(amc);
    return s;
}

void checkSameDoubles(const SessionData& a, const SessionData& b) {
    REQUIRE(a.edits.size() == b.edits.size());
    for (const auto& [frame, rec] : a.edits) {
        const EditRecord& other = b.edits.at(frame);
        CHECK(rec.pose.rootCm == other.pose.rootCm);
        REQUIRE(rec.pose.anglesDeg.size() == other.pose.anglesDeg.size());
        for (std::size_t k = 0; k < rec.pose.anglesDeg.size(); ++k)
            CHECK(rec.pose.anglesDeg[k] == other.pose.anglesDeg[k]);
        CHECK(rec.x.size() == other.x.size());
        CHECK(rec.x == other.x);
        CHECK(rec.moved == other.moved);
    }
    CHECK(a.camera.yawDeg == b.camera.yawDeg);
    CHECK(a.camera.pitchDeg == b.camera.pitchDeg);
    CHECK(a.camera.distanceCm == b.camera.distanceCm);
    CHECK(a.camera.fovYDeg == b.camera.fovYDeg);
    CHECK(a.camera.targetCm == b.camera.targetCm);
    CHECK(a.path.keyOffsetsCm == b.path.keyOffsetsCm);
}

}  // namespace

TEST_CASE("a session with a model, edits, pins, camera, path edit and UI state round-trips bit-exactly") {
    const auto version = test::walkModel35();
    const gp::GpModel& model = *version->model;
    const std::string dir = test::scratchDir("session_roundtrip");
    SessionData s = clipSession(test::mocap("asf_amc/35_01.amc"));
    s.skeletonPath = test::mocap("asf_amc/35.asf");
    s.model = model;
    s.modelVersion = 3;
    s.compareModel = model;
    Eigen::VectorXd x = model.X.row(12).transpose();
    x[0] += 1.0 / 3.0;
    s.edits[12] = nudgedEdit(model.clip, 12, x);
    s.edits[12].moved = {Effector::kRHand, Effector::kHead};      // what the admission leaves out
    s.edits[40] = nudgedEdit(model.clip, 40, Eigen::VectorXd());  // solved by plain IK
    s.frame = 40;
    s.pins[static_cast<int>(Effector::kLFoot)] = true;
    s.pins[static_cast<int>(Effector::kRFoot)] = true;
    s.keys = {0, 99, 159};
    s.selectedEffector = static_cast<int>(Effector::kRHand);
    s.compareMode = "model";
    s.adaptiveEnabled = false;
    s.camera = {12.5 / 7.0, -3.0 / 11.0, 417.123456789012345, 35.000000000000007, {0.1, 90.2, -1e-300}, false};
    s.path = {
        true, Effector::kRFoot, {20, 30, 45}, {{0, 0, 0}, {1.0 / 3.0, 5, -2}, {0, 0, 0}}, PathMode::kDisplacement};
    s.ui = {{"panels", {{"latent_map", true}, {"timeline", false}}}, {"zoom", 1.25}, {"name", "ünïcode"}};

    const std::string path = dir + "/walk" + kSessionExtension;
    saveSession(path, s);
    const SessionData r = loadSession(path);
    CHECK(r.warnings.empty());
    CHECK(r.clipPath == normal(s.clipPath));  // stored absolute and normalised
    CHECK(r.skeletonPath == normal(s.skeletonPath));
    CHECK(r.clipSha256 == s.clipSha256);
    REQUIRE(r.model);
    REQUIRE(r.compareModel);
    CHECK(gp::modelToJsonText(*r.model) == gp::modelToJsonText(model));
    CHECK(gp::modelToJsonText(*r.compareModel) == gp::modelToJsonText(model));
    CHECK(r.model->X == model.X);
    CHECK(r.model->logParams == model.logParams);
    CHECK(r.modelVersion == 3);
    checkSameDoubles(s, r);
    CHECK(r.frame == 40);
    CHECK(r.pins == s.pins);
    CHECK(r.keys == s.keys);
    CHECK(r.selectedEffector == s.selectedEffector);
    CHECK(r.compareMode == "model");
    CHECK(r.adaptiveEnabled == false);
    CHECK(r.camera.followCharacter == false);
    CHECK(r.path.present);
    CHECK(r.path.effector == Effector::kRFoot);
    CHECK(r.path.keyFrames == s.path.keyFrames);
    CHECK(r.path.mode == PathMode::kDisplacement);
    CHECK(r.ui == s.ui);
    CHECK(sessionToJsonText(r, path) == test::readText(path));  // nothing lost, nothing added
    CHECK_FALSE(loadSessionClip(r, path));                      // the model carries the clip
}

TEST_CASE("a session on the synthetic walk needs no file and rebuilds the clip") {
    const std::string dir = test::scratchDir("session_synthetic");
    const Clip walk = makeSyntheticWalk(120);
    SessionData s;
    s.syntheticClip = true;
    s.syntheticFrames = 120;
    s.edits[5] = nudgedEdit(walk, 5, Eigen::VectorXd());
    s.frame = 119;
    const std::string path = dir + "/synthetic.mgsession";
    saveSession(path, s);
    const SessionData r = loadSession(path);
    CHECK(r.syntheticClip);
    CHECK(r.clipPath.empty());
    checkSameDoubles(s, r);
    const std::optional<Clip> clip = loadSessionClip(r, path);
    REQUIRE(clip);
    CHECK(clip->frameCount() == 120);
    CHECK(clip->skeleton.jointCount() == walk.skeleton.jointCount());
    CHECK_FALSE(r.path.present);
}

TEST_CASE("the clip is found relative to the session first, then by its absolute path") {
    const std::string root = test::scratchDir("session_paths");
    fs::create_directories(root + "/project/clips");
    fs::create_directories(root + "/project/sessions");
    fs::copy_file(test::mocap("asf_amc/35_01.amc"), root + "/project/clips/35_01.amc");
    fs::copy_file(test::mocap("asf_amc/35.asf"), root + "/project/clips/35.asf");
    SessionData s = clipSession(root + "/project/clips/35_01.amc");
    s.skeletonPath = root + "/project/clips/35.asf";
    const Clip clip = loadClip(s.clipPath, s.skeletonPath);
    s.edits[3] = nudgedEdit(clip, 3, Eigen::VectorXd());
    saveSession(root + "/project/sessions/a.mgsession", s);
    const json stored = json::parse(test::readText(root + "/project/sessions/a.mgsession"));
    CHECK(stored["clip"]["relative_path"] == "../clips/35_01.amc");
    CHECK(stored["clip"]["skeleton_relative_path"] == "../clips/35.asf");

    // The whole folder moves: the absolute paths are stale, the relative ones still fit.
    fs::rename(root + "/project", root + "/moved");
    const SessionData moved = loadSession(root + "/moved/sessions/a.mgsession");
    CHECK(moved.clipPath == root + "/moved/clips/35_01.amc");
    CHECK(moved.skeletonPath == root + "/moved/clips/35.asf");
    CHECK(moved.warnings.empty());
    const std::optional<Clip> reloaded = loadSessionClip(moved, root + "/moved/sessions/a.mgsession");
    REQUIRE(reloaded);
    CHECK(reloaded->frameCount() == clip.frameCount());

    // Only the session moves: the relative path is wrong, the absolute one still holds.
    saveSession(root + "/moved/sessions/b.mgsession", moved);
    fs::create_directories(root + "/elsewhere/deeper");
    fs::rename(root + "/moved/sessions/b.mgsession", root + "/elsewhere/deeper/b.mgsession");
    const SessionData b = loadSession(root + "/elsewhere/deeper/b.mgsession");
    CHECK(b.clipPath == root + "/moved/clips/35_01.amc");
    CHECK(b.skeletonPath == root + "/moved/clips/35.asf");
}

TEST_CASE("a clip file that changed since the session was saved loads with a warning") {
    const std::string dir = test::scratchDir("session_sha");
    fs::copy_file(test::mocap("asf_amc/35_01.amc"), dir + "/35_01.amc");
    fs::copy_file(test::mocap("asf_amc/35.asf"), dir + "/35.asf");
    saveSession(dir + "/s.mgsession", clipSession(dir + "/35_01.amc"));
    CHECK(loadSession(dir + "/s.mgsession").warnings.empty());
    test::writeText(dir + "/35_01.amc", test::readText(dir + "/35_01.amc") + "\n");
    const SessionData r = loadSession(dir + "/s.mgsession");
    REQUIRE(r.warnings.size() == 1);
    CHECK(r.warnings[0] == dir +
                               "/35_01.amc changed since the session was saved (SHA-256 differs): "
                               "the edits may not fit the motion");
    CHECK(loadSessionClip(r, dir + "/s.mgsession"));
}

TEST_CASE("every damaged session file gives one exact error") {
    const std::string amc = test::mocap("asf_amc/35_01.amc");
    const Clip clip = loadClip(amc);
    SessionData base = clipSession(amc);
    base.edits[5] = nudgedEdit(clip, 5, Eigen::VectorXd());
    const json good = json::parse(sessionToJsonText(base, "/tmp/s.mgsession"));
    const std::string f = "bad.mgsession";
    auto errorOf = [&](const std::string& text) -> std::string {
        try {
            sessionFromJsonText(text, f);
        } catch (const ParseError& e) {
            return e.what();
        }
        return "no error";
    };
    auto mutated = [&](auto change) {
        json j = good;
        change(j);
        return errorOf(j.dump());
    };

    CHECK(mutated([](json& j) { j["format"] = "motiongp-model"; }) ==
          f + ": expected \"format\": \"motiongp-session\", found \"motiongp-model\"");
    CHECK(mutated([](json& j) { j.erase("format"); }) ==
          f + ": expected \"format\": \"motiongp-session\", found no format field");
    CHECK(mutated([](json& j) { j["version"] = 3; }) ==
          f + ": expected session file version ≤ 2 (this build reads up to version 2), found version 3");
    CHECK(errorOf("") == f + ": expected a JSON session file (format motiongp-session), found an empty file");
    CHECK(errorOf("{\"format\": \"motiongp-session\", \"vers") ==
          f + ": expected a JSON session file (format motiongp-session), found damaged JSON "
              "([json.exception.parse_error.101] parse error at line 1, column 37: syntax error while "
              "parsing object key - invalid string: missing closing quote; last read: '\"vers'; expected string "
              "literal)");
    CHECK(mutated([](json& j) { j["camera"]["yaw_deg"] = nullptr; }) ==
          f + ": expected camera.yaw_deg as a number, found null");
    CHECK(mutated([](json& j) { j["edits"][0]["root_cm"][1] = nullptr; }) ==
          f + ": expected edits[0].root_cm[1] as a number, found null");
    CHECK(mutated([](json& j) { j["frame"] = "3"; }) == f + ": expected frame as an integer, found \"3\"");
    CHECK(mutated([](json& j) { j["frame"] = 2.5; }) == f + ": expected frame as an integer, found 2.5");
    CHECK(mutated([](json& j) { j["adaptive_enabled"] = 1; }) ==
          f + ": expected adaptive_enabled as true or false, found 1");
    CHECK(mutated([](json& j) { j["edits"] = json::object(); }) == f + ": expected edits as an array, found an object");
    CHECK(mutated([](json& j) {
              j["edits"][0]["angles_deg"][0] = json::array({1, 2});
          }) == f + ": expected edits[0].angles_deg[0] as an array of 3 numbers, found an array of 2");
    CHECK(mutated([](json& j) { j.erase("camera"); }) == f + ": expected field 'camera', found none");
    CHECK(mutated([](json& j) { j["camera"].erase("target_cm"); }) ==
          f + ": expected field 'camera.target_cm', found none");
    CHECK(mutated([](json& j) { j["pins"] = json::array({"lknee"}); }) ==
          f + ": expected pins[0] as an effector name (lhand rhand lfoot rfoot head), found \"lknee\"");
    CHECK(mutated([](json& j) { j["edits"][0]["moved"] = json::array({"lknee"}); }) ==
          f + ": expected edits[0].moved[0] as an effector name (lhand rhand lfoot rfoot head), found \"lknee\"");
    CHECK(mutated([](json& j) { j["edits"][0]["moved"] = 3; }) == f + ": expected edits[0].moved as an array, found 3");
    CHECK(mutated([](json& j) { j["compare_mode"] = "ghost"; }) ==
          f + ": expected compare_mode none, plain or model, found \"ghost\"");
    CHECK(mutated([](json& j) { j["edits"][0]["frame"] = -1; }) == f + ": expected edits[0].frame ≥ 0, found -1");
    CHECK(mutated([](json& j) { j["edits"].push_back(j["edits"][0]); }) ==
          f + ": expected distinct edit frames, found frame 5 twice");
    CHECK(mutated([](json& j) { j["frame"] = 1e12; }) == f + ": expected frame as an integer, found 1000000000000.0");
    CHECK(mutated([](json& j) { j["frame"] = 4000000000LL; }) ==
          f + ": expected frame as an integer, found 4000000000");
    CHECK(mutated([](json& j) {
              j["edits"][0]["x"] = json::array({0.5, 0.25});
          }) == f + ": expected edits[0].x of 0 numbers (no model: []), found 2");
    CHECK(mutated([](json& j) {
              j["path"] = {{"effector", "rfoot"},
                           {"key_frames", {10, 5}},
                           {"key_offsets_cm", {{0, 0, 0}, {0, 0, 0}}},
                           {"mode", "direct"}};
          }) == f + ": expected path.key_frames strictly increasing from 0, found 5");
    CHECK(mutated([](json& j) { j["ui"] = json::array(); }) == f + ": expected ui as an object, found an array of 0");
    CHECK(mutated([](json& j) {
              j["keys"] = json::array({4, -1});
          }) == f + ": expected distinct key frames ≥ 0, found -1");
    CHECK(mutated([](json& j) {
              j["keys"] = json::array({4, 4});
          }) == f + ": expected distinct key frames ≥ 0, found 4");
    CHECK(mutated([](json& j) { j["keys"] = json::array({4.5}); }) ==
          f + ": expected keys[0] as an integer, found 4.5");
    CHECK(mutated([](json& j) { j["keys"] = 3; }) == f + ": expected keys as an array, found 3");
    // A session from before keys existed has none.
    CHECK(mutated([](json& j) { j.erase("keys"); }) == "no error");
    CHECK(mutated([](json& j) { j["model"] = 7; }) ==
          f + ": expected model as a motiongp-model object or null, found 7");
    CHECK(errorOf("[1, 2]") == f + ": expected \"format\": \"motiongp-session\", found no format field");
    CHECK(
        errorOf(
            "{\"format\": \"motiongp-session\", \"version\": 1, \"clip\": {\"synthetic\": false, \"synthetic_frames\": "
            "240, "
            "\"path\": \"a.amc\", \"relative_path\": \"\", \"skeleton_path\": \"\", \"skeleton_relative_path\": \"\", "
            "\"sha256\": \"\"}, \"model\": null, \"model_version\": 0, \"compare_model\": null, \"edits\": "
            "[{\"frame\": 0, "
            "\"root_cm\": [1e400, 0, 0], \"angles_deg\": [[0, 0, 0]], \"x\": []}]}") ==
        f + ": expected a JSON session file (format motiongp-session), found damaged JSON "
            "([json.exception.out_of_range.406] number overflow parsing '1e400')");

    // Checks that need the clip.
    SessionData s = sessionFromJsonText(good.dump(), f);
    CHECK(validateAgainstClip(s, clip) == "");
    s.edits[100000] = s.edits[5];
    CHECK(validateAgainstClip(s, clip) ==
          "expected edit frames in 0.." + std::to_string(clip.frameCount() - 1) + " (the clip's frames), found 100000");
    s.edits.erase(100000);
    s.edits[5].pose.anglesDeg.resize(22);
    CHECK(validateAgainstClip(s, clip) == "expected " + std::to_string(clip.skeleton.jointCount()) +
                                              " joint angles per edit (the clip's skeleton), found 22 at frame 5");
    s = sessionFromJsonText(good.dump(), f);
    s.keys = {3, clip.frameCount()};
    CHECK(validateAgainstClip(s, clip) == "expected key frames in 0.." + std::to_string(clip.frameCount() - 1) +
                                              " (the clip's frames), found " + std::to_string(clip.frameCount()));
    s = sessionFromJsonText(good.dump(), f);
    s.frame = clip.frameCount();
    CHECK(validateAgainstClip(s, clip) == "expected frame in 0.." + std::to_string(clip.frameCount() - 1) +
                                              " (the clip's frames), found " + std::to_string(clip.frameCount()));
}

TEST_CASE("with a model, a session's edits are checked against its clip and latent dimension on reading") {
    const auto version = test::walkModel35();
    const gp::GpModel& model = *version->model;
    SessionData s;
    s.model = model;
    s.edits[2] = nudgedEdit(model.clip, 2, Eigen::VectorXd::Constant(model.latentDim() + 1, 0.5));
    CHECK_THROWS_WITH_AS(sessionFromJsonText(sessionToJsonText(s, "/tmp/m.mgsession"), "m.mgsession"),
                         ("m.mgsession: expected edits[0].x of " + std::to_string(model.latentDim()) +
                          " numbers (the model's latent dimension), found " + std::to_string(model.latentDim() + 1))
                             .c_str(),
                         ParseError);
    s.edits[2] = nudgedEdit(model.clip, 2, Eigen::VectorXd());
    s.edits[2].pose.anglesDeg.pop_back();
    CHECK_THROWS_WITH_AS(sessionFromJsonText(sessionToJsonText(s, "/tmp/m.mgsession"), "m.mgsession"),
                         ("m.mgsession: expected " + std::to_string(model.clip.skeleton.jointCount()) +
                          " joint angles per edit (the clip's skeleton), found " +
                          std::to_string(model.clip.skeleton.jointCount() - 1) + " at frame 2")
                             .c_str(),
                         ParseError);
}

TEST_CASE("missing clip, empty file, directory and missing session give clear errors") {
    const std::string dir = test::scratchDir("session_files");
    SessionData s;
    s.clipPath = dir + "/nowhere/x.amc";
    saveSession(dir + "/s.mgsession", s);
    CHECK_THROWS_WITH_AS(loadSession(dir + "/s.mgsession"),
                         (dir +
                          "/s.mgsession: expected the session's clip file (nowhere/x.amc relative to the "
                          "session, or " +
                          dir + "/nowhere/x.amc), found neither")
                             .c_str(),
                         ParseError);
    test::writeText(dir + "/empty.mgsession", "");
    CHECK_THROWS_WITH_AS(
        loadSession(dir + "/empty.mgsession"),
        (dir + "/empty.mgsession: expected a JSON session file (format motiongp-session), found an empty file").c_str(),
        ParseError);
    fs::create_directories(dir + "/folder.mgsession");
    CHECK_THROWS_WITH_AS(loadSession(dir + "/folder.mgsession"),
                         (dir + "/folder.mgsession: expected a file, found a directory").c_str(), ParseError);
    CHECK_THROWS_WITH_AS(
        loadSession(dir + "/none.mgsession"),
        (dir + "/none.mgsession: expected a readable file, found none (No such file or directory)").c_str(),
        ParseError);
}

TEST_CASE("session file: the undo history and the adaptive table round-trip bit-exactly, and version 1 still reads") {
    const std::string amc = test::mocap("asf_amc/35_01.amc");
    const Clip clip = loadClip(amc);
    SessionData s = clipSession(amc);
    s.edits[5] = nudgedEdit(clip, 5, Eigen::VectorXd());
    EditStep drag;
    drag.label = "drag rhand on frame 6";
    drag.before[5] = std::nullopt;
    drag.after[5] = nudgedEdit(clip, 5, Eigen::VectorXd());
    EditStep regen;
    regen.label = "regenerate rfoot, frames 8-9";
    regen.before[7] = nudgedEdit(clip, 7, Eigen::VectorXd());
    regen.before[8] = std::nullopt;
    regen.after[7] = nudgedEdit(clip, 7, Eigen::VectorXd());
    regen.after[7]->pose.rootCm.x() += 1.0 / 7.0;
    regen.after[8] = nudgedEdit(clip, 8, Eigen::VectorXd());
    s.undoSteps = {drag};
    s.redoSteps = {regen};
    AdaptiveHistoryEntry h;
    h.when = std::chrono::system_clock::time_point(std::chrono::milliseconds(1795000000123LL));
    h.frame = 5;
    h.accepted = false;
    h.diagnostic = "refused: L_IK 93.1 above the training frames' p99 65.0";
    h.seconds = 1.0 / 3.0;
    h.versionBefore = h.versionAfter = 2;
    h.rowsAfter = 360;
    h.activeSize = 200;
    h.activeChanged = 3;
    h.newPointActive = true;
    h.objectiveBefore = -1234.5678901234567;
    h.objectiveAfter = -1234.0 / 3.0;
    s.adaptiveHistory = {h};

    const std::string text = sessionToJsonText(s, "/tmp/h.mgsession");
    const SessionData r = sessionFromJsonText(text, "h.mgsession");
    CHECK(validateAgainstClip(r, clip) == "");
    REQUIRE(r.undoSteps.size() == 1);
    REQUIRE(r.redoSteps.size() == 1);
    CHECK(r.undoSteps[0].label == drag.label);
    CHECK_FALSE(r.undoSteps[0].before.at(5));
    CHECK(r.undoSteps[0].after.at(5)->pose.anglesDeg == drag.after[5]->pose.anglesDeg);
    CHECK(r.redoSteps[0].before.at(7)->pose.rootCm == regen.before[7]->pose.rootCm);
    CHECK(r.redoSteps[0].after.at(7)->pose.rootCm == regen.after[7]->pose.rootCm);
    CHECK_FALSE(r.redoSteps[0].before.at(8));
    REQUIRE(r.adaptiveHistory.size() == 1);
    const AdaptiveHistoryEntry& g = r.adaptiveHistory[0];
    CHECK(g.when == h.when);
    CHECK(g.frame == 5);
    CHECK_FALSE(g.accepted);
    CHECK(g.diagnostic == h.diagnostic);
    CHECK(g.seconds == h.seconds);
    CHECK((g.versionBefore == 2 && g.versionAfter == 2 && g.rowsAfter == 360 && g.activeSize == 200));
    CHECK((g.activeChanged == 3 && g.newPointActive));
    CHECK(g.objectiveBefore == h.objectiveBefore);
    CHECK(g.objectiveAfter == h.objectiveAfter);
    CHECK(sessionToJsonText(r, "/tmp/h.mgsession") == text);

    // A history frame outside the clip is caught with the clip, naming the step.
    SessionData bad = r;
    bad.undoSteps[0].after[100000] = std::nullopt;
    CHECK(validateAgainstClip(bad, clip) == "expected undo history frames in 0.." +
                                                std::to_string(clip.frameCount() - 1) +
                                                " (the clip's frames), found 100000 in \"drag rhand on frame 6\"");
    json j = json::parse(text);
    j["history"]["undo"][0]["after"][0]["frame"] = "5";
    CHECK_THROWS_WITH_AS(sessionFromJsonText(j.dump(), "h.mgsession"),
                         "h.mgsession: expected history.undo[0].after[0].frame as an integer, found \"5\"", ParseError);

    // A version-1 file (before the history was saved) reads with an empty history.
    json v1 = json::parse(text);
    v1["version"] = 1;
    v1.erase("history");
    v1.erase("adaptive_history");
    const SessionData old = sessionFromJsonText(v1.dump(), "old.mgsession");
    CHECK(old.undoSteps.empty());
    CHECK(old.adaptiveHistory.empty());
    CHECK(old.edits.size() == 1);
}
