#pragma once
// The folders the rendering and editor tests read and write, named once for every test file.
#include <string>

#include "test_paths.h"

namespace mgp::test {

inline const std::string kMocap = MOTIONGP_TEST_MOCAP;
inline const std::string kGoldenDir = MOTIONGP_GOLDEN_DIR;
inline const std::string kOutDir = MOTIONGP_GL_OUT_DIR;

}  // namespace mgp::test
