// docs/maths.md §7: SCG on Rosenbrock and on a function that returns NaN off its domain.
#include <doctest/doctest.h>

#include <cmath>

#include "gp/scg.h"

using namespace mgp::gp;

namespace {
// Rosenbrock's valley, minimum 0 at (1, 1).
const ValueAndGradient rosen = [](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
    const double a = 1.0 - x[0], b = x[1] - x[0] * x[0];
    g[0] = -2.0 * a - 400.0 * x[0] * b;
    g[1] = 200.0 * b;
    return a * a + 100.0 * b * b;
};
}  // namespace

TEST_CASE("scg: Rosenbrock from (−1.2, 1) reaches (1, 1) within 1e-6 in < 100 iterations") {
    ScgOptions o;
    o.maxIterations = 100;
    o.tolX = 1e-8;
    o.tolF = 1e-12;
    const ScgResult r = scgMinimize(rosen, Eigen::Vector2d(-1.2, 1.0), o);
    CHECK(r.stop == ScgStop::kConverged);
    CHECK(r.iterations < 100);
    CHECK((r.x - Eigen::Vector2d(1.0, 1.0)).cwiseAbs().maxCoeff() < 1e-6);
}

TEST_CASE("scg: a NaN-returning trial does not stall the optimiser") {
    // f(x) = 100 Σ (x_i⁴/4 − x_i), minimum at (1, 1), NaN wherever |x_i| > 10. From (0.01, 0.02)
    // the curvature is tiny and the gradient large, so the first trial steps land far outside
    // (x ≈ 97): plain Netlab would repeat that failing step until the iteration limit (docs/maths.md §7).
    int nanCalls = 0;
    const ValueAndGradient f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
        if (x.cwiseAbs().maxCoeff() > 10.0) {
            ++nanCalls;
            g.setConstant(std::nan(""));
            return std::nan("");
        }
        double v = 0.0;
        for (int i = 0; i < 2; ++i) {
            v += 100.0 * (std::pow(x[i], 4) / 4.0 - x[i]);
            g[i] = 100.0 * (std::pow(x[i], 3) - 1.0);
        }
        return v;
    };
    ScgOptions o;
    o.maxIterations = 200;
    o.tolX = 1e-10;
    o.tolF = 1e-12;
    const ScgResult r = scgMinimize(f, Eigen::Vector2d(0.01, 0.02), o);
    CHECK(nanCalls > 0);  // the NaN region was actually hit
    CHECK(r.stop != ScgStop::kMaxIterations);
    CHECK(r.iterations < 200);
    CHECK(std::isfinite(r.value));
    CHECK((r.x - Eigen::Vector2d(1.0, 1.0)).cwiseAbs().maxCoeff() < 1e-6);
}

TEST_CASE("scg: a non-finite start is reported, not iterated") {
    const ValueAndGradient f = [](const Eigen::VectorXd&, Eigen::VectorXd& g) {
        g.setZero();
        return std::nan("");
    };
    const ScgResult r = scgMinimize(f, Eigen::Vector2d(0, 0));
    CHECK(r.stop == ScgStop::kBadStart);
    CHECK(r.evaluations == 1);
}

TEST_CASE("scg: machines run side by side take the steps scgMinimize takes, and end for good") {
    // Step 8 drives many ScgMachines in lock step with batched evaluations; each must take exactly
    // the steps it takes alone.
    const ValueAndGradient bowl = [](const Eigen::VectorXd& x, Eigen::VectorXd& g) {
        g = Eigen::Vector3d(2.0, 8.0, 18.0).cwiseProduct(x - Eigen::Vector3d(1.0, -2.0, 0.5));
        return 0.5 * g.dot(x - Eigen::Vector3d(1.0, -2.0, 0.5));
    };
    ScgOptions o;
    o.tolX = 1e-8;
    o.tolF = 1e-12;
    const Eigen::VectorXd r0 = Eigen::Vector2d(-1.2, 1.0), b0 = Eigen::Vector3d(4.0, 4.0, 4.0);
    const ScgResult rAlone = scgMinimize(rosen, r0, o), bAlone = scgMinimize(bowl, b0, o);
    ScgMachine r(r0, o), b(b0, o);
    while (!r.done() || !b.done()) {
        if (!r.done()) r.supply(rosen(r.request(), r.gradientSlot()));
        if (!b.done()) b.supply(bowl(b.request(), b.gradientSlot()));
    }
    for (const auto& [alone, machine] : {std::pair{&rAlone, &r.result()}, std::pair{&bAlone, &b.result()}}) {
        CHECK(machine->stop == alone->stop);
        CHECK(machine->iterations == alone->iterations);
        CHECK(machine->evaluations == alone->evaluations);
        CHECK((machine->x.array() == alone->x.array()).all());
        CHECK(machine->value == alone->value);
    }
    CHECK(bAlone.stop == ScgStop::kConverged);
    CHECK_THROWS_AS(r.supply(0.0), std::logic_error);
}
