// docs/maths.md §9: L_IK gradients w.r.t. x and y, and σ² ≥ 1/β, plus Step 8's
// thread-count independence.
#include <doctest/doctest.h>

#include <cmath>

#include "gp/gp_objective.h"
#include "gp/point_objective.h"
#include "gp/train/pca_init.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "test_paths.h"

using namespace mgp::gp;

namespace {

struct Setup {
    TrainingData data;
    Eigen::MatrixXd X;
    std::vector<int> active, inactive;
};

Setup walkSetup() {
    const mgp::Clip clip = mgp::loadClip(std::string(MOTIONGP_TEST_MOCAP) + "/asf_amc/35_01.amc");
    std::vector<int> frames;
    for (int t = 0; t < clip.frameCount(); t += 4) frames.push_back(t);
    Setup s;
    s.data = trainingDataFromClip(clip, frames);
    s.X = whitenedPca(s.data.Y.rowwise() - s.data.mu.transpose(), 2).X;
    for (int i = 0; i < s.X.rows(); ++i) (i % 3 == 0 ? s.active : s.inactive).push_back(i);
    return s;
}

Eigen::VectorXd psiFor(KernelKind kind, double beta) {
    Eigen::VectorXd psi(paramCount(kind));
    psi[kAlpha] = std::log(30.0);
    psi[kGamma] = std::log(1.5);
    psi[kBeta] = std::log(beta);
    if (kind == KernelKind::kFas) psi[kEta] = std::log(20.0);
    return psi;
}

ActiveSetPosterior makeModel(const Setup& s, KernelKind kind, double beta) {
    Eigen::MatrixXd XI(s.active.size(), 2), Yhat(s.active.size(), s.data.Y.cols());
    for (std::size_t r = 0; r < s.active.size(); ++r) {
        XI.row(r) = s.X.row(s.active[r]);
        Yhat.row(r) = s.data.Y.row(s.active[r]) - s.data.mu.transpose();
    }
    const Kernel k(kind, psiFor(kind, beta));
    const GpEvaluation ev = evaluateGp(k, XI, Yhat, {}, false);
    REQUIRE(ev.ok);
    return ActiveSetPosterior(k, XI, Yhat, s.data.mu, ev.w);
}

}  // namespace

TEST_CASE("L_IK: gradients w.r.t. x and y match central differences (including near the origin)") {
    const Setup s = walkSetup();
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm}) {
        const ActiveSetPosterior pm = makeModel(s, kind, 0.2);
        const Eigen::VectorXd y = s.data.Y.row(s.inactive[7]).transpose().array() + 3.0;
        for (const Eigen::Vector2d& xv : {Eigen::Vector2d(s.X(s.inactive[7], 0), s.X(s.inactive[7], 1)),
                                          Eigen::Vector2d(2.5, -1.0), Eigen::Vector2d(0.6e-4, -0.8e-4)}) {
            const Eigen::VectorXd x = xv;
            Eigen::VectorXd gx, gy;
            pm.evaluate(x, y, &gx, &gy);
            const double hx = x.norm() < 1e-3 ? 1e-8 : 1e-6, hy = 1e-6;
            double errX = 0.0, errY = 0.0;
            for (int c = 0; c < 2; ++c) {
                Eigen::VectorXd a = x, b = x;
                a[c] += hx;
                b[c] -= hx;
                errX = std::max(
                    errX,
                    std::abs((pm.evaluate(a, y, nullptr, nullptr) - pm.evaluate(b, y, nullptr, nullptr)) / (2 * hx) -
                             gx[c]));
            }
            for (Eigen::Index k = 0; k < y.size(); ++k) {
                Eigen::VectorXd a = y, b = y;
                a[k] += hy;
                b[k] -= hy;
                errY = std::max(
                    errY,
                    std::abs((pm.evaluate(x, a, nullptr, nullptr) - pm.evaluate(x, b, nullptr, nullptr)) / (2 * hy) -
                             gy[k]));
            }
            CAPTURE(kernelKindName(kind));
            CAPTURE(xv.transpose());
            CHECK(errX < 1e-5 * std::max(1.0, gx.cwiseAbs().maxCoeff()));
            CHECK(errY < 1e-5 * std::max(1.0, gy.cwiseAbs().maxCoeff()));
        }
    }
}

TEST_CASE("L_IK: σ² ≥ 1/β holds exactly at a training active point with tiny noise") {
    const Setup s = walkSetup();
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm}) {
        const double beta = std::exp(20.0);
        const ActiveSetPosterior pm = makeModel(s, kind, beta);
        for (int i : s.active) {
            Eigen::VectorXd mean;
            double var = 0.0;
            pm.predict(s.X.row(i).transpose(), mean, var);
            CHECK(var >= 1.0 / pm.kernel().beta());
        }
    }
}

TEST_CASE("σ² over many points at once (the latent map's) is predict's σ² at each, across product blocks") {
    const Setup s = walkSetup();
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm}) {
        const ActiveSetPosterior pm = makeModel(s, kind, 0.2);
        // 1100 points: two full blocks of 512 and a partial one; training points, points far out
        // (σ² at its ceiling) and the origin's neighbourhood (the angular term's special case).
        Eigen::MatrixXd points(1100, 2);
        for (Eigen::Index i = 0; i < points.rows(); ++i) {
            const double t = double(i) / double(points.rows());
            points.row(i) = i < s.X.rows()
                                ? Eigen::RowVector2d(s.X.row(i))
                                : Eigen::RowVector2d(6.0 * std::cos(40.0 * t) * t, 6.0 * std::sin(40.0 * t) * t - 0.1);
        }
        points.row(1099) << 0.6e-4, -0.8e-4;
        const Eigen::VectorXd v = pm.variances(points);
        REQUIRE(v.size() == points.rows());
        for (Eigen::Index i = 0; i < points.rows(); ++i) {
            Eigen::VectorXd mean;
            double var = 0.0;
            pm.predict(points.row(i).transpose(), mean, var);
            CAPTURE(i);
            CHECK(v[i] == doctest::Approx(var).epsilon(1e-9));
        }
        CHECK(pm.variances(Eigen::MatrixXd(0, 2)).size() == 0);
    }
}

TEST_CASE("L_IK: Step 8 gives identical bits with 1 and 2 threads, and lowers every L_IK") {
    const Setup s = walkSetup();
    const ActiveSetPosterior pm = makeModel(s, KernelKind::kFas, 0.2);
    ScgOptions o;
    o.maxIterations = 20;
    Eigen::MatrixXd X1 = s.X, X2 = s.X;
    optimizeInactivePoints(pm, s.data.Y, s.inactive, X1, o, 1);
    optimizeInactivePoints(pm, s.data.Y, s.inactive, X2, o, 2);
    CHECK((X1.array() == X2.array()).all());
    for (int i : s.active) CHECK((X1.row(i).array() == s.X.row(i).array()).all());
    for (int i : s.inactive) {
        const Eigen::VectorXd y = s.data.Y.row(i).transpose();
        CHECK(pm.evaluate(X1.row(i).transpose(), y, nullptr, nullptr) <=
              pm.evaluate(s.X.row(i).transpose(), y, nullptr, nullptr));
    }
}
