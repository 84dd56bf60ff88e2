// Back-constraints (docs/maths.md §22): the kernel's known values, the least-squares start, the
// Step-6 gradient in (ψ, A) by central differences, and a back-constrained training whose every
// latent point stays on the mapping and whose setting survives the model file.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "central_difference.h"
#include "gp/model_file.h"
#include "gp/train/back_constraints.h"
#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "test_support.h"

using namespace mgp::gp;

namespace {

// Five 1-D "poses" 0, 1, 2, 3, 10: squared distances between distinct rows are known.
Eigen::MatrixXd lineOfPoses() {
    Eigen::MatrixXd Y(5, 1);
    Y << 0.0, 1.0, 2.0, 3.0, 10.0;
    return Y;
}

Eigen::MatrixXd wavyPoses(int n, int dims) {
    Eigen::MatrixXd Y(n, dims);
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < dims; ++k) Y(i, k) = std::sin(0.3 * i * (k + 1) + k) + 0.02 * i * k;
    Y.rowwise() -= Y.colwise().mean();
    return Y;
}

}  // namespace

TEST_CASE("back-constraints: kernel values, basis rows every ceil(N/R)-th, median length scale") {
    const BackConstraint bc(lineOfPoses(), 3);  // stride ⌈5/3⌉ = 2: rows 0, 2, 4
    REQUIRE(bc.basisRows() == std::vector<int>{0, 2, 4});
    // Squared distances row → basis over distinct pairs: to 0: 1, 4, 9, 100; to 2: 4, 1, 1, 64;
    // to 10: 100, 81, 64, 49. Sorted: 1 1 1 4 4 9 | 49 64 64 81 100 100; the upper median is 49.
    const double ell2 = kBackLengthScale2 * 49.0;
    CHECK(bc.lengthScaleSquared() == doctest::Approx(ell2));
    const Eigen::MatrixXd& K = bc.kernel();
    REQUIRE(K.rows() == 5);
    REQUIRE(K.cols() == 3);
    CHECK(K(0, 0) == doctest::Approx(1.0));
    CHECK(K(3, 1) == doctest::Approx(std::exp(-1.0 / (2 * ell2))));
    CHECK(K(1, 2) == doctest::Approx(std::exp(-81.0 / (2 * ell2))));
    Eigen::MatrixXd A(3, 2);
    A << 1.0, 0.0, 0.5, -1.0, 0.0, 2.0;
    CHECK((bc.latent(A) - K * A).norm() == doctest::Approx(0.0));
    CHECK_THROWS_AS(BackConstraint(Eigen::MatrixXd::Zero(4, 3)), std::invalid_argument);
    CHECK_THROWS_AS(BackConstraint(Eigen::MatrixXd::Zero(1, 3)), std::invalid_argument);
}

TEST_CASE("back-constraints: the start reproduces a layout the mapping can reach") {
    const BackConstraint bc(wavyPoses(40, 3));
    Eigen::MatrixXd A(bc.kernel().cols(), 2);
    for (Eigen::Index i = 0; i < A.rows(); ++i) A.row(i) << std::cos(0.4 * i), 0.1 * i - 1.0;
    const Eigen::MatrixXd X = bc.latent(A);
    CHECK((bc.latent(bc.fit(X)) - X).norm() < 1e-4 * X.norm());
}

