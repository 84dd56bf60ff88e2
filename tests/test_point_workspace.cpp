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

TEST_CASE("ActiveSetPosterior::evaluateBatch gives each column what evaluate gives it, for both kernels") {
    // Step 8 evaluates its points in batches (docs/maths.md §7): the same formulas, the matrix-vector
    // products done as matrix products, so only the summation order differs. Both kernels: the
    // committed walk model is FAS; the SGPLVM posterior is the same active set under the RBF kernel.
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    std::mt19937 rng(5);
    std::normal_distribution<double> n01;
    const int b = 13, d = m.latentDim(), D = static_cast<int>(m.Y.cols());
    Eigen::MatrixXd X(d, b), Y(D, b);
    for (int j = 0; j < b; ++j) {
        X.col(j) = m.X.row(j * 23).transpose();
        for (int i = 0; i < d; ++i) X(i, j) += 0.3 * n01(rng);
        Y.col(j) = m.Y.row(j * 19).transpose();
        for (int i = 0; i < D; ++i) Y(i, j) += 3.0 * n01(rng);
    }
    X.col(0).setConstant(2e-4);                 // near the origin, where the angular term is steep
    X.col(1) = m.activeX().row(3).transpose();  // on an active point, where σ² cancels most
    X.col(2) = 40.0 * X.col(5);                 // far from the data, where k ≈ 0
    Eigen::VectorXd psi(gp::paramCount(gp::KernelKind::kSgplvm));
    psi[gp::kAlpha] = std::log(30.0);
    psi[gp::kGamma] = std::log(1.5);
    psi[gp::kBeta] = std::log(0.2);
    const gp::ActiveSetPosterior rbf(gp::Kernel(gp::KernelKind::kSgplvm, psi), m.activeX(), m.activeYhat(), m.mu, m.w);
    for (const gp::ActiveSetPosterior* point : {version->posterior.get(), &rbf}) {
        CAPTURE(point->kernel().hasEta());
        gp::PointWorkspace ws;
        gp::PointBatchWorkspace bws;
        Eigen::VectorXd values;
        Eigen::MatrixXd G;
        point->evaluateBatch(X, Y, bws, values, G);
        REQUIRE(values.size() == b);
        REQUIRE(G.rows() == d);
        REQUIRE(G.cols() == b);
        for (int j = 0; j < b; ++j) {
            CAPTURE(j);
            Eigen::VectorXd gx(d);
            const double v = point->evaluate(X.col(j), Y.col(j), ws, &gx, nullptr);
            // The bound of the test above: σ²'s cancellation turns last-bit differences of kᵀK⁻¹k
            // into ~1e-9 relative in L_IK and its gradient.
            CHECK(values[j] == doctest::Approx(v).epsilon(1e-7));
            CHECK((G.col(j) - gx).cwiseAbs().maxCoeff() <= 1e-7 * std::max(1.0, gx.cwiseAbs().maxCoeff()));
        }
        // A batch of one column is the same evaluation.
        Eigen::VectorXd one;
        Eigen::MatrixXd G1;
        point->evaluateBatch(X.rightCols(1), Y.rightCols(1), bws, one, G1);
        CHECK(one[0] == doctest::Approx(values[b - 1]).epsilon(1e-12));
        CHECK_THROWS_AS(point->evaluateBatch(X, Y.leftCols(b - 1), bws, values, G), std::invalid_argument);
        CHECK_THROWS_AS(point->evaluateBatch(X.topRows(d - 1), Y, bws, values, G), std::invalid_argument);
    }
}
