// The second-difference smoothness prior on latent trajectories (docs/maths.md §19): known values,
// segmentation, and central-difference checks of both gradients (whole X and one point).
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "gp/temporal_prior.h"
#include "gp/train/active_step.h"

using namespace mgp::gp;

namespace {

Eigen::MatrixXd wavy(int n) {
    Eigen::MatrixXd X(n, 2);
    for (int i = 0; i < n; ++i) {
        X(i, 0) = std::sin(0.7 * i) + 0.1 * i;
        X(i, 1) = std::cos(1.3 * i) - 0.05 * i * i;
    }
    return X;
}

}  // namespace

TEST_CASE("temporal prior: names parse both ways and bad ones are refused") {
    LatentPrior p = LatentPrior::kNone;
    CHECK(parseLatentPrior("smooth", p));
    CHECK(p == LatentPrior::kSmooth);
    CHECK(std::string(latentPriorName(p)) == "smooth");
    CHECK(parseLatentPrior("none", p));
    CHECK(p == LatentPrior::kNone);
    CHECK_FALSE(parseLatentPrior("gpdm", p));
    CHECK_THROWS(TemporalPrior::secondDifference({0, 1, 2}, -1.0));
}

TEST_CASE("temporal prior: known values on equally spaced frames") {
    const std::vector<int> frames{0, 1, 2, 3, 4};
    const TemporalPrior p = TemporalPrior::secondDifference(frames, 2.0);
    REQUIRE(p.triples().size() == 3);
    CHECK(p.triples()[0].coef[0] == 1.0);
    CHECK(p.triples()[0].coef[1] == -2.0);
    CHECK(p.triples()[0].coef[2] == 1.0);
    // A straight line at constant speed costs nothing.
    Eigen::MatrixXd X(5, 2);
    for (int i = 0; i < 5; ++i) X.row(i) << 0.5 * i - 1.0, 2.0 - 0.25 * i;
    CHECK(p.value(X) == doctest::Approx(0.0).epsilon(1e-15));
    // One point pushed by (1, 0): second differences 1, −2, 1 at the three triples → (λ/2)·6.
    X(2, 0) += 1.0;
    CHECK(p.value(X) == doctest::Approx(0.5 * 2.0 * 6.0).epsilon(1e-14));
}

TEST_CASE("temporal prior: unequal gaps annihilate linear motion, large gaps split segments") {
    // Gaps 1, 2, 1 (every-10th hold-out leaves gaps of 2), then a cut of 50 frames.
    const std::vector<int> frames{10, 11, 13, 14, 64, 65, 66};
    const TemporalPrior p = TemporalPrior::secondDifference(frames, 1.0);
    // Triples (10,11,13), (11,13,14) and (64,65,66); none across the cut.
    REQUIRE(p.triples().size() == 3);
    Eigen::MatrixXd X(7, 2);
    for (int i = 0; i < 7; ++i) X.row(i) << 0.3 * frames[i] + 1.0, -0.2 * frames[i];
    CHECK(p.value(X) == doctest::Approx(0.0).epsilon(1e-12));
    // A jump between the two segments costs nothing either.
    X.bottomRows(3).array() += 5.0;
    CHECK(p.value(X) == doctest::Approx(0.0).epsilon(1e-12));
    // Divided second difference for h₁ = 1, h₂ = 2: a = 2/3, c = 1/3, b = −1.
    const auto& t = p.triples()[0];
    CHECK(t.coef[0] == doctest::Approx(2.0 / 3.0));
    CHECK(t.coef[1] == doctest::Approx(-1.0));
    CHECK(t.coef[2] == doctest::Approx(1.0 / 3.0));
}

TEST_CASE("temporal prior: rows in any order follow their frames") {
    const TemporalPrior a = TemporalPrior::secondDifference({0, 1, 2, 3}, 1.0);
    const TemporalPrior b = TemporalPrior::secondDifference({3, 1, 0, 2}, 1.0);
    Eigen::MatrixXd Xa = wavy(4), Xb(4, 2);
    const int rowOf[4] = {2, 1, 3, 0};  // frame f sits in row rowOf[f] of b
    for (int f = 0; f < 4; ++f) Xb.row(rowOf[f]) = Xa.row(f);
    CHECK(a.value(Xa) == doctest::Approx(b.value(Xb)).epsilon(1e-14));
}

