#pragma once
// A small real model shared by the IK and motion tests: gauge-fixed FAS on 35_01 with M = 100,
// T = 3, loaded from the committed file tests/fixtures/walk35_fas_m100_t3.model (its README says
// how it is regenerated), never trained at test time: every CPU sees the same model.
#include <string>

#include "gp/model_version.h"
#include "ik/learned_ik.h"

namespace mgp::test {

std::string walkModelPath();
gp::ModelVersionPtr walkModel35();
// A learned-IK request starting at clip frame `frame` (captured pose, the frame's latent point).
LearnedIkRequest requestAtFrame(const gp::ModelVersion& version, int frame, int maxIterations = 500);

}  // namespace mgp::test
