#pragma once
// A small real model shared by the IK and motion tests: gauge-fixed FAS on 35_01 with M = 100,
// T = 3 (ALGORITHM.md §13 item 14), trained once per test run.
#include "gp/model_version.h"
#include "ik/learned_ik.h"

namespace mgp::test {

gp::ModelVersionPtr walkModel35();
// A learned-IK request starting at clip frame `frame` (captured pose, the frame's latent point).
LearnedIkRequest requestAtFrame(const gp::ModelVersion& version, int frame, int maxIterations = 500);

}  // namespace mgp::test
