// `motiongp inbetween`: the written clip keeps the keys and every frame outside the gaps, the
// --json report per gap, and bad gaps or methods as one clear error line.
#include <nlohmann/json.hpp>

#include <algorithm>

#include "io/clip_loader.h"
#include "skeleton/forward_kinematics.h"
#include "test_support.h"

using nlohmann::json;
using namespace mgp;

namespace {
const std::string kKickModel = std::string(MOTIONGP_TEST_FIXTURES) + "/kick10_03_fas_m100_t3.model";
}

TEST_CASE("motiongp inbetween: gaps of an unseen clip filled, keys and the rest of the clip kept, one report per gap") {
    const std::string dir = test::scratchDir("cli_inbetween");
    const std::string clipPath = test::mocap("asf_amc/10_02.amc");
    const auto r = test::runCli("inbetween '" + kKickModel + "' --on '" + clipPath + "' --gaps 41:102,201:322 --out '" +
                                dir + "/f.bvh' --json");
    REQUIRE(r.exitCode == 0);
    const json j = json::parse(r.out);
    CHECK(j["method"] == "prior");
    REQUIRE(j["gaps"].size() == 2);
    CHECK(j["gaps"][0]["a"] == 41);
    CHECK(j["gaps"][0]["b"] == 102);
    CHECK(j["gaps"][0]["frames"] == 60);
    for (const json& g : j["gaps"]) {
        CHECK(g["key_error_cm"].is_number());
        CHECK(g["source"]["clip"] == "10_03");
        CHECK(g["variance"]["mean"].get<double>() > 0.0);
        CHECK(g["span"]["max_held_residual_cm"].get<double>() < 1.0);
        CHECK(g["second_difference_deg"]["p95"].is_number());
    }
    // The written clip, read back: every frame outside 42..101 and 202..321 where the clip has it
    // (the BVH round trip keeps joint positions to well under 0.05 cm).
    const Clip original = loadClip(clipPath);
    const Clip written = loadClip(dir + "/f.bvh");
    REQUIRE(written.frameCount() == original.frameCount());
    double worst = 0.0, changed = 0.0;
    FkState fo, fw;
    for (int t = 0; t < original.frameCount(); ++t) {
        forwardKinematics(original.skeleton, original.frames[t], fo);
        forwardKinematics(written.skeleton, written.frames[t], fw);
        double d = 0.0;
        for (int jt = 0; jt < written.skeleton.jointCount(); ++jt) {
            const int o = original.skeleton.findJoint(written.skeleton.joints[jt].name);
            if (o >= 0) d = std::max(d, (fo.jointCm[o] - fw.jointCm[jt]).norm());
        }
        const bool inner = (t > 40 && t < 101) || (t > 200 && t < 321);
        if (inner)
            changed = std::max(changed, d);
        else
            worst = std::max(worst, d);
    }
    CHECK(worst < 0.05);
    CHECK(changed > 1.0);  // the gaps were generated, not copied
}

TEST_CASE("motiongp inbetween: bad gaps and methods are one clear error line") {
    const std::string base = "inbetween '" + kKickModel + "' --on '" + test::mocap("asf_amc/10_02.amc") + "' --out '" +
                             test::scratchDir("cli_inbetween_bad") + "/f.bvh'";
    const std::pair<std::string, std::string> cases[] = {
        {" --gaps 41-102", "expected --gaps as key frames A:B counted from 1"},
        {" --gaps 41:42", "expected at least one frame between the keys of a gap A:B (A + 1 < B), found 41:42"},
        {" --gaps 500:700", "expected gaps inside the clip's frames 1..590, found 500:700"},
        {" --gaps 100:200,150:300",
         "expected gaps in increasing order that do not overlap, found 150:300 after 100:200"},
        {" --gaps 0:20", "expected --gaps as key frames A:B counted from 1"},
        {" --gaps 41:102 --method magic", "expected --method prior, retrieve, interpolate or hold, found 'magic'"},
    };
    for (const auto& c : cases) {  // not a structured binding: clang 14 cannot capture one
        const std::string& args = c.first;
        const std::string& message = c.second;
        CAPTURE(args);
        const auto r = test::runCli(base + args);
        CHECK(r.exitCode == 2);
        CHECK(r.err.find(message) != std::string::npos);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    }
    // Another subject's skeleton.
    const auto r = test::runCli("inbetween '" + kKickModel + "' --on '" + test::mocap("asf_amc/35_01.amc") +
                                "' --gaps 41:102 --out '" + test::scratchDir("cli_inbetween_bad") + "/g.bvh'");
    CHECK(r.exitCode == 2);
    CHECK(r.err.find("expected a clip of the model's skeleton") != std::string::npos);
}
