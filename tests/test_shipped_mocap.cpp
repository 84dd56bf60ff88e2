// The clips shipped in assets/mocap are byte-for-byte CMU files: every file is listed in the
// folder's README with its SHA-256, the checksums match, and the subset stays within 3 MB.
#include <filesystem>
#include <map>
#include <regex>

#include "gp/sha256.h"
#include "io/clip_loader.h"
#include "test_support.h"

namespace fs = std::filesystem;

TEST_CASE("shipped mocap: every file is listed with its SHA-256, matches it, and the subset is at most 3 MB") {
    const std::string root = mgp::test::mocap("");
    const std::string readme = mgp::test::readText(root + "/README.md");
    // A table row: | `asf_amc/35_01.amc` | ... | `<64 hex digits>` |
    const std::regex row(R"(\| `((?:asf_amc|bvh)/[^`]+)` \|[^\n]*`([0-9a-f]{64})` \|)");
    std::map<std::string, std::string> listed;
    for (auto it = std::sregex_iterator(readme.begin(), readme.end(), row); it != std::sregex_iterator(); ++it)
        listed[(*it)[1]] = (*it)[2];
    std::uintmax_t total = 0;
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        if (!entry.is_regular_file() || entry.path().filename() == "README.md") continue;
        const std::string relative = fs::relative(entry.path(), root).string();
        CAPTURE(relative);
        REQUIRE_MESSAGE(listed.count(relative) == 1, "not listed in assets/mocap/README.md");
        CHECK(mgp::gp::sha256OfFile(entry.path().string()) == listed[relative]);
        total += entry.file_size();
        ++files;
    }
    CHECK(files == static_cast<int>(listed.size()));  // nothing listed is missing
    CHECK(files >= 10);
    CHECK(total <= 3'000'000);
}

TEST_CASE("shipped mocap: the clips the tests and the editor rely on load") {
    // A walk, kicks (the editor's default 10_02 and the held-out 10_03), a jump, and one BVH of each
    // cgspeed convention.
    for (const char* clip : {"asf_amc/35_01.amc", "asf_amc/10_02.amc", "asf_amc/10_03.amc", "asf_amc/16_01.amc",
                             "bvh/02_03.bvh", "bvh/49_04.bvh", "bvh/131_01.bvh"}) {
        CAPTURE(clip);
        CHECK(mgp::loadClip(mgp::test::mocap(clip)).frameCount() > 100);
    }
}
