// Block-banded Cholesky (motion/block_banded.h) against a dense solve.
#include <Eigen/Cholesky>
#include <random>

#include "motion/block_banded.h"
#include "test_support.h"

using namespace mgp;

TEST_CASE("block-banded Cholesky solves like a dense LLT, and refuses an indefinite matrix") {
    std::mt19937 rng(3);
    std::normal_distribution<double> g(0.0, 1.0);
    for (int w : {0, 1, 2}) {
        CAPTURE(w);
        const int n = 7, b = 4;
        BlockBandedMatrix a(n, b, w);
        // A = BᵀB + I restricted to the band pattern is not SPD in general; build a banded SPD
        // matrix as a sum of banded outer products plus a diagonal.
        for (int i = 0; i < n; ++i) {
            a.block(i, i) = Eigen::MatrixXd::Identity(b, b) * 5.0;
            for (int j = std::max(0, i - w); j <= i; ++j) {
                Eigen::MatrixXd r(b, b);
                for (int p = 0; p < b; ++p)
                    for (int q = 0; q < b; ++q) r(p, q) = g(rng);
                if (j == i)
                    a.block(i, i) += r * r.transpose();
                else
                    a.block(i, j) = 0.3 * r;
            }
        }
        const Eigen::MatrixXd dense = a.dense();
        REQUIRE(dense.isApprox(dense.transpose()));
        Eigen::VectorXd rhs(n * b);
        for (int k = 0; k < rhs.size(); ++k) rhs[k] = g(rng);
        BlockBandedMatrix l;
        REQUIRE(l.factor(a, 0.0, 0.0));
        const Eigen::VectorXd x = l.solve(rhs);
        const Eigen::VectorXd ref = dense.llt().solve(rhs);
        CHECK((x - ref).norm() < 1e-10 * ref.norm());
        // The shift adds shift·(|A_kk| + floor) to the diagonal.
        REQUIRE(l.factor(a, 0.5, 1.0));
        Eigen::MatrixXd shifted = dense;
        shifted.diagonal().array() += 0.5 * (dense.diagonal().array().abs() + 1.0);
        CHECK((l.solve(rhs) - shifted.llt().solve(rhs)).norm() < 1e-10 * rhs.norm());
    }
    BlockBandedMatrix bad(3, 2, 1);
    for (int i = 0; i < 3; ++i) bad.block(i, i) = -Eigen::MatrixXd::Identity(2, 2);
    BlockBandedMatrix l;
    CHECK_FALSE(l.factor(bad, 0.0, 0.0));
}
