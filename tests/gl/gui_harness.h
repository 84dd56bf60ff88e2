#pragma once
// The names the path UI tests use for the shared offscreen editor harness (editor_harness.h).
#include <doctest/doctest.h>

#include "editor_harness.h"

namespace mgp::test {

inline const std::string kMocap = MOTIONGP_TEST_MOCAP;
inline const std::string kGoldenDir = MOTIONGP_GOLDEN_DIR;
inline const std::string kOutDir = MOTIONGP_GL_OUT_DIR;
constexpr int kW = kGuiWidth, kH = kGuiHeight;

}  // namespace mgp::test
