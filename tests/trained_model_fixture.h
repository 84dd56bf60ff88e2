#pragma once
// A small real model shared by the IK and motion tests: gauge-fixed FAS on 35_01 with M = 100,
// T = 3 (ALGORITHM.md §13 item 14), trained once per test run.
#include "gp/model_version.h"

namespace mgp::test {

gp::ModelVersionPtr walkModel35();

}  // namespace mgp::test
