#pragma once
// Scaled conjugate gradients, the Netlab/GPmat `scg2` variant (docs/maths.md §7), with the
// non-finite-trial fix of its step 4: a trial point whose value or gradient is not finite counts
// as a failed step with Δ = −∞, so the scale grows ×4 instead of repeating the same failing step.
// Reusable for any objective f(x) -> (value, gradient).
#include <Eigen/Core>
#include <functional>

namespace mgp::gp {

// Returns f(x) and writes ∇f(x) into grad (already sized like x).
using ValueAndGradient = std::function<double(const Eigen::VectorXd& x, Eigen::VectorXd& grad)>;

struct ScgOptions {
    int maxIterations = 100;
    double tolX = 1e-4;  // stop when max_i |α d_i| < tolX AND |Δf| < tolF (on a success)
    double tolF = 1e-4;
    std::function<bool()> shouldStop;  // optional: polled once per iteration (cancellation)
};

enum class ScgStop { kMaxIterations, kConverged, kZeroGradient, kTinyDirection, kBadStart, kStopped };
const char* scgStopName(ScgStop s);

struct ScgResult {
    Eigen::VectorXd x;
    double value = 0.0;
    int iterations = 0;
    int evaluations = 0;
    ScgStop stop = ScgStop::kMaxIterations;
};

ScgResult scgMinimize(const ValueAndGradient& fg, const Eigen::VectorXd& x0, const ScgOptions& options = {});

}  // namespace mgp::gp
