// The allocation-free fused L_IK evaluation equals the reference one (value and gradients).
#include <random>

#include "gp/point_objective.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("ActiveSetPosterior::evaluate with a workspace equals the reference evaluation") {
    const auto version = test::walkModel35();
    const gp::ActiveSetPosterior& point = *version->posterior;
    const gp::GpModel& m = *version->model;
    std::mt19937 rng(3);
    std::normal_distribution<double> n01;
    gp::PointWorkspace ws;
    for (int trial = 0; trial < 20; ++trial) {
        Eigen::VectorXd x = m.X.row(trial * 17).transpose();
        for (int i = 0; i < x.size(); ++i) x[i] += 0.3 * n01(rng);
        if (trial == 0) x.setConstant(2e-4);  // near the origin, where the angular term is steep
        Eigen::VectorXd y = m.Y.row(trial * 11).transpose();
        for (int i = 0; i < y.size(); ++i) y[i] += 3.0 * n01(rng);
        Eigen::VectorXd gx, gy, gx2(x.size()), gy2(y.size());
        const double v = point.evaluate(x, y, &gx, &gy);
        const double v2 = point.evaluate(x, y, ws, &gx2, &gy2);
        // The fused kernel vector itself agrees to rounding (no cancellation happens there).
        const Eigen::VectorXd kRef = m.kernel().cross(m.activeX(), x);
        CHECK((ws.k - kRef).cwiseAbs().maxCoeff() <= 1e-14 * kRef.cwiseAbs().maxCoeff());
        // Value and gradients go through σ² = k(x,x) − kᵀK⁻¹k, which cancels: here ≈ 12 − 12 → ~1e-2,
        // so the last-bit differences of kᵀK⁻¹k (κ(K)·ε ≈ 1e-12 relative) grow by ~1e3 in σ² and
        // hence in L_IK and its gradients. 1e-7 relative is that bound with a margin of ~10.
        CHECK(v2 == doctest::Approx(v).epsilon(1e-7));
        CHECK((gx2 - gx).cwiseAbs().maxCoeff() <= 1e-7 * std::max(1.0, gx.cwiseAbs().maxCoeff()));
        CHECK((gy2 - gy).cwiseAbs().maxCoeff() <= 1e-7 * std::max(1.0, gy.cwiseAbs().maxCoeff()));
        CHECK(point.evaluate(x, y, ws, nullptr, nullptr) == v2);
    }
}
