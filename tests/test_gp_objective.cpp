// docs/maths.md §4: L_GP gradients, the gauge and the closed-form W, on real CMU data.
#include <doctest/doctest.h>

#include <cmath>

#include "gp/gp_objective.h"
#include "gp/scg.h"
#include "gp/train/active_step.h"
#include "gp/train/pca_init.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "test_paths.h"

using namespace mgp::gp;

namespace {

struct Fixture {
    Eigen::MatrixXd XI, Yhat;
    int n = 0;
};

// 40 active rows of 35_01 (every 9th frame), D = 43, whitened-PCA latent points.
Fixture walkFixture() {
    const mgp::Clip clip = mgp::loadClip(std::string(MOTIONGP_TEST_MOCAP) + "/asf_amc/35_01.amc");
    std::vector<int> frames;
    for (int t = 0; t < clip.frameCount() && frames.size() < 40; t += 9) frames.push_back(t);
    const TrainingData data = trainingDataFromClip(clip, frames);
    Fixture f;
    f.Yhat = data.Y.rowwise() - data.mu.transpose();
    f.XI = whitenedPca(f.Yhat, 2).X;
    f.n = clip.frameCount();
    return f;
}

Eigen::VectorXd psiFor(KernelKind kind) {
    Eigen::VectorXd psi(paramCount(kind));
    psi[kAlpha] = std::log(40.0);
    psi[kGamma] = std::log(2.0);
    psi[kBeta] = std::log(0.5);
    if (kind == KernelKind::kFas) psi[kEta] = std::log(25.0);
    return psi;
}

double maxGradError(KernelKind kind, const Fixture& f) {
    const Eigen::VectorXd psi = psiFor(kind);
    const int p = paramCount(kind), m = static_cast<int>(f.XI.rows());
    auto value = [&](const Eigen::VectorXd& z) {
        Eigen::VectorXd ps;
        Eigen::MatrixXd X;
        unpackParams(z, p, m, static_cast<int>(f.XI.cols()), ps, X);
        return evaluateGp(Kernel(kind, ps), X, f.Yhat, {}, false).value;
    };
    const Eigen::VectorXd z = packParams(psi, f.XI);
    const GpEvaluation ev = evaluateGp(Kernel(kind, psi), f.XI, f.Yhat);
    REQUIRE(ev.ok);
    const Eigen::VectorXd g = packParams(ev.gradPsi, ev.gradX);
    const double h = 1e-6;
    double err = 0.0;
    for (Eigen::Index i = 0; i < z.size(); ++i) {
        Eigen::VectorXd a = z, b = z;
        a[i] += h;
        b[i] -= h;
        err = std::max(err, std::abs((value(a) - value(b)) / (2 * h) - g[i]));
    }
    return err / g.cwiseAbs().maxCoeff();
}

}  // namespace

TEST_CASE("L_GP: gradient w.r.t. log-params and X_I matches central differences (profiled gauge W)") {
    Fixture f = walkFixture();
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm}) {
        CAPTURE(kernelKindName(kind));
        CHECK(maxGradError(kind, f) < 1e-5);
    }
    // One point at ‖x‖ = 1e-4.
    f.XI.row(5) << 0.6e-4, 0.8e-4;
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm}) {
        CAPTURE(kernelKindName(kind));
        CHECK(maxGradError(kind, f) < 1e-5);
    }
    // The code is generic in d: a 3-D latent space.
    f.XI = whitenedPca(f.Yhat, 3).X;
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm}) {
        CAPTURE(kernelKindName(kind));
        CHECK(maxGradError(kind, f) < 1e-5);
    }
}

TEST_CASE("L_GP: explicit-W gradient w.r.t. ln w matches central differences") {
    const Fixture f = walkFixture();
    const Kernel k(KernelKind::kFas, psiFor(KernelKind::kFas));
    const Eigen::Index D = f.Yhat.cols();
    Eigen::VectorXd w(D);
    for (Eigen::Index i = 0; i < D; ++i) w[i] = 0.5 + 0.03 * static_cast<double>(i);
    GpObjectiveOptions o;
    o.weights = WeightMode::kFixed;
    o.fixedW = w;
    const GpEvaluation ev = evaluateGp(k, f.XI, f.Yhat, o);
    REQUIRE(ev.ok);
    const double h = 1e-6;
    double err = 0.0;
    for (Eigen::Index i = 0; i < D; ++i) {
        GpObjectiveOptions a = o, b = o;
        a.fixedW[i] *= std::exp(h);
        b.fixedW[i] *= std::exp(-h);
        const double num =
            (evaluateGp(k, f.XI, f.Yhat, a, false).value - evaluateGp(k, f.XI, f.Yhat, b, false).value) / (2 * h);
        err = std::max(err, std::abs(num - ev.gradLogW[i]));
    }
    CHECK(err < 1e-5 * ev.gradLogW.cwiseAbs().maxCoeff());
}

