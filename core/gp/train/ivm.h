#pragma once
// Active-set selection by the IVM criterion for Gaussian noise (docs/maths.md §6): greedily pick
// the point of largest noise-free posterior variance — a pivoted partial Cholesky. It depends on
// X and θ only, never on Y or W. Ties go to the smallest index; no swap refinement.
#include <Eigen/Core>
#include <vector>

#include "gp/kernel.h"

namespace mgp::gp {

struct IvmResult {
    std::vector<int> active;    // in selection order (all 0..N−1 in order when M ≥ N)
    Eigen::VectorXd variances;  // noise-free posterior variance of every point after selection
                                // (clamped at ≥ 0); empty when M ≥ N
};

// threads: workers for each step's kernel column and update (≥ 1; the bits do not depend on it).
IvmResult selectActiveSet(const Kernel& kernel, const Eigen::MatrixXd& X, int m, int threads = 1);

}  // namespace mgp::gp
