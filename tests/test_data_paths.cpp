// Search order for the mocap folder (docs/architecture.md §8) and the synthetic fallback.
#include <cstdlib>
#include <filesystem>

#include "io/data_paths.h"
#include "test_support.h"

using namespace mgp;

TEST_CASE("mocap folder search order: --data, then $MOTIONGP_DATA, then the compiled-in path") {
    const std::string shared = test::sharedMocapDir();
    const std::string other = test::scratchDir("fake_mocap");
    REQUIRE(std::system(("mkdir -p '" + other + "/bvh'").c_str()) == 0);
    CHECK(isMocapFolder(other));
    CHECK_FALSE(isMocapFolder(test::scratchDir("empty_folder")));

    ::unsetenv("MOTIONGP_DATA");
    CHECK(findMocapFolder(other, "").value() == other);
    CHECK_FALSE(findMocapFolder("/does/not/exist", "").has_value());  // an explicit choice is kept
    ::setenv("MOTIONGP_DATA", other.c_str(), 1);
    CHECK(findMocapFolder("", "").value() == other);
    ::unsetenv("MOTIONGP_DATA");
    if (!shared.empty())
        CHECK(findMocapFolder("", "").value() == shared);
    else
        CHECK_FALSE(findMocapFolder("", "").has_value());
    CHECK(defaultClipIn(test::mocap("")).value().find("10_02.amc") != std::string::npos);
    CHECK_FALSE(defaultClipIn(other).has_value());
}

TEST_CASE("the shipped clips: found without ../shared, the editor's fallback, never replacing an explicit --data") {
    ::unsetenv("MOTIONGP_DATA");
    const auto shipped = findShippedMocapFolder("");
    REQUIRE(shipped.has_value());
    CHECK(defaultClipIn(*shipped).has_value());  // the editor opens the 10_02 kick on a fresh clone
    const std::string shared = test::sharedMocapDir();
    CHECK(findEditorMocapFolder("", "").value() == (shared.empty() ? *shipped : shared));
    CHECK_FALSE(findEditorMocapFolder("/does/not/exist", "").has_value());
}

TEST_CASE("data paths: absolutePath makes a relative path absolute and normal, and leaves empty alone") {
    CHECK(absolutePath("") == "");
    const std::string cwd = std::filesystem::current_path().lexically_normal().string();
    CHECK(absolutePath("a/./b/../c.amc") == (std::filesystem::path(cwd) / "a/c.amc").string());
    CHECK(absolutePath("/x/y/../z.bvh") == "/x/z.bvh");
}