TEST_CASE("L_GP: the scale family (docs/maths.md §4.2) changes L by [D(M − c) + 2·[η]]·ln s") {
    const Fixture f = walkFixture();
    const double M = static_cast<double>(f.XI.rows()), D = static_cast<double>(f.Yhat.cols());
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm}) {
        for (double c : {M, static_cast<double>(f.n)}) {
            Eigen::VectorXd w(f.Yhat.cols());
            for (Eigen::Index i = 0; i < w.size(); ++i) w[i] = 0.8 + 0.01 * static_cast<double>(i);
            GpObjectiveOptions o;
            o.weights = WeightMode::kFixed;
            o.fixedW = w;
            o.jacobianCoef = c;
            const Eigen::VectorXd psi = psiFor(kind);
            const double L0 = evaluateGp(Kernel(kind, psi), f.XI, f.Yhat, o, false).value;
            for (double s : {0.1, 10.0}) {
                Eigen::VectorXd ps = psi;
                ps[kAlpha] += 2 * std::log(s);
                ps[kBeta] -= 2 * std::log(s);
                if (kind == KernelKind::kFas) ps[kEta] += 2 * std::log(s);
                GpObjectiveOptions os = o;
                os.fixedW = s * w;
                const double L1 = evaluateGp(Kernel(kind, ps), f.XI, f.Yhat, os, false).value;
                const double expected = (D * (M - c) + (kind == KernelKind::kFas ? 2.0 : 0.0)) * std::log(s);
                CAPTURE(kernelKindName(kind));
                CAPTURE(c);
                CAPTURE(s);
                CHECK(std::abs((L1 - L0) - expected) <= 1e-9 * std::abs(L0));
            }
        }
    }
}

TEST_CASE("L_GP: closed-form W is stationary (gauge and free) and the gauge holds after minimising") {
    const Fixture f = walkFixture();
    const Kernel k(KernelKind::kFas, psiFor(KernelKind::kFas));
    const double M = static_cast<double>(f.XI.rows());
    // Gauge: w_k = sqrt(g/s_k) makes the projected gradient vanish.
    const GpEvaluation g = evaluateGp(k, f.XI, f.Yhat);
    REQUIRE(g.ok);
    GpObjectiveOptions fixedAtGauge;
    fixedAtGauge.weights = WeightMode::kFixed;
    fixedAtGauge.fixedW = g.w;
    const GpEvaluation e = evaluateGp(k, f.XI, f.Yhat, fixedAtGauge);
    const Eigen::VectorXd projected = e.gradLogW.array() - e.gradLogW.mean();
    CHECK(projected.cwiseAbs().maxCoeff() < 1e-10);
    CHECK(std::abs(g.w.array().log().sum()) < 1e-10);
    // Same value whether W is profiled or passed explicitly at the profile.
    CHECK(e.value == doctest::Approx(g.value).epsilon(1e-12));
    // Without the gauge the raw gradient is 0 at w = sqrt(M/s_k).
    GpObjectiveOptions free;
    free.weights = WeightMode::kProfileFree;
    const GpEvaluation fr = evaluateGp(k, f.XI, f.Yhat, free);
    CHECK(fr.gradLogW.cwiseAbs().maxCoeff() < 1e-10 * M);
    // Minimise L_GP (profiled) a little and check the gauge and the closed form at the result.
    const int p = 4, m = static_cast<int>(f.XI.rows());
    const ValueAndGradient fg = [&](const Eigen::VectorXd& z, Eigen::VectorXd& grad) {
        Eigen::VectorXd ps;
        Eigen::MatrixXd X;
        unpackParams(z, p, m, 2, ps, X);
        const GpEvaluation ev = evaluateGp(Kernel(KernelKind::kFas, ps), X, f.Yhat);
        grad = packParams(ev.gradPsi, ev.gradX);
        return ev.value;
    };
    ScgOptions so;
    so.maxIterations = 30;
    const ScgResult r = scgMinimize(fg, packParams(psiFor(KernelKind::kFas), f.XI), so);
    Eigen::VectorXd ps;
    Eigen::MatrixXd X;
    unpackParams(r.x, p, m, 2, ps, X);
    const GpEvaluation fin = evaluateGp(Kernel(KernelKind::kFas, ps), X, f.Yhat);
    CHECK(fin.value < g.value);
    CHECK(std::abs(fin.w.array().log().sum()) < 1e-10);
    const double gm = std::exp(fin.s.array().log().mean());
    CHECK(((fin.w.array().square() * fin.s.array()) / gm - 1.0).abs().maxCoeff() < 1e-12);
}

