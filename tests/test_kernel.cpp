// The kernel is PSD, and its own derivative contractions are right (docs/maths.md §3).
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "gp/kernel.h"

using namespace mgp::gp;

namespace {

Eigen::MatrixXd randomPoints(int n, int d, unsigned seed, double scale = 1.0) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    Eigen::MatrixXd X(n, d);
    for (int i = 0; i < n; ++i)
        for (int c = 0; c < d; ++c) X(i, c) = scale * u(rng);
    return X;
}

Eigen::VectorXd fasParams() {
    return (Eigen::VectorXd(4) << std::log(3.0), std::log(1.7), std::log(20.0), std::log(2.5)).finished();
}

}  // namespace

TEST_CASE("kernel: exp(cos) Gram of 60 random points is PSD and K ⪰ (1/β) I") {
    const Eigen::MatrixXd X = randomPoints(60, 2, 7);
    const Kernel k(KernelKind::kFas, fasParams());
    const GramParts p = k.parts(X);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> esE(p.E);
    CHECK(esE.eigenvalues().minCoeff() > -1e-12);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> esK(k.gram(X));
    CHECK(esK.eigenvalues().minCoeff() >= 1.0 / k.beta() - 1e-9);
    // SGPLVM too.
    const Kernel ks(KernelKind::kSgplvm, fasParams().head(3));
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> esS(ks.gram(X));
    CHECK(esS.eigenvalues().minCoeff() >= 1.0 / ks.beta() - 1e-9);
}

TEST_CASE("kernel: gram, cross and diag agree, angular term is η at the origin") {
    const Eigen::MatrixXd X = randomPoints(8, 3, 3);
    const Kernel k(KernelKind::kFas, fasParams());
    const Eigen::MatrixXd K = k.gram(X);
    for (int i = 0; i < 8; ++i) {
        const Eigen::VectorXd xi = X.row(i).transpose();
        const Eigen::VectorXd c = k.cross(X, xi);
        for (int j = 0; j < 8; ++j) {
            if (i == j)
                CHECK(K(i, i) == doctest::Approx(k.diagF(xi) + 1.0 / k.beta()).epsilon(1e-13));
            else
                CHECK(K(i, j) == doctest::Approx(c[j]).epsilon(1e-13));
        }
    }
    CHECK(k.diagF(Eigen::VectorXd::Zero(3)) == doctest::Approx(k.alpha() + k.eta()).epsilon(1e-15));
}

TEST_CASE("kernel: contractions against central differences (log-params and latent points)") {
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm}) {
        Eigen::MatrixXd X = randomPoints(12, 2, 11);
        X.row(3) << 1e-4, -0.5e-4;  // near the origin
        const Eigen::VectorXd psi = kind == KernelKind::kFas ? fasParams() : Eigen::VectorXd(fasParams().head(3));
        Eigen::MatrixXd G = randomPoints(12, 12, 5);
        G = 0.5 * (G + G.transpose()).eval();
        auto f = [&](const Eigen::VectorXd& ps, const Eigen::MatrixXd& Xs) {
            return (G.array() * Kernel(kind, ps).gram(Xs).array()).sum();
        };
        const Kernel k(kind, psi);
        const Eigen::VectorXd gp = k.gradLogParams(X, G);
        const Eigen::MatrixXd gx = k.gradX(X, G);
        const double h = 1e-6;
        double maxErr = 0.0, maxG = std::max(gp.cwiseAbs().maxCoeff(), gx.cwiseAbs().maxCoeff());
        for (int p = 0; p < psi.size(); ++p) {
            Eigen::VectorXd a = psi, b = psi;
            a[p] += h;
            b[p] -= h;
            maxErr = std::max(maxErr, std::abs((f(a, X) - f(b, X)) / (2 * h) - gp[p]));
        }
        for (int i = 0; i < X.rows(); ++i)
            for (int c = 0; c < X.cols(); ++c) {
                Eigen::MatrixXd A = X, B = X;
                A(i, c) += h * 1e-2;  // the point near the origin needs a step below ε
                B(i, c) -= h * 1e-2;
                maxErr = std::max(maxErr, std::abs((f(psi, A) - f(psi, B)) / (2 * h * 1e-2) - gx(i, c)));
            }
        CHECK(maxErr < 1e-5 * maxG);
    }
}

TEST_CASE("kernel: cross and diagonal latent gradients against central differences") {
    const Eigen::MatrixXd X = randomPoints(10, 2, 13);
    const Kernel k(KernelKind::kFas, fasParams());
    for (const Eigen::Vector2d& xv : {Eigen::Vector2d(0.7, -1.1), Eigen::Vector2d(2e-4, 1e-4)}) {
        const Eigen::VectorXd x = xv;
        const Eigen::MatrixXd J = k.crossGradX(X, x);
        const Eigen::VectorXd gd = k.diagGradX(x);
        const double h = 1e-8;
        for (int c = 0; c < 2; ++c) {
            Eigen::VectorXd a = x, b = x;
            a[c] += h;
            b[c] -= h;
            const Eigen::VectorXd num = (k.cross(X, a) - k.cross(X, b)) / (2 * h);
            CHECK((num - J.col(c)).cwiseAbs().maxCoeff() < 1e-6 * std::max(1.0, J.cwiseAbs().maxCoeff()));
            CHECK(std::abs((k.diagF(a) - k.diagF(b)) / (2 * h) - gd[c]) <
                  1e-6 * std::max(1.0, gd.cwiseAbs().maxCoeff()));
        }
    }
}

TEST_CASE("kernel: log-parameters are clamped and a NaN parameter is rejected with a clear error") {
    Eigen::VectorXd psi(4);
    psi << 100.0, -100.0, 0.0, 0.0;
    const Kernel k(KernelKind::kFas, psi);
    CHECK(k.logParams()[kAlpha] == kLogParamBound);
    CHECK(k.logParams()[kGamma] == -kLogParamBound);
    CHECK(std::isfinite(k.beta()));
    // A NaN used to become θ = 1 silently; it never reaches exp() and is now named.
    psi[2] = std::nan("");
    CHECK_THROWS_WITH_AS(Kernel(KernelKind::kFas, psi), "expected finite kernel log-parameters, found NaN at index 2",
                         std::invalid_argument);
}
