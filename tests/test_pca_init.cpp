// docs/maths.md §5: constant columns (via the training preprocessing) and whitened PCA.
#include <doctest/doctest.h>

#include "gp/train/pca_init.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "test_paths.h"

using namespace mgp::gp;

namespace {
TrainingData walkData() {
    const mgp::Clip clip = mgp::loadClip(std::string(MOTIONGP_TEST_MOCAP) + "/asf_amc/35_01.amc");
    std::vector<int> frames(clip.frameCount());
    for (int i = 0; i < clip.frameCount(); ++i) frames[i] = i;
    return prepareTrainingData(mgp::poseMatrix(clip), frames);
}
}  // namespace

TEST_CASE("pca_init: subject 35 drops the clavicle columns {33, 34, 40, 41}, D = 43") {
    const TrainingData d = walkData();
    CHECK(d.constantColumns == std::vector<int>{33, 34, 40, 41});
    CHECK(d.Y.cols() == 43);
    CHECK(d.keptColumns.size() == 43);
    CHECK(latentDimensionFor(47) == 2);
    CHECK(latentDimensionFor(43) == 2);
    CHECK(latentDimensionFor(62) == 3);
}

TEST_CASE("pca_init: whitened latent columns have mean 0 and population variance 1") {
    const TrainingData d = walkData();
    const Eigen::MatrixXd Ybar = d.Y.rowwise() - d.mu.transpose();
    for (int dim : {2, 3}) {
        const PcaInit p = whitenedPca(Ybar, dim);
        REQUIRE(p.X.cols() == dim);
        const double n = static_cast<double>(p.X.rows());
        for (int c = 0; c < dim; ++c) {
            CHECK(std::abs(p.X.col(c).mean()) < 1e-12);
            CHECK(std::abs(p.X.col(c).squaredNorm() / n - 1.0) < 1e-12);
        }
        // Components are orthonormal, eigenvalues descend, signs follow the rule.
        CHECK((p.components.transpose() * p.components - Eigen::MatrixXd::Identity(dim, dim)).cwiseAbs().maxCoeff() <
              1e-12);
        for (int c = 0; c + 1 < dim; ++c) CHECK(p.eigenvalues[c] >= p.eigenvalues[c + 1]);
        for (int c = 0; c < dim; ++c) {
            Eigen::Index big;
            p.components.col(c).cwiseAbs().maxCoeff(&big);
            CHECK(p.components(big, c) > 0.0);
        }
        // Deterministic signs: negating the data negates the latent points, nothing else.
        const PcaInit q = whitenedPca(-Ybar, dim);
        CHECK((q.components - p.components).cwiseAbs().maxCoeff() < 1e-9);
        CHECK((q.X + p.X).cwiseAbs().maxCoeff() < 1e-8);
    }
}
