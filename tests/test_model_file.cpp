// Model file: bit-exact doubles, self-contained round trip, version and damage errors, atomic
// writes.
#include <doctest/doctest.h>

#include "test_support.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "gp/model_file.h"
#include "gp/sha256.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "io/parse_error.h"

using namespace mgp::gp;

namespace {

GpModel smallModel() {
    const mgp::Clip clip = mgp::loadClip(std::string(MOTIONGP_TEST_MOCAP) + "/asf_amc/35_01.amc");
    std::vector<int> frames;
    for (int t = 0; t < clip.frameCount(); t += 7) frames.push_back(t);
    TrainOptions o;
    o.activeSize = 30;
    o.outerIterations = 1;
    o.scgIterations = 10;
    o.pointIterations = 10;
    TrainResult r = train(trainingDataFromClip(clip, frames), o);
    r.model.clip = clip;
    r.model.sourceFile = "35_01.amc";
    r.model.sourceSha256 = sha256OfFile(std::string(MOTIONGP_TEST_MOCAP) + "/asf_amc/35_01.amc");
    return r.model;
}

std::string tmpDir() {
    const std::string dir = mgp::test::scratchDir("model_file");
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace

TEST_CASE("model_file: SHA-256 matches the published checksum of 35_01.amc and the FIPS vector") {
    CHECK(sha256Hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    CHECK(sha256Hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    CHECK(sha256OfFile(std::string(MOTIONGP_TEST_MOCAP) + "/asf_amc/35_01.amc") ==
          "0743f4ea48e7e199cd56b2810b5ce81f8ede08d32ff79aa4e363c44cc4fe33aa");
}

TEST_CASE("model_file: nlohmann-json round-trips awkward doubles bit-exactly") {
    std::mt19937_64 rng(42);
    GpModel m = smallModel();
    // Overwrite μ with random bit patterns of finite doubles (tiny, huge, subnormal).
    for (Eigen::Index i = 0; i < m.mu.size(); ++i) {
        double v;
        do {
            const std::uint64_t bits = rng();
            std::memcpy(&v, &bits, sizeof v);
        } while (!std::isfinite(v));
        m.mu[i] = v;
    }
    m.mu[0] = 0.1;
    m.mu[1] = 5e-324;
    m.mu[2] = -1.7976931348623157e308;
    const GpModel back = modelFromJsonText(modelToJsonText(m), "mem");
    CHECK(mgp::test::bitsEqual(m.mu, back.mu));
}

TEST_CASE("model_file: save/load is self-contained and bit-exact, writes are atomic") {
    const GpModel m = smallModel();
    const std::string dir = tmpDir();  // each call empties the folder: call it once
    const std::string path = dir + "/m.json";
    saveModel(path, m);
    for (const auto& e : std::filesystem::directory_iterator(dir))
        CHECK(e.path().filename().string().find(".tmp.") == std::string::npos);
    const GpModel b = loadModel(path);
    CHECK(b.kind == m.kind);
    CHECK(mgp::test::bitsEqual(b.logParams, m.logParams));
    CHECK(mgp::test::bitsEqual(b.w, m.w));
    CHECK(mgp::test::bitsEqual(b.mu, m.mu));
    CHECK(mgp::test::bitsEqual(b.X, m.X));
    CHECK(mgp::test::bitsEqual(b.Y, m.Y));  // rebuilt from the stored clip poses
    CHECK(mgp::test::bitsEqual(b.constantValues, m.constantValues));
    CHECK(b.active == m.active);
    CHECK(b.keptColumns == m.keptColumns);
    CHECK(b.constantColumns == m.constantColumns);
    CHECK(b.trainingFrames == m.trainingFrames);
    REQUIRE(b.objectiveHistory.size() == m.objectiveHistory.size());
    CHECK(std::memcmp(b.objectiveHistory.data(), m.objectiveHistory.data(),
                      sizeof(double) * m.objectiveHistory.size()) == 0);
    CHECK(b.sourceSha256 == m.sourceSha256);
    CHECK(b.clip.frameCount() == m.clip.frameCount());
    CHECK(mgp::test::bitsEqual(mgp::poseMatrix(b.clip), mgp::poseMatrix(m.clip)));
    CHECK(mgp::test::bitsEqual(mgp::rootTranslations(b.clip), mgp::rootTranslations(m.clip)));
    CHECK(b.clip.skeleton.jointCount() == m.clip.skeleton.jointCount());
    // Saving the loaded model reproduces the file byte for byte.
    CHECK(modelToJsonText(b) == mgp::test::readText(path));
    // The loaded model predicts like the original.
    Eigen::VectorXd f1, f2;
    double v1 = 0, v2 = 0;
    m.posterior().predict(m.X.row(3).transpose(), f1, v1);
    b.posterior().predict(b.X.row(3).transpose(), f2, v2);
    CHECK(mgp::test::bitsEqual(f1, f2));
    CHECK(v1 == v2);
}

TEST_CASE("model_file: newer versions, other formats, truncated and empty files are clear errors") {
    const std::string text = modelToJsonText(smallModel());
    auto expectError = [](const std::string& t, const std::string& needle) {
        try {
            modelFromJsonText(t, "x.json");
            FAIL("expected a ParseError");
        } catch (const mgp::ParseError& e) {
            const std::string msg = e.what();
            CAPTURE(msg);
            CHECK(msg.find("x.json") == 0);
            CHECK(msg.find("expected") != std::string::npos);
            CHECK(msg.find(needle) != std::string::npos);
        }
    };
    std::string newer = text;
    newer.replace(newer.find("\"version\": 1"), std::strlen("\"version\": 1"), "\"version\": 3");
    expectError(newer, "version 3");
    // Version 2 (several clips) needs its clip list.
    std::string v2 = text;
    v2.replace(v2.find("\"version\": 1"), std::strlen("\"version\": 1"), "\"version\": 2");
    expectError(v2, "'more_clips'");
    expectError(text.substr(0, text.size() / 2), "damaged JSON");
    expectError("", "empty file");
    expectError("{\"format\": \"something-else\", \"version\": 1}", "something-else");
    std::string noX = text;
    noX.replace(noX.find("\"X\""), 3, "\"Z\"");
    expectError(noX, "'X'");
    // Regressions (UBSan float-cast-overflow): huge or fractional numbers where integers belong.
    const nlohmann::json doc = nlohmann::json::parse(text);
    nlohmann::json bad = doc;
    bad["N"] = 1e300;
    expectError(bad.dump(1), "an integer for 'N', found 1e+300");
    bad = doc;
    bad["training"]["iterations"] = -1e300;
    expectError(bad.dump(1), "an integer for 'iterations', found -1e+300");
    bad = doc;
    bad["active"][0] = 4294967296LL;  // would truncate to 0, a valid index
    expectError(bad.dump(1), "integers in active");
    bad = doc;
    bad["clip"]["joints"][1]["parent"] = 1e300;
    expectError(bad.dump(1), "an integer for parent, found 1e+300");
    bad = doc;
    bad["clip"]["joints"][1]["order"][0] = 1e300;
    expectError(bad.dump(1), "an axis 0..2");
    bad = doc;
    bad["clip"]["first_frame_label"] = 1e300;
    expectError(bad.dump(1), "an integer for first_frame_label, found 1e+300");
    // A NaN kernel parameter (JSON writes it as null) is refused with the field's name, never
    // read as θ = 1.
    bad = doc;
    bad["log_params"][1] = nullptr;
    expectError(bad.dump(1), "numbers in log_params, found null");
    CHECK_THROWS_AS(loadModel(tmpDir() + "/does-not-exist.json"), mgp::ParseError);
}

TEST_CASE("model_file: the objective history is optional, bit-exact and validated") {
    GpModel m = smallModel();
    REQUIRE(m.objectiveHistory.size() == static_cast<std::size_t>(m.iterations) + 1);
    m.objectiveHistory.push_back(0.1);
    m.objectiveHistory.push_back(-1.2345678901234567e-300);
    const GpModel back = modelFromJsonText(modelToJsonText(m), "mem");
    REQUIRE(back.objectiveHistory.size() == m.objectiveHistory.size());
    CHECK(std::memcmp(back.objectiveHistory.data(), m.objectiveHistory.data(),
                      sizeof(double) * m.objectiveHistory.size()) == 0);

    nlohmann::json j = nlohmann::json::parse(modelToJsonText(m));
    SUBCASE("a file written before the field existed loads with an empty history") {
        j["training"].erase("objective_history");
        const GpModel old = modelFromJsonText(j.dump(1), "old.json");
        CHECK(old.objectiveHistory.empty());
        CHECK(mgp::test::bitsEqual(old.logParams, m.logParams));
    }
    auto message = [](const nlohmann::json& doc) -> std::string {
        try {
            modelFromJsonText(doc.dump(1), "x.json");
        } catch (const mgp::ParseError& e) {
            return e.what();
        }
        return "no error";
    };
    SUBCASE("a null entry is rejected") {
        j["training"]["objective_history"][1] = nullptr;
        CHECK(message(j) == "x.json: expected numbers in training.objective_history, found null");
    }
    SUBCASE("a string entry is rejected") {
        j["training"]["objective_history"][0] = "12.5";
        CHECK(message(j) == "x.json: expected numbers in training.objective_history, found \"12.5\"");
    }
    SUBCASE("a non-array is rejected") {
        j["training"]["objective_history"] = 3.0;
        CHECK(message(j) == "x.json: expected training.objective_history as an array of numbers, found number");
    }
}
