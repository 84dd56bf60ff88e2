#pragma once
// Learned IK (docs/maths.md §10): the most likely pose under the GPLVM prior that meets the targets,
//
//   minimise over (x, y):  F = (1 − λ) L_IK(x, y) + λ Σ_e ‖FK_e(y) − c_e‖²     (cm, λ = 0.999)
//
// y holds the model's kept pose columns (degrees); constant columns stay at the model's values,
// DOFs outside the pose vector (an ASF clip's hands, toes) and the root translation stay at the
// start pose's values. L-BFGS (LBFGS++) from the warm start (x, y) of the request. Interactive
// stopping rule: stop when F changed < 1e-7 relative over 5 iterations, or at the iteration cap;
// `converged` additionally requires every residual < 0.05 cm. LBFGS++ throws on a line-search
// failure and leaves x at its last trial point: the solver keeps the best (F, x, y) it evaluated,
// catches, and returns that best with a diagnostic. No exception leaves solve().
//
// LearnedIkSolver holds a preallocated workspace for one model version (vectors, FK state, the
// L-BFGS solver): after the first solve, a drag allocates nothing of ours; LBFGS++ itself makes
// two small temporaries per iteration (its add_correction(x − x_prev, g − g_prev)).
#include <LBFGS.h>
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "gp/model_version.h"
#include "ik/ik_types.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"

namespace mgp {

struct LearnedIkRequest {
    Pose start;              // full pose of the model's skeleton (root translation is kept)
    Eigen::VectorXd startX;  // latent warm start (d)
    std::vector<IkConstraint> constraints;
    double lambda = 0.999;
    int maxIterations = 50;       // cap per call (the UI refines further when idle)
    double stallRelative = 1e-7;  // F change over `stallWindow` iterations
    int stallWindow = 5;
    double convergedResidualCm = 0.05;
    // Diagonal preconditioning: L-BFGS runs on u with z = S·u, S = diag(H_ii^(-1/2)) from the
    // start point's diagonal curvature (analytic for y, numeric for x). The problem is stiff
    // (constraint curvature ~1000× the prior's, lever arms from cm to m), so this matters.
    bool precondition = true;
};

// Why a solve stopped. `diagnostic` says the same in words (and a line search's message).
enum class LearnedIkStop {
    kInvalidRequest,    // validate() refused it; nothing was solved
    kConverged,         // the stopping rule was met with every residual < convergedResidualCm
    kStalled,           // the stopping rule (F stalled, or a zero gradient) was met, residuals not tight
    kIterationCap,      // maxIterations reached
    kLineSearchFailed,  // LBFGS++ threw; the best point seen is returned
};
const char* learnedIkStopName(LearnedIkStop stop);
// The same reason as a JSON key, in snake case like ikStopName: "converged", "iteration_cap",
// "line_search_failed", "invalid_request", "stalled".
const char* learnedIkStopKey(LearnedIkStop stop);

// The backtracking line search of LBFGS++, counting the line searches started in the objective
// functor it is given: LBFGS++ returns no iteration count when it throws.
template <class Scalar>
struct CountingLineSearch {
    template <typename Foo, typename Vector, typename Param>
    static void LineSearch(Foo& f, Scalar& fx, Vector& x, Vector& grad, Scalar& step, const Vector& drt,
                           const Vector& xp, const Param& param) {
        ++*f.lineSearches;
        LBFGSpp::LineSearchBacktracking<Scalar>::LineSearch(f, fx, x, grad, step, drt, xp, param);
    }
};

struct LearnedIkResult {
    Pose pose;
    Eigen::VectorXd x;       // latent point (d)
    Eigen::VectorXd y;       // kept pose columns (D, degrees)
    double sigma2 = 0.0;     // σ²(x)
    double lik = 0.0;        // L_IK(x, y)
    double objective = 0.0;  // F
    std::vector<IkConstraintResult> constraints;
    bool reached = false;    // every target and pin within 0.5 cm
    bool converged = false;  // stopping rule met with every residual < 0.05 cm
    int iterations = 0;      // L-BFGS iterations completed (also when a line search failed)
    int evaluations = 0;
    LearnedIkStop stop = LearnedIkStop::kInvalidRequest;
    std::string diagnostic;  // "converged", "iteration cap", a line-search message, ...
};

class LearnedIkSolver {
public:
    explicit LearnedIkSolver(gp::ModelVersionPtr version);
    const gp::ModelVersionPtr& version() const { return version_; }

    // "" if the request can be solved, else what is wrong (expected ..., found ...).
    std::string validate(const LearnedIkRequest& request) const;
    // Never throws; fills `result` (reusing its storage).
    void solve(const LearnedIkRequest& request, LearnedIkResult& result);
    LearnedIkResult solve(const LearnedIkRequest& request);

    // F and its gradient at z = (x, y) for the current request (exposed for the gradient test).
    double objective(const Eigen::VectorXd& z, Eigen::VectorXd& grad);
    void bind(const LearnedIkRequest& request);  // sets the request objective() evaluates

private:
    void computeScaling(const Eigen::VectorXd& z0);
    gp::ModelVersionPtr version_;
    PoseLayout layout_;
    int d_ = 0, D_ = 0;
    // Workspace.
    const LearnedIkRequest* request_ = nullptr;
    Pose pose_;
    FkState fk_;
    Eigen::VectorXd full_, gradFull_, x_, y_, gx_, gy_;
    gp::PointWorkspace pointWs_;
    Eigen::Matrix<double, 3, Eigen::Dynamic> jac_;
    Eigen::VectorXd bestZ_, scale_, zScaled_, gScaled_, z_, u_, gTmp_, zProbe_;
    LBFGSpp::LBFGSParam<double> lbfgsParam_;
    std::unique_ptr<LBFGSpp::LBFGSSolver<double, CountingLineSearch>> lbfgs_;  // holds a reference to lbfgsParam_
    double bestF_ = 0.0;
    int evaluations_ = 0;
};

// The latent start for clip frame `frame` (0-based): its own x if the frame is a training row,
// else argmin_x L_IK(x, y_t) from the nearest training row's x (docs/maths.md §10.3).
Eigen::VectorXd latentStartForFrame(const gp::ModelVersion& version, int frame);

}  // namespace mgp
