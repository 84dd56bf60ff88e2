// docs/maths.md §6: IVM residual variances equal a direct solve; selection ignores Y.
#include <doctest/doctest.h>

#include <Eigen/Cholesky>

#include "gp/train/ivm.h"
#include "gp/train/pca_init.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "test_paths.h"

using namespace mgp::gp;

namespace {
TrainingData walkData(int step) {
    const mgp::Clip clip = mgp::loadClip(std::string(MOTIONGP_TEST_MOCAP) + "/asf_amc/35_01.amc");
    std::vector<int> frames;
    for (int t = 0; t < clip.frameCount(); t += step) frames.push_back(t);
    return trainingDataFromClip(clip, frames);
}

// α = 5, γ = 3, β = 50 (and η = 2 for FAS): a kernel whose selection is not trivial on the walk.
Kernel testKernel(KernelKind kind) {
    Eigen::VectorXd psi(paramCount(kind));
    psi[kAlpha] = std::log(5.0);
    psi[kGamma] = std::log(3.0);
    psi[kBeta] = std::log(50.0);
    if (kind == KernelKind::kFas) psi[kEta] = std::log(2.0);
    return Kernel(kind, psi);
}
}  // namespace

TEST_CASE("ivm: residual variances after selection equal the exact posterior variances") {
    const TrainingData d = walkData(3);
    const Eigen::MatrixXd X = whitenedPca(d.Y.rowwise() - d.mu.transpose(), 2).X;
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm}) {
        const Kernel k = testKernel(kind);
        const int m = 30;
        const IvmResult r = selectActiveSet(k, X, m);
        REQUIRE(r.active.size() == static_cast<std::size_t>(m));
        Eigen::MatrixXd XI(m, 2);
        for (int i = 0; i < m; ++i) XI.row(i) = X.row(r.active[i]);
        const Eigen::LLT<Eigen::MatrixXd> llt(k.gram(XI));
        double worst = 0.0;
        for (Eigen::Index n = 0; n < X.rows(); ++n) {
            const Eigen::VectorXd x = X.row(n).transpose();
            const Eigen::VectorXd kx = k.cross(XI, x);
            const double prior = k.diagF(x);
            const double exact = std::max(0.0, prior - kx.dot(llt.solve(kx)));
            worst = std::max(worst, std::abs(exact - r.variances[n]) / prior);
        }
        CHECK(worst < 1e-9);
        // Distinct points, each picked at the largest remaining variance.
        std::vector<int> sorted = r.active;
        std::sort(sorted.begin(), sorted.end());
        CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
    }
}

TEST_CASE("ivm: ties go to the smallest index, and M ≥ N selects every point") {
    Eigen::MatrixXd X = Eigen::MatrixXd::Zero(6, 2);  // identical prior variances everywhere
    X.row(1) << 1, 0;
    X.row(4) << 0, 1;
    const Kernel k(KernelKind::kSgplvm, Eigen::VectorXd::Zero(3));
    CHECK(selectActiveSet(k, X, 1).active == std::vector<int>{0});
    CHECK(selectActiveSet(k, X, 6).active == std::vector<int>{0, 1, 2, 3, 4, 5});
    CHECK(selectActiveSet(k, X, 10).active == std::vector<int>{0, 1, 2, 3, 4, 5});
}

TEST_CASE("ivm: the trainer's selection ignores Y (any affine change of Y gives the same set)") {
    TrainingData a = walkData(2);
    TrainingData b = a;
    b.Y = 3.0 * a.Y.array() + 7.0;  // the whitened PCA and the kernel never see the scale
    b.mu = b.Y.colwise().mean().transpose();
    TrainOptions o;
    o.activeSize = 40;
    const Trainer ta(a, o), tb(b, o);
    CHECK(ta.activeSet() == tb.activeSet());
    const IvmResult direct = selectActiveSet(Kernel(KernelKind::kFas, Eigen::VectorXd::Zero(4)), ta.latent(), 40);
    CHECK(direct.active == ta.activeSet());
}

TEST_CASE("ivm: the selection is the same bits for 1, 2 and 3 threads over several row chunks") {
    // Rows are worked on in fixed chunks of 2048 whatever the thread count (docs/maths.md §6), so
    // 5 000 rows make three chunks for the workers to share.
    const TrainingData d = walkData(1);
    const Eigen::MatrixXd base = whitenedPca(d.Y.rowwise() - d.mu.transpose(), 2).X;
    Eigen::MatrixXd X(5000, 2);
    for (Eigen::Index i = 0; i < X.rows(); ++i)
        X.row(i) = base.row(i % base.rows()) * (1.0 + 0.01 * static_cast<double>(i / base.rows()));
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm}) {
        const Kernel k = testKernel(kind);
        const IvmResult one = selectActiveSet(k, X, 60, 1);
        for (int threads : {2, 3}) {
            const IvmResult many = selectActiveSet(k, X, 60, threads);
            CHECK(many.active == one.active);
            CHECK((many.variances.array() == one.variances.array()).all());
        }
    }
}
