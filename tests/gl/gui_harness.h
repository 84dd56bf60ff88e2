#pragma once
// The names the path UI tests use for the shared offscreen editor harness (editor_harness.h).
#include <doctest/doctest.h>

#include "editor_harness.h"
#include "gl_test_paths.h"

namespace mgp::test {

constexpr int kW = kGuiWidth, kH = kGuiHeight;

}  // namespace mgp::test
