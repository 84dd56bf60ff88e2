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

TEST_CASE(
    "ActiveSetPosterior::evaluate with a workspace: σ² from the Cholesky factor is smooth where the inverse's "
    "cancels") {
    // σ² = k(x,x) − kᵀK⁻¹k next to a training point is 12 − 12 → ~1e-2. With the explicit K⁻¹ the
    // cancellation leaves noise of κ(K)·ε·k(x,x) in σ²: on weakly trained models L_IK jittered by up
    // to 1e-8 relative from one x to the next, more than the IK's stationarity test allows, and
    // solves stalled (docs/maths.md §9.1).
    // k(x,x) − ‖L⁻¹k‖² is a sum of squares: its rounding is O(M·ε·k(x,x)).
    const auto version = test::walkModel35();
    const gp::ActiveSetPosterior& point = *version->posterior;
    const gp::GpModel& m = *version->model;
    gp::PointWorkspace ws;
    const Eigen::VectorXd y = m.Y.row(40).transpose();
    const Eigen::VectorXd x0 = m.X.row(40).transpose() + Eigen::VectorXd::Constant(m.latentDim(), 0.05);
    const Eigen::VectorXd dir = Eigen::VectorXd::Ones(m.latentDim()).normalized();
    const double h = 1e-9;  // σ² is smooth in x: over this step its own second difference is ~1e-18
    std::vector<double> fused, inverse;
    for (int i = 0; i < 9; ++i) {
        const Eigen::VectorXd x = x0 + (i * h) * dir;
        point.evaluate(x, y, ws, nullptr, nullptr);
        fused.push_back(ws.variance);
        Eigen::VectorXd mean;
        double s2 = 0.0;
        point.predict(x, mean, s2);
        inverse.push_back(s2);
    }
    auto worstSecondDifference = [](const std::vector<double>& s) {
        double worst = 0.0;
        for (std::size_t i = 1; i + 1 < s.size(); ++i)
            worst = std::max(worst, std::abs(s[i - 1] - 2.0 * s[i] + s[i + 1]));
        return worst;
    };
    const double kxx = m.kernel().diagF(x0);
    MESSAGE("σ² " << fused[0] << ", k(x,x) " << kxx << "; second differences: Cholesky " << worstSecondDifference(fused)
                  << ", explicit inverse " << worstSecondDifference(inverse));
    CHECK(fused[0] < 0.1 * kxx);  // the cancelling regime
    CHECK(worstSecondDifference(fused) <= 4.0 * m.activeX().rows() * 2.3e-16 * kxx);
}
