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

// The same minimisation as a resumable state machine: the caller evaluates the objective where
// request() asks, writes the gradient into gradientSlot() and passes the value to supply(), until
// done(). scgMinimize is this loop with one objective; Step 8 runs many machines side by side and
// evaluates all their requests in one batched evaluation (docs/maths.md §7). Each machine takes
// exactly the steps scgMinimize takes from the same values.
class ScgMachine {
public:
    ScgMachine(const Eigen::VectorXd& x0, const ScgOptions& options);

    bool done() const { return phase_ == Phase::kDone; }
    const Eigen::VectorXd& request() const;           // where to evaluate next (not done())
    Eigen::VectorXd& gradientSlot();                  // write ∇f(request()) here, sized like x0
    void supply(double value);                        // f(request()); advances to the next request or done()
    const ScgResult& result() const { return res_; }  // complete once done()

private:
    enum class Phase { kStart, kCurvature, kTrial, kDone };
    void beginIteration();  // the top of an iteration: a curvature probe, a trial step, or the end
    void requestTrial();    // the step along dir from the curvature estimate
    void finish(ScgStop stop);

    ScgOptions opt_;
    ScgResult res_;
    Phase phase_ = Phase::kStart;
    Eigen::VectorXd x_, g_, gOld_, gNew_, gPlus_, xNew_, xPlus_, dir_;
    double fOld_ = 0.0, alpha_ = 0.0;
    bool success_ = true;
    int nSuccess_ = 0, iteration_ = 0;
    double beta_ = 1.0, mu_ = 0.0, kappa_ = 0.0, theta_ = 0.0, sigma_ = 0.0;
};

}  // namespace mgp::gp
