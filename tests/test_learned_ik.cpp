// Learned IK (docs/maths.md §10): gradient through FK, reachable targets, pins, unreachable targets.
#include <chrono>
#include <cmath>
#include <random>

#include "ik/learned_ik.h"
#include "ik/plain_ik.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("learned IK objective gradient (L_IK + FK) matches central differences") {
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    LearnedIkSolver solver(version);
    LearnedIkRequest req = test::requestAtFrame(*version, 100, 50);
    const Eigen::Vector3d foot = effectorCm(m.clip.skeleton, req.start, Effector::kRFoot);
    req.constraints = {{Effector::kRFoot, foot + Eigen::Vector3d(3, 12, -4), false},
                       {Effector::kLHand, effectorCm(m.clip.skeleton, req.start, Effector::kLHand), true}};
    solver.bind(req);
    const PoseLayout layout(m.clip.skeleton);
    const Eigen::VectorXd full = layout.extract(req.start);
    Eigen::VectorXd z(m.latentDim() + m.D());
    z.head(m.latentDim()) = req.startX + Eigen::VectorXd::Constant(m.latentDim(), 0.05);
    for (int k = 0; k < m.D(); ++k) z[m.latentDim() + k] = full[m.keptColumns[k]] + 0.3 * std::sin(k);
    Eigen::VectorXd g, gp_, gm;
    solver.objective(z, g);
    double worst = 0.0, scale = g.cwiseAbs().maxCoeff();
    for (int i = 0; i < z.size(); ++i) {
        const double h = 1e-6;
        Eigen::VectorXd zp = z, zm = z;
        zp[i] += h;
        zm[i] -= h;
        const double numeric = (solver.objective(zp, gp_) - solver.objective(zm, gm)) / (2 * h);
        worst = std::max(worst, std::abs(numeric - g[i]));
    }
    MESSAGE("IK objective gradient: max abs error " << worst << " against max |g| " << scale);
    CHECK(worst < 1e-5 * scale);
}

TEST_CASE("learned IK: δ = 0 is met to 0.05 cm and an rfoot raise up to 40 cm to 0.5 cm on frame 101") {
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    LearnedIkSolver solver(version);
    LearnedIkRequest req = test::requestAtFrame(*version, 100);
    const Eigen::Vector3d foot = effectorCm(m.clip.skeleton, req.start, Effector::kRFoot);
    LearnedIkResult res;
    for (int delta = 0; delta <= 40; delta += 2) {
        CAPTURE(delta);
        req.constraints = {{Effector::kRFoot, foot + Eigen::Vector3d(0, delta, 0), false}};
        solver.solve(req, res);
        REQUIRE(res.constraints.size() == 1);
        if (delta == 0) CHECK(res.constraints[0].residualCm < 0.05);
        CHECK(res.constraints[0].residualCm < 0.5);
        CHECK(res.reached);
        CHECK(std::isfinite(res.lik));
        CHECK(res.sigma2 >= 1.0 / std::exp(m.logParams[gp::kBeta]));
        CHECK((effectorCm(m.clip.skeleton, res.pose, Effector::kRFoot) - req.constraints[0].targetCm).norm() ==
              doctest::Approx(res.constraints[0].residualCm).epsilon(1e-9));
        CHECK(res.pose.rootCm == m.clip.frames[100].rootCm);
        if (delta % 10 == 0)
            MESSAGE("δ = " << delta << " cm: residual " << res.constraints[0].residualCm << " cm, L_IK " << res.lik
                           << ", " << res.iterations << " iterations, " << res.diagnostic);
        req.start = res.pose;  // warm start from δ − 2, as in the editing-range protocol
        req.startX = res.x;
    }
}

TEST_CASE("learned IK holds pins within 0.5 cm while a hand is dragged") {
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    LearnedIkSolver solver(version);
    LearnedIkRequest req = test::requestAtFrame(*version, 50);
    const Skeleton& sk = m.clip.skeleton;
    const Eigen::Vector3d lf = effectorCm(sk, req.start, Effector::kLFoot),
                          rf = effectorCm(sk, req.start, Effector::kRFoot);
    req.constraints = {
        {Effector::kRHand, effectorCm(sk, req.start, Effector::kRHand) + Eigen::Vector3d(0, 15, 10), false},
        {Effector::kLFoot, lf, true},
        {Effector::kRFoot, rf, true}};
    const LearnedIkResult res = solver.solve(req);
    for (const auto& c : res.constraints) {
        CAPTURE(effectorName(c.effector));
        CHECK(c.residualCm < 0.5);
    }
    CHECK(res.reached);
}