TEST_CASE("L_GP: no NaN leaves the function") {
    Fixture f = walkFixture();
    Eigen::VectorXd psi(4);
    psi << 1000.0, 0.0, -1000.0, 50.0;
    const GpEvaluation a = evaluateGp(Kernel(KernelKind::kFas, psi), f.XI, f.Yhat);
    CHECK(!std::isnan(a.value));
    CHECK(!a.gradPsi.hasNaN());
    // A NaN parameter is refused by the kernel, and Step 6's objective calls it a failed step.
    psi[1] = std::nan("");
    CHECK_THROWS_AS(Kernel(KernelKind::kFas, psi), std::invalid_argument);
    Eigen::VectorXd g;
    const double v = activeStepObjective(KernelKind::kFas, packParams(psi, f.XI), static_cast<int>(f.XI.rows()), f.Yhat,
                                         {}, nullptr, g);
    CHECK(std::isinf(v));
    CHECK(g.size() == psi.size() + f.XI.size());
    CHECK(g.isZero());
    f.XI(0, 0) = std::nan("");
    const GpEvaluation b = evaluateGp(Kernel(KernelKind::kFas, psiFor(KernelKind::kFas)), f.XI, f.Yhat);
    CHECK(!b.ok);
    CHECK(std::isinf(b.value));
    CHECK(!b.gradX.hasNaN());
}

TEST_CASE("Step 6 objective: flat outside the log-parameter box, with a zero gradient there (central differences)") {
    const Fixture f = walkFixture();
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm}) {
        Eigen::VectorXd psi = psiFor(kind);
        psi[kAlpha] = kLogParamBound + 4.0;  // outside the box: α is clamped at e^36
        psi[kBeta] = -(kLogParamBound + 2.0);
        const int m = static_cast<int>(f.XI.rows());
        const Eigen::VectorXd z = packParams(psi, f.XI);
        Eigen::VectorXd g, gp_, gm;
        const double v = activeStepObjective(kind, z, m, f.Yhat, {}, nullptr, g);
        REQUIRE(std::isfinite(v));
        const double h = 1e-4;
        for (int i = 0; i < 8; ++i) {
            Eigen::VectorXd zp = z, zm = z;
            zp[i] += h;
            zm[i] -= h;
            const double num = (activeStepObjective(kind, zp, m, f.Yhat, {}, nullptr, gp_) -
                                activeStepObjective(kind, zm, m, f.Yhat, {}, nullptr, gm)) /
                               (2 * h);
            INFO(kernelKindName(kind) << " coordinate " << i << ": analytic " << g[i] << ", numeric " << num);
            if (i == kAlpha || i == kBeta) {
                CHECK(g[i] == 0.0);  // before: the gradient of the clamped value, not 0
                CHECK(num == 0.0);   // the value is exactly flat
            } else {
                CHECK(std::abs(num - g[i]) <= 1e-5 * std::max(1.0, std::abs(g[i])));
            }
        }
    }
}

TEST_CASE("L_GP: a reused GpWorkspace gives the same bits as a fresh one, whatever it held before") {
    const Fixture f = walkFixture();
    const Kernel k(KernelKind::kFas, psiFor(KernelKind::kFas));
    GpWorkspace fresh, reused;
    // Fill the reused workspace with another problem's sizes and values first.
    const Eigen::MatrixXd smallX = f.XI.topRows(7) * 1.3, smallY = f.Yhat.topRows(7);
    evaluateGp(Kernel(KernelKind::kSgplvm, psiFor(KernelKind::kSgplvm)), smallX, smallY, {}, true, reused);
    const GpEvaluation a = evaluateGp(k, f.XI, f.Yhat, {}, true, fresh);
    const GpEvaluation b = evaluateGp(k, f.XI, f.Yhat, {}, true, reused);
    const GpEvaluation c = evaluateGp(k, f.XI, f.Yhat);
    REQUIRE(a.ok);
    CHECK(a.value == b.value);
    CHECK(a.value == c.value);
    CHECK(a.gradPsi == b.gradPsi);
    CHECK(a.gradX == b.gradX);
    CHECK(a.gradX == c.gradX);
    CHECK(a.w == b.w);
}
