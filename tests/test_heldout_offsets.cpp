// The held-out protocol over several offsets (core/eval/layout_quality.h, docs/maths.md §20):
// the splits of different offsets are disjoint and cover the frames, the spread is the mean and
// sample sd of the per-offset values, and `evaluate --heldout-offsets` reports each split and
// their mean.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "eval/layout_quality.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("held-out offsets: offset k holds out positions k, k+10, ... and offset 0 the 10th, 20th, ...") {
    std::vector<int> frames;
    for (int f = 0; f < 35; ++f) frames.push_back(100 + f);
    CHECK(eval::everyNthHeldOut(frames, 10, 0).heldFrames == std::vector<int>{109, 119, 129});
    CHECK(eval::everyNthHeldOut(frames, 10).heldFrames == eval::everyNthHeldOut(frames, 10, 0).heldFrames);
    CHECK(eval::everyNthHeldOut(frames, 10, 3).heldFrames == std::vector<int>{102, 112, 122, 132});
    CHECK(eval::everyNthHeldOut(frames, 10, 6).heldFrames == std::vector<int>{105, 115, 125});
    CHECK_THROWS(eval::everyNthHeldOut(frames, 10, 10));
    CHECK_THROWS(eval::everyNthHeldOut(frames, 10, -1));
}

TEST_CASE("held-out offsets: the splits are disjoint, and each split covers the frames exactly once") {
    // Unsorted input with a duplicate and a cut: positions count in sorted, de-duplicated order.
    std::vector<int> frames;
    for (int f = 57; f >= 0; --f) frames.push_back(f < 30 ? f : f + 40);
    frames.push_back(12);
    std::set<int> unique(frames.begin(), frames.end());
    std::set<int> heldAll;
    std::size_t heldTotal = 0;
    for (int offset = 0; offset < 7; ++offset) {
        const eval::HeldOutSplit s = eval::everyNthHeldOut(frames, 7, offset);
        CHECK(std::is_sorted(s.trainFrames.begin(), s.trainFrames.end()));
        CHECK(std::is_sorted(s.heldFrames.begin(), s.heldFrames.end()));
        std::set<int> both(s.trainFrames.begin(), s.trainFrames.end());
        for (int f : s.heldFrames) CHECK(both.insert(f).second);  // held frames are not trained on
        CHECK(both == unique);
        CHECK(s.trainFrames.size() + s.heldFrames.size() == unique.size());
        for (int f : s.heldFrames) CHECK(heldAll.insert(f).second);  // no frame held out by two offsets
        heldTotal += s.heldFrames.size();
    }
    // All `every` offsets together hold out every frame exactly once.
    CHECK(heldTotal == unique.size());
    CHECK(heldAll == unique);
}

TEST_CASE("held-out offsets: spread is mean, sample sd, min and max") {
    const eval::Spread s = eval::spreadOf({1.0, 2.0, 3.0, 6.0});
    CHECK(s.count == 4);
    CHECK(s.mean == doctest::Approx(3.0));
    CHECK(s.sd == doctest::Approx(std::sqrt(14.0 / 3.0)));  // (4 + 1 + 0 + 9) / (4 − 1)
    CHECK(s.min == 1.0);
    CHECK(s.max == 6.0);
    const eval::Spread one = eval::spreadOf({0.25});
    CHECK(one.mean == 0.25);
    CHECK(one.sd == 0.0);
    CHECK(eval::spreadOf({}).count == 0);
}

TEST_CASE("held-out offsets: the summary is the mean over the per-offset reports") {
    eval::HeldOutOffsetsReport rep;
    eval::HeldOutReport a, b, c;
    a.rmsDeg = 0.2, a.nearestRmsDeg = 0.5, a.timeRmsDeg = 1.0, a.timeCount = 3;
    b.rmsDeg = 0.4, b.nearestRmsDeg = 0.7, b.timeRmsDeg = 2.0, b.timeCount = 2;
    c.rmsDeg = 0.9, c.nearestRmsDeg = 0.6, c.timeRmsDeg = 0.0, c.timeCount = 0;  // no in-between frame
    rep.perOffset = {a, b, c};
    eval::summarizeHeldOut(rep);
    CHECK(rep.rmsDeg.mean == doctest::Approx(0.5));
    CHECK(rep.rmsDeg.min == 0.2);
    CHECK(rep.rmsDeg.max == 0.9);
    CHECK(rep.nearestRmsDeg.mean == doctest::Approx(0.6));
    CHECK(rep.nearestRmsDeg.sd == doctest::Approx(0.1));
    // In-betweening averages only the splits that had an in-between frame.
    CHECK(rep.timeRmsDeg.count == 2);
    CHECK(rep.timeRmsDeg.mean == doctest::Approx(1.5));
}