// ∂L/∂X of the whole prior against central differences, entry by entry.
static void checkWholePriorGradient(const TemporalPrior& p, const Eigen::MatrixXd& X) {
    Eigen::MatrixXd g;
    p.value(X, &g);
    const double h = 1e-6;
    for (Eigen::Index i = 0; i < X.rows(); ++i)
        for (Eigen::Index k = 0; k < X.cols(); ++k) {
            Eigen::MatrixXd Xp = X, Xm = X;
            Xp(i, k) += h;
            Xm(i, k) -= h;
            const double fd = (p.value(Xp) - p.value(Xm)) / (2 * h);
            CHECK(g(i, k) == doctest::Approx(fd).epsilon(1e-6).scale(1.0));
        }
}

// One row's part of the prior: replacing that row changes the whole prior by exactly the change
// of its part, and the part's gradient in x matches central differences.
static void checkOnePointPart(const TemporalPrior& p, const Eigen::MatrixXd& X, int row) {
    CAPTURE(row);
    Eigen::VectorXd x(2);
    x << 0.4, -1.1;
    Eigen::MatrixXd X2 = X;
    X2.row(row) = x.transpose();
    const double whole = p.value(X2) - p.value(X);
    const double part = p.pointValue(X, row, x, nullptr) - p.pointValue(X, row, X.row(row).transpose(), nullptr);
    CHECK(whole == doctest::Approx(part).epsilon(1e-12));
    Eigen::VectorXd g;
    p.pointValue(X, row, x, &g);
    const double h = 1e-6;
    for (int k = 0; k < 2; ++k) {
        Eigen::VectorXd xp = x, xm = x;
        xp[k] += h;
        xm[k] -= h;
        const double fd = (p.pointValue(X, row, xp, nullptr) - p.pointValue(X, row, xm, nullptr)) / (2 * h);
        CHECK(g[k] == doctest::Approx(fd).epsilon(1e-6).scale(1.0));
    }
}

TEST_CASE("temporal prior: gradient of L_smooth(X) by central differences") {
    const std::vector<int> frames{0, 1, 2, 4, 5, 6, 7, 30, 31, 32, 33};
    const TemporalPrior p = TemporalPrior::secondDifference(frames, 3.7);
    const Eigen::MatrixXd X = wavy(static_cast<int>(frames.size()));
    checkWholePriorGradient(p, X);
}

TEST_CASE("temporal prior: one point's part has the whole prior's differences and gradient") {
    const std::vector<int> frames{0, 1, 2, 3, 4, 5, 6, 7};
    const TemporalPrior p = TemporalPrior::secondDifference(frames, 0.8);
    const Eigen::MatrixXd X = wavy(8);
    for (int row : {0, 1, 4, 7}) checkOnePointPart(p, X, row);
}

TEST_CASE("temporal prior: the Step-6 term on the active rows, gradient by central differences") {
    const std::vector<int> frames{0, 1, 2, 3, 4, 5, 6, 7, 8};
    const TemporalPrior p = TemporalPrior::secondDifference(frames, 2.5);
    const Eigen::MatrixXd X = wavy(9);
    const std::vector<int> active{7, 1, 4, 5};  // any order, inactive rows in between
    const LatentTerm term = priorOnActive(p, X, active);
    Eigen::MatrixXd XI(4, 2);
    XI << 0.3, -0.2, 1.1, 0.4, -0.7, 0.9, 0.05, -1.3;
    Eigen::MatrixXd g, scratch;
    const double v = term(XI, g);
    // The value is the whole prior with those rows replaced.
    Eigen::MatrixXd full = X;
    for (std::size_t i = 0; i < active.size(); ++i) full.row(active[i]) = XI.row(static_cast<Eigen::Index>(i));
    CHECK(v == doctest::Approx(p.value(full)).epsilon(1e-14));
    REQUIRE(g.rows() == 4);
    const double h = 1e-6;
    for (Eigen::Index i = 0; i < XI.rows(); ++i)
        for (Eigen::Index k = 0; k < XI.cols(); ++k) {
            Eigen::MatrixXd Xp = XI, Xm = XI;
            Xp(i, k) += h;
            Xm(i, k) -= h;
            const double fd = (term(Xp, scratch) - term(Xm, scratch)) / (2 * h);
            CHECK(g(i, k) == doctest::Approx(fd).epsilon(1e-6).scale(1.0));
        }
}

TEST_CASE("paced prior: the name parses and round-trips") {
    LatentPrior p = LatentPrior::kNone;
    CHECK(parseLatentPrior("paced", p));
    CHECK(p == LatentPrior::kPaced);
    CHECK(std::string(latentPriorName(p)) == "paced");
    CHECK_THROWS(TemporalPrior::posePaced({0, 1, 2}, Eigen::MatrixXd::Zero(2, 3), 1.0));  // one pose row per frame
    CHECK_THROWS(TemporalPrior::posePaced({0, 1, 2}, Eigen::MatrixXd::Zero(3, 3), -1.0));
}