TEST_CASE("back-constraints: Step-6 gradient in (psi, A) by central differences, with and without a prior") {
    const int n = 24;
    const Eigen::MatrixXd Y = wavyPoses(n, 4);
    const BackConstraint bc(Y, 10);  // stride 3: 8 basis rows
    const int r = static_cast<int>(bc.kernel().cols());
    const std::vector<int> active{3, 0, 17, 9, 21, 12};
    Eigen::MatrixXd Yhat(active.size(), Y.cols());
    for (std::size_t i = 0; i < active.size(); ++i) Yhat.row(static_cast<Eigen::Index>(i)) = Y.row(active[i]);
    Eigen::MatrixXd A(r, 2);
    for (int i = 0; i < r; ++i) A.row(i) << std::sin(1.7 * i), 0.3 * std::cos(0.9 * i);
    std::vector<int> frames(n);
    for (int i = 0; i < n; ++i) frames[static_cast<std::size_t>(i)] = i;
    for (KernelKind kind : {KernelKind::kFas, KernelKind::kSgplvm})
        for (double lambda : {0.0, 3.0}) {
            CAPTURE(lambda);
            const TemporalPrior prior = TemporalPrior::secondDifference(frames, lambda);
            Eigen::VectorXd psi = Eigen::VectorXd::Constant(paramCount(kind), 0.1);
            psi[0] = 0.4;
            const Eigen::VectorXd z = packParams(psi, A);
            Eigen::VectorXd g, scratch;
            const double v = backConstrainedObjective(kind, z, bc, active, Yhat, prior, {}, g);
            REQUIRE(std::isfinite(v));
            // The value is L_GP at X_I = K_I A plus the prior at X = K A.
            const Eigen::MatrixXd X = bc.latent(A);
            Eigen::MatrixXd XI(active.size(), 2);
            for (std::size_t i = 0; i < active.size(); ++i) XI.row(static_cast<Eigen::Index>(i)) = X.row(active[i]);
            const double expected = evaluateGp(Kernel(kind, psi), XI, Yhat, {}, false).value + prior.value(X);
            CHECK(v == doctest::Approx(expected).epsilon(1e-12));
            const auto f = [&](const Eigen::VectorXd& zz) {
                return backConstrainedObjective(kind, zz, bc, active, Yhat, prior, {}, scratch);
            };
            for (Eigen::Index i = 0; i < z.size(); ++i)
                CHECK(g[i] == doctest::Approx(mgp::test::centralDifference(f, z, i)).epsilon(1e-5).scale(1.0));
        }
}

TEST_CASE("back-constraints: training keeps every latent point on the mapping, and the model file keeps the setting") {
    const mgp::Clip clip = mgp::loadClip(std::string(MOTIONGP_TEST_MOCAP) + "/asf_amc/16_35.amc");
    std::vector<int> frames;
    for (int t = 0; t < clip.frameCount(); t += 3) frames.push_back(t);
    const TrainingData data = trainingDataFromClip(clip, frames);
    TrainOptions o;
    o.activeSize = 25;  // < N: without the mapping, Step 8 would move the inactive points
    o.outerIterations = 3;
    o.scgIterations = 25;
    o.backConstraints = true;
    Trainer trainer(data, o);
    REQUIRE_FALSE(trainer.backConstraint().empty());
    const Eigen::MatrixXd X0 = trainer.latent();
    for (int t = 0; t < 3; ++t) {
        trainer.step();
        const IterationLog& e = trainer.log().back();
        CHECK(e.L <= e.L_before);
        // Every point, active or not, is where the mapping puts it.
        CHECK((trainer.backConstraint().latent(trainer.backWeights()) - trainer.latent()).cwiseAbs().maxCoeff() == 0.0);
    }
    CHECK((trainer.latent() - X0).cwiseAbs().maxCoeff() > 1e-3);
    TrainResult r = train(data, o);
    CHECK(r.model.X == trainer.latent());
    CHECK(r.model.settings.backConstraints);

    r.model.clip = clip;
    r.model.sourceFile = "16_35.amc";
    const std::string dir = mgp::test::scratchDir("back_constraints");
    std::filesystem::create_directories(dir);
    saveModel(dir + "/back.json", r.model);
    CHECK(loadModel(dir + "/back.json").settings.backConstraints);
    CHECK(mgp::test::readText(dir + "/back.json").find("\"back_constraints\": true") != std::string::npos);
    r.model.settings.backConstraints = false;  // a free layout's file has no such field
    saveModel(dir + "/free.json", r.model);
    CHECK(mgp::test::readText(dir + "/free.json").find("back_constraints") == std::string::npos);
    CHECK_FALSE(loadModel(dir + "/free.json").settings.backConstraints);
}