TEST_CASE("held-out offsets: one retraining per offset on a real clip, each scored on its own split") {
    const Clip clip = loadClip(mgp::test::mocap("asf_amc/35_01.amc"));
    gp::GpModel m;
    m.clip = clip;
    for (int f = 0; f < 60; ++f) m.trainingFrames.push_back(f);
    gp::TrainOptions o;
    o.activeSize = 30;
    o.outerIterations = 2;
    o.scgIterations = 20;
    o.pointIterations = 20;
    o.threads = 1;
    o.prior = gp::LatentPrior::kNone;
    const eval::HeldOutOffsetsReport rep = eval::heldOutOverOffsets(m, o, 10, {0, 5});
    REQUIRE(rep.perOffset.size() == 2);
    CHECK(rep.offsets == std::vector<int>{0, 5});
    CHECK(rep.trainSeconds.size() == 2);
    for (const eval::HeldOutReport& h : rep.perOffset) {
        CHECK(h.heldOut == 6);
        CHECK(h.trained == 54);
        CHECK(std::isfinite(h.rmsDeg));
        CHECK(h.nearestRmsDeg > 0.0);  // the held-out frames are not training frames
    }
    // The two splits are different data: their errors differ, and the summary is their mean.
    CHECK(rep.perOffset[0].rmsDeg != rep.perOffset[1].rmsDeg);
    CHECK(rep.rmsDeg.mean == doctest::Approx(0.5 * (rep.perOffset[0].rmsDeg + rep.perOffset[1].rmsDeg)));
    // A split too small to train on is an error, not a silent empty report.
    gp::GpModel tiny;
    tiny.clip = clip;
    tiny.trainingFrames = {0, 1, 2};
    CHECK_THROWS(eval::heldOutOverOffsets(tiny, o, 10, {0}));
}

TEST_CASE("cmd evaluate: --heldout-offsets reports every split and their mean") {
    const std::string base = "evaluate " + mgp::test::walkModelPath() + " --no-yardstick --json --threads 1";
    const mgp::test::CliResult r = mgp::test::runCli(base + " --heldout-iters 1 --heldout-offsets 0,5");
    REQUIRE(r.exitCode == 0);
    const auto j = nlohmann::json::parse(r.out);
    const auto& h = j["heldout"];
    REQUIRE(h["per_offset"].size() == 2);
    CHECK(h["offsets"] == nlohmann::json::array({0, 5}));
    CHECK(h["per_offset"][0]["offset"] == 0);
    CHECK(h["per_offset"][1]["offset"] == 5);
    const double r0 = h["per_offset"][0]["rms_deg"], r1 = h["per_offset"][1]["rms_deg"];
    CHECK(h["rms_deg"].get<double>() == doctest::Approx(0.5 * (r0 + r1)));
    CHECK(h["spread"]["rms_deg"]["mean"].get<double>() == doctest::Approx(0.5 * (r0 + r1)));
    CHECK(h["spread"]["rms_deg"]["sd"].get<double>() == doctest::Approx(std::abs(r0 - r1) / std::sqrt(2.0)));
    for (const char* bad :
         {" --heldout-offsets 0,0", " --heldout-offsets 10", " --heldout-offsets 1,x", " --heldout-offsets ,"}) {
        const mgp::test::CliResult e = mgp::test::runCli(base + bad);
        INFO(bad);
        CHECK(e.exitCode == 2);
        CHECK(e.err.find("--heldout-offsets") != std::string::npos);
    }
}
