#pragma once
// Where the tests find this checkout's files and this build's binary and scratch folders. The paths
// are absolute, so they live in one file the build generates (test_paths.cpp in the build folder,
// tests/CMakeLists.txt) rather than in -D flags: every other test file then compiles to the same
// object in any clone, and a compiler cache reuses it (docs/architecture.md, "Build").
namespace mgp::test::paths {

const char* mocap();        // the shipped clips, assets/mocap
const char* sharedMocap();  // the full CMU set beside the checkout (it may be absent)
const char* fixtures();     // tests/fixtures
const char* sourceDir();    // tests/
const char* binary();       // the motiongp executable
const char* tmp();          // the tests' scratch folder in the build tree
// The rendering and editor tests' (tests/gl): golden images, their output folder, and the
// preload library that hides libGL.so.1.
const char* goldenDir();
const char* glOutDir();
const char* noLibglPreload();

}  // namespace mgp::test::paths

#define MOTIONGP_TEST_MOCAP (::mgp::test::paths::mocap())
#define MOTIONGP_TEST_SHARED_MOCAP (::mgp::test::paths::sharedMocap())
#define MOTIONGP_TEST_FIXTURES (::mgp::test::paths::fixtures())
#define MOTIONGP_TEST_SOURCE_DIR (::mgp::test::paths::sourceDir())
#define MOTIONGP_TEST_BINARY (::mgp::test::paths::binary())
#define MOTIONGP_TEST_TMP (::mgp::test::paths::tmp())
#define MOTIONGP_GOLDEN_DIR (::mgp::test::paths::goldenDir())
#define MOTIONGP_GL_OUT_DIR (::mgp::test::paths::glOutDir())
#define MOTIONGP_TEST_NO_LIBGL_PRELOAD (::mgp::test::paths::noLibglPreload())
