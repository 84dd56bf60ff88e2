// Model ▸ Train on clips…'s candidate list (core/edit/training_candidates.h): the open clip first,
// the clip files of its skeleton beside it offered (AMC of its ASF subject, or BVH of its
// hierarchy), every other file beside it refused with the reason. Run on the shipped clips and on
// a scratch folder of copies (a BVH, an AMC without its ASF, a file of another extension).
#include <doctest/doctest.h>

#include <filesystem>

#include "edit/training_candidates.h"
#include "io/clip_loader.h"
#include "test_support.h"

using namespace mgp;

namespace {
namespace fs = std::filesystem;

const TrainingCandidate* find(const std::vector<TrainingCandidate>& list, const std::string& name) {
    for (const TrainingCandidate& c : list)
        if (c.name == name) return &c;
    return nullptr;
}
}  // namespace

TEST_CASE("training candidates: the shipped kick 10_02 offers 10_03 and refuses the other subjects") {
    const Clip open = loadClip(test::mocap("asf_amc/10_02.amc"));
    const std::vector<TrainingCandidate> list = trainingCandidates(open);
    // 10_02 (open), 10_03 (offered), then 02_03, 16_01, 16_35, 16_36, 35_01 (refused), by name.
    REQUIRE(list.size() == 7u);
    CHECK(list[0].name == "10_02");
    CHECK(list[0].open);
    CHECK(list[0].usable);
    CHECK(list[1].name == "10_03");
    CHECK(list[1].usable);
    CHECK_FALSE(list[1].open);
    CHECK(list[1].reason.empty());
    CHECK(fs::equivalent(list[1].path, test::mocap("asf_amc/10_03.amc")));
    const char* refused[] = {"02_03", "16_01", "16_35", "16_36", "35_01"};
    for (int i = 0; i < 5; ++i) {
        CAPTURE(refused[i]);
        CHECK(list[static_cast<std::size_t>(2 + i)].name == refused[i]);
        CHECK_FALSE(list[static_cast<std::size_t>(2 + i)].usable);
    }
    // The reason names the other skeleton's ASF and what differs (sameSkeleton's words).
    const TrainingCandidate* jump = find(list, "16_01");
    REQUIRE(jump);
    CHECK(jump->reason.rfind("another skeleton (16.asf): joint ", 0) == 0);
    CHECK(find(list, "35_01")->reason.rfind("another skeleton (35.asf): ", 0) == 0);
}

TEST_CASE("training candidates: BVH, a missing ASF and other files beside the open clip are refused, each with why") {
    const std::string dir = test::scratchDir("training_candidates");
    for (const char* f : {"asf_amc/10.asf", "asf_amc/10_02.amc", "asf_amc/10_03.amc", "asf_amc/16.asf",
                          "asf_amc/16_01.amc", "bvh/02_03.bvh"})
        fs::copy_file(test::mocap(f), dir + "/" + fs::path(f).filename().string(),
                      fs::copy_options::overwrite_existing);
    fs::copy_file(test::mocap("asf_amc/10_03.amc"), dir + "/77_01.amc",
                  fs::copy_options::overwrite_existing);  // no 77.asf
    test::writeText(dir + "/notes.txt", "not a clip\n");
    const Clip open = loadClip(dir + "/10_03.amc");
    const std::vector<TrainingCandidate> list = trainingCandidates(open);
    REQUIRE(list.size() == 5u);  // notes.txt and the ASF files are not clips: not listed
    CHECK(list[0].name == "10_03");
    CHECK(list[0].open);
    CHECK(list[1].name == "10_02");
    CHECK(list[1].usable);
    CHECK(list[2].name == "02_03");
    CHECK_FALSE(list[2].usable);
    CHECK(list[2].reason == "a BVH clip: another skeleton than the open ASF/AMC (retargeting is not supported)");
    CHECK(list[3].name == "16_01");
    CHECK(list[3].reason.rfind("another skeleton (16.asf): ", 0) == 0);
    CHECK(list[4].name == "77_01");
    CHECK_FALSE(list[4].usable);
    CHECK(list[4].reason.rfind("cannot read its skeleton: ", 0) == 0);
    CHECK(list[4].reason.find("77.asf") != std::string::npos);

    // Added by path: the same checks; the open clip itself and a missing file are refused.
    CHECK(trainingCandidate(open, dir + "/10_02.amc").usable);
    CHECK(trainingCandidate(open, dir + "/16_01.amc").reason.rfind("another skeleton (16.asf): ", 0) == 0);
    CHECK(trainingCandidate(open, dir + "/10_03.amc").reason == "the open clip is always included");
    CHECK(trainingCandidate(open, dir + "/10_99.amc").reason == "no such file");
    CHECK(trainingCandidate(open, dir + "/notes.txt").reason == "expected a clip file (.amc or .bvh), found '.txt'");
}

TEST_CASE("training candidates: an open BVH clip trains, BVH of its hierarchy are offered, others refused") {
    const std::string dir = test::scratchDir("training_candidates_bvh");
    for (const char* f : {"bvh/02_03.bvh", "bvh/49_04.bvh", "asf_amc/02_03.amc", "asf_amc/02.asf"})
        fs::copy_file(test::mocap(f), dir + "/" + fs::path(f).filename().string(),
                      fs::copy_options::overwrite_existing);
    fs::copy_file(test::mocap("bvh/02_03.bvh"), dir + "/02_04.bvh", fs::copy_options::overwrite_existing);
    const Clip open = loadClip(dir + "/02_03.bvh");
    const std::vector<TrainingCandidate> list = trainingCandidates(open);
    // 02_03.bvh (open), 02_04 (offered: the same hierarchy), then 02_03.amc and 49_04 (refused).
    REQUIRE(list.size() == 4u);
    CHECK(list[0].open);
    CHECK(list[0].usable);
    CHECK(list[1].name == "02_04");
    CHECK(list[1].usable);
    CHECK(list[2].name == "02_03");
    CHECK(list[2].reason == "an ASF/AMC clip: another skeleton than the open BVH (retargeting is not supported)");
    CHECK(list[3].name == "49_04");
    CHECK(list[3].reason.rfind("another skeleton (49_04.bvh): joint ", 0) == 0);
}