TEST_CASE("paced prior: gaps are pose distances over their median, clamped") {
    // Pose steps 1, 2, 1, 1, 0.1, 10 along one axis (median 1): h = 1, 2, 1, 1, 0.25, 4.
    const std::vector<int> frames{0, 1, 2, 3, 4, 5, 6};
    Eigen::MatrixXd Y = Eigen::MatrixXd::Zero(7, 3);
    const double steps[6] = {1.0, 2.0, 1.0, 1.0, 0.1, 10.0};
    for (int i = 1; i < 7; ++i) Y(i, 1) = Y(i - 1, 1) + steps[i - 1];
    const TemporalPrior p = TemporalPrior::posePaced(frames, Y, 1.0);
    REQUIRE(p.triples().size() == 5);
    const double h[6] = {1.0, 2.0, 1.0, 1.0, kMinPaceGap, kMaxPaceGap};
    for (int k = 0; k < 5; ++k) {
        const auto& t = p.triples()[static_cast<std::size_t>(k)];
        const double h1 = h[k], h2 = h[k + 1];
        CHECK(t.coef[0] == doctest::Approx(2.0 / (h1 * (h1 + h2))).epsilon(1e-14));
        CHECK(t.coef[2] == doctest::Approx(2.0 / (h2 * (h1 + h2))).epsilon(1e-14));
        CHECK(t.coef[1] == doctest::Approx(-(t.coef[0] + t.coef[2])).epsilon(1e-14));
    }
    // Triple (0,1,2), h = (1, 2): a = 2/3, b = −1, c = 1/3.
    CHECK(p.triples()[0].coef[0] == doctest::Approx(2.0 / 3.0));
    CHECK(p.triples()[0].coef[1] == doctest::Approx(-1.0));
    CHECK(p.triples()[0].coef[2] == doctest::Approx(1.0 / 3.0));
    // A latent path that moves as far as the pose does (unclamped steps) costs nothing.
    const std::vector<int> f5{0, 1, 2, 3, 4};
    const Eigen::MatrixXd Y5 = Y.topRows(5);
    const TemporalPrior q = TemporalPrior::posePaced(f5, Y5, 2.0);
    Eigen::MatrixXd X(5, 2);
    for (int i = 0; i < 5; ++i) X.row(i) << 0.5 * Y5(i, 1) - 1.0, 2.0 - 0.25 * Y5(i, 1);
    CHECK(q.value(X) == doctest::Approx(0.0).epsilon(1e-14));
    // The frame-spaced prior charges that path for its change of speed.
    CHECK(TemporalPrior::secondDifference(f5, 2.0).value(X) > 0.01);
}

TEST_CASE("paced prior: same segments as the smooth prior, equal poses steps give its coefficients") {
    const std::vector<int> frames{10, 11, 13, 14, 64, 65, 66};
    Eigen::MatrixXd Y(7, 2);
    for (int i = 0; i < 7; ++i) Y.row(i) << 0.7 * frames[i], 3.0;  // pose moves in step with the frames
    const TemporalPrior s = TemporalPrior::secondDifference(frames, 1.0);
    const TemporalPrior p = TemporalPrior::posePaced(frames, Y, 1.0);
    REQUIRE(p.triples().size() == s.triples().size());
    for (std::size_t k = 0; k < s.triples().size(); ++k)
        for (int j = 0; j < 3; ++j) {
            CHECK(p.triples()[k].row[j] == s.triples()[k].row[j]);
            CHECK(p.triples()[k].coef[j] == doctest::Approx(s.triples()[k].coef[j]).epsilon(1e-14));
        }
    // Every pose equal: no pace to follow, gaps of 1 (the plain second difference).
    const TemporalPrior still = TemporalPrior::posePaced({0, 1, 2, 3}, Eigen::MatrixXd::Ones(4, 5), 1.0);
    REQUIRE(still.triples().size() == 2);
    CHECK(still.triples()[0].coef[1] == doctest::Approx(-2.0));
}

TEST_CASE("paced prior: gradients of the whole prior and of one point by central differences") {
    const std::vector<int> frames{0, 1, 2, 4, 5, 6, 7, 30, 31, 32, 33};
    Eigen::MatrixXd Y(11, 3);
    for (int i = 0; i < 11; ++i)
        Y.row(i) << std::sin(0.4 * frames[i]), 0.3 * frames[i] * frames[i] / 10.0, std::cos(frames[i]);
    const TemporalPrior p = TemporalPrior::posePaced(frames, Y, 3.7);
    const Eigen::MatrixXd X = wavy(11);
    checkWholePriorGradient(p, X);
    for (int row : {0, 3, 5, 10}) checkOnePointPart(p, X, row);
}