TEST_CASE("learned IK: unreachable and NaN targets give finite results, reached = false") {
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    LearnedIkSolver solver(version);
    LearnedIkRequest req = test::requestAtFrame(*version, 10, 50);
    req.constraints = {
        {Effector::kHead, effectorCm(m.clip.skeleton, req.start, Effector::kHead) + Eigen::Vector3d(0, 300, 0), false}};
    LearnedIkResult res = solver.solve(req);
    CHECK_FALSE(res.reached);
    CHECK(std::isfinite(res.constraints[0].residualCm));
    CHECK(res.x.allFinite());
    for (const auto& a : res.pose.anglesDeg) CHECK(a.allFinite());
    req.constraints[0].targetCm.y() = NAN;
    res = solver.solve(req);
    CHECK(res.diagnostic == "expected a finite target for head, found NaN or Inf");
    CHECK_FALSE(res.reached);
    for (const auto& a : res.pose.anglesDeg) CHECK(a.allFinite());
}

namespace {
// ‖x − a‖² whose gradient turns to the wrong sign after `goodEvaluations` calls: the line
// search of the next iteration then fails. Carries the counter CountingLineSearch increments.
struct TurningBad {
    int* lineSearches;
    int goodEvaluations;
    int evaluations = 0;
    double operator()(const Eigen::VectorXd& x, Eigen::VectorXd& g) {
        const Eigen::VectorXd a = Eigen::VectorXd::LinSpaced(x.size(), 1.0, 3.0);
        g = 2.0 * (x - a).cwiseProduct(Eigen::VectorXd::LinSpaced(x.size(), 1.0, 9.0));
        const double f = (x - a).cwiseAbs2().dot(Eigen::VectorXd::LinSpaced(x.size(), 1.0, 9.0));
        if (++evaluations > goodEvaluations) g = -g;
        return f;
    }
};
}  // namespace

TEST_CASE("learned IK: the line-search counter gives the true iteration count, also when a line search throws") {
    LBFGSpp::LBFGSParam<double> param;
    param.epsilon = 1e-30;
    param.epsilon_rel = 1e-30;
    param.past = 0;
    param.max_iterations = 6;
    LBFGSpp::LBFGSSolver<double, CountingLineSearch> solver(param);
    int lineSearches = 0;
    TurningBad good{&lineSearches, 1000000};
    Eigen::VectorXd x = Eigen::VectorXd::Zero(5);
    double fx = 0.0;
    const int k = solver.minimize(good, x, fx);
    CHECK(k == 6);
    CHECK(lineSearches == k);  // one line search per iteration
    // A wrong-signed gradient from the start: the first line search never finds a decrease and
    // throws, so no iteration completed (the cap, 100, was reported before).
    lineSearches = 0;
    param.max_iterations = 100;
    TurningBad bad{&lineSearches, 0};
    x.setZero();
    CHECK_THROWS_AS(solver.minimize(bad, x, fx), std::runtime_error);
    CHECK(lineSearches == 1);
    // Going wrong part-way: some iterations complete, then one throws, well before the cap.
    lineSearches = 0;
    TurningBad later{&lineSearches, 4};
    x.setZero();
    CHECK_THROWS(solver.minimize(later, x, fx));
    CHECK(lineSearches >= 1);
    CHECK(lineSearches < 100);
}

TEST_CASE("learned IK: the stop reason is an enum that agrees with converged and the diagnostic") {
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    LearnedIkSolver solver(version);
    LearnedIkRequest req = test::requestAtFrame(*version, 100, 200);
    req.constraints = {
        {Effector::kRFoot, effectorCm(m.clip.skeleton, req.start, Effector::kRFoot) + Eigen::Vector3d(0, 5, 0), false}};
    const LearnedIkResult r = solver.solve(req);
    CHECK(r.converged == (r.stop == LearnedIkStop::kConverged));
    if (r.stop == LearnedIkStop::kLineSearchFailed)
        CHECK(r.diagnostic.rfind("line search: ", 0) == 0);
    else
        CHECK(r.diagnostic == learnedIkStopName(r.stop));
    CHECK(r.iterations >= 0);
    CHECK(r.iterations <= req.maxIterations);
    req.maxIterations = 2;
    const LearnedIkResult capped = solver.solve(req);
    CHECK(capped.stop == LearnedIkStop::kIterationCap);
    CHECK(capped.iterations == 2);
    CHECK(capped.diagnostic == "iteration cap");
    CHECK(std::string(learnedIkStopKey(capped.stop)) == "iteration_cap");  // the JSON spelling (pose --json)
    CHECK(std::string(learnedIkStopKey(LearnedIkStop::kLineSearchFailed)) == "line_search_failed");
    req.maxIterations = 0;
    const LearnedIkResult refused = solver.solve(req);
    CHECK(refused.stop == LearnedIkStop::kInvalidRequest);
    CHECK(refused.iterations == 0);
}
