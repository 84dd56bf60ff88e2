// docs/maths.md §4.4 step 4: K⁻¹ from the Cholesky factor by a recursive triangular inverse and
// L⁻ᵀL⁻¹ product (util/cholesky_inverse.h), against Eigen's dense inverse and products.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <limits>
#include <random>

#include "util/cholesky_inverse.h"

namespace {

// A well-conditioned SPD matrix of size n (a Gram matrix plus a diagonal shift), seeded.
Eigen::MatrixXd spdMatrix(Eigen::Index n, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> normal;
    Eigen::MatrixXd B(n, n + 3);
    for (Eigen::Index i = 0; i < B.size(); ++i) B.data()[i] = normal(rng);
    Eigen::MatrixXd K = B * B.transpose() / double(n);
    K.diagonal().array() += 0.5;
    return K;
}

// Largest entry of the lower triangles' difference, over the largest entry of the reference's.
double lowerRelativeError(const Eigen::MatrixXd& got, const Eigen::MatrixXd& want) {
    const Eigen::MatrixXd diff =
        Eigen::MatrixXd(got.triangularView<Eigen::Lower>()) - Eigen::MatrixXd(want.triangularView<Eigen::Lower>());
    return diff.cwiseAbs().maxCoeff() / want.cwiseAbs().maxCoeff();
}

// The strict upper triangle is never touched: fill it with a marker and check it afterwards.
constexpr double kMarker = 12345.0;
void markUpper(Eigen::MatrixXd& M) { M.triangularView<Eigen::StrictlyUpper>().setConstant(kMarker); }
bool upperStillMarked(const Eigen::MatrixXd& M) {
    for (Eigen::Index j = 1; j < M.cols(); ++j)
        for (Eigen::Index i = 0; i < j; ++i)
            if (M(i, j) != kMarker) return false;
    return true;
}

const Eigen::Index kSizes[] = {1, 2, 7, 32, 33, 64, 65, 100, 257};

}  // namespace

TEST_CASE("cholesky inverse: L⁻¹, VᵀV and K⁻¹ match dense Eigen at sizes across the block boundary") {
    for (Eigen::Index n : kSizes) {
        INFO("n = " << n);
        const Eigen::MatrixXd K = spdMatrix(n, 7u + unsigned(n));
        const Eigen::LLT<Eigen::MatrixXd> llt(K);
        REQUIRE(llt.info() == Eigen::Success);
        const Eigen::MatrixXd L = llt.matrixL();
        // Scratch as large as any call needs, full of NaN: storage only, never read before written.
        Eigen::MatrixXd scratch = Eigen::MatrixXd::Constant(n * n, 1, std::numeric_limits<double>::quiet_NaN());

        Eigen::MatrixXd Linv = L;
        markUpper(Linv);
        mgp::invertLowerTriangularInPlace(Linv, scratch);
        const Eigen::MatrixXd LinvWant = L.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(n, n));
        CHECK(lowerRelativeError(Linv, LinvWant) < 1e-13);
        CHECK(upperStillMarked(Linv));

        Eigen::MatrixXd V = LinvWant;
        markUpper(V);
        mgp::lowerTransposeTimesSelfInPlace(V, scratch);
        const Eigen::MatrixXd VtVWant = LinvWant.transpose() * LinvWant;
        CHECK(lowerRelativeError(V, VtVWant) < 1e-13);
        CHECK(upperStillMarked(V));

        Eigen::MatrixXd Kinv = llt.matrixLLT();
        markUpper(Kinv);
        mgp::choleskyInverseInPlace(Kinv, scratch);
        CHECK(lowerRelativeError(Kinv, K.inverse()) < 1e-11);
        CHECK(upperStillMarked(Kinv));
        const Eigen::MatrixXd KinvFull = Kinv.selfadjointView<Eigen::Lower>();
        CHECK((KinvFull * K - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff() < 1e-11);
    }
}

TEST_CASE("cholesky inverse: the same bits whatever the scratch held, and on a block of a larger matrix") {
    const Eigen::Index n = 150;
    const Eigen::LLT<Eigen::MatrixXd> llt(spdMatrix(n, 3u));
    Eigen::MatrixXd a = llt.matrixLLT(), b = a;
    Eigen::MatrixXd fresh, used = Eigen::MatrixXd::Constant(400, 400, -7.0);
    mgp::choleskyInverseInPlace(a, fresh);
    mgp::choleskyInverseInPlace(b, used);
    CHECK(a == b);

    // A Ref to a block (outer stride larger than its rows) gives what the matrix on its own does,
    // and nothing outside the block's lower triangle changes.
    Eigen::MatrixXd big = Eigen::MatrixXd::Random(n + 9, n + 4);
    big.block(5, 2, n, n).triangularView<Eigen::Lower>() = llt.matrixLLT();
    const Eigen::MatrixXd before = big;
    mgp::choleskyInverseInPlace(big.block(5, 2, n, n), used);
    Eigen::MatrixXd want = before;
    want.block(5, 2, n, n).triangularView<Eigen::Lower>() = a;
    CHECK(big == want);
}
