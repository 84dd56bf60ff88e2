// The pose-range tint (render/range_tint.h): exact colours and weights at the breakpoints, and
// the colour a bone is drawn in (render/scene.h tintedColour). Pure: no GL context.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "range_tint.h"

using namespace mgp;
using namespace mgp::render;

namespace {

gp::TrainingRange testRange() {
    gp::TrainingRange r;
    r.sigma2Percentile = 2.0;
    r.sigma2Limit = 4.0;
    r.likLimit = 10.0;
    return r;
}

void checkVec(const glm::vec3& a, const glm::vec3& b) {
    CHECK(a.r == b.r);
    CHECK(a.g == b.g);
    CHECK(a.b == b.b);
}

}  // namespace

TEST_CASE("range tint: side colours up to the sigma^2 percentile") {
    const gp::TrainingRange r = testRange();
    for (double s2 : {0.0, 1.0, 2.0}) {
        const RangeTint t = rangeTint(r, s2, 5.0);
        CHECK(t.band == RangeBand::kInRange);
        CHECK(t.weight == 0.0f);
    }
}

TEST_CASE("range tint: amber ramps from the percentile to the limit") {
    const gp::TrainingRange r = testRange();
    RangeTint t = rangeTint(r, 3.0, 5.0);
    CHECK(t.band == RangeBand::kNearLimit);
    checkVec(t.colour, kRangeAmber);
    CHECK(t.weight == 0.5f);
    t = rangeTint(r, 2.5, 5.0);
    CHECK(t.weight == 0.25f);
    t = rangeTint(r, 4.0, 10.0);  // both exactly at their limits: still admissible
    CHECK(t.band == RangeBand::kNearLimit);
    checkVec(t.colour, kRangeAmber);
    CHECK(t.weight == 1.0f);
}

TEST_CASE("range tint: red above the sigma^2 limit or the L_IK limit or when not finite") {
    const gp::TrainingRange r = testRange();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const auto& values : {std::pair{4.0001, 5.0}, std::pair{100.0, 5.0}, std::pair{1.0, 10.0001},
                               std::pair{3.0, 50.0}, std::pair{nan, 5.0}, std::pair{1.0, nan},
                               std::pair{std::numeric_limits<double>::infinity(), 5.0}}) {
        // Named copies: clang before 16 cannot capture a structured binding in INFO's lambda.
        const double s2 = values.first, lik = values.second;
        INFO("sigma2 " << s2 << " lik " << lik);
        const RangeTint t = rangeTint(r, s2, lik);
        CHECK(t.band == RangeBand::kOutOfRange);
        checkVec(t.colour, kRangeRed);
        CHECK(t.weight == 1.0f);
    }
    CHECK(std::string(rangeBandLabel(RangeBand::kOutOfRange)) == "out of range");
    CHECK(std::string(rangeBandLabel(RangeBand::kNearLimit)) == "near limit");
    CHECK(std::string(rangeBandLabel(RangeBand::kInRange)) == "sigma^2 in range");
}

TEST_CASE("range tint: bone colours are the side colour at weight 0 and the tint at weight 1") {
    const glm::vec3 base{0.96f, 0.52f, 0.18f};
    Figure f;
    checkVec(tintedColour(base, f), base);
    applyRangeTint(f, rangeTint(testRange(), 3.0, 5.0));
    const glm::vec3 half = tintedColour(base, f);
    CHECK(half.r == doctest::Approx(0.98f).epsilon(1e-6));
    CHECK(half.g == doctest::Approx(0.62f).epsilon(1e-6));
    CHECK(half.b == doctest::Approx(0.09f).epsilon(1e-6));
    applyRangeTint(f, rangeTint(testRange(), 4.0, 5.0));
    checkVec(tintedColour(base, f), kRangeAmber);
    applyRangeTint(f, rangeTint(testRange(), 5.0, 5.0));
    checkVec(tintedColour(base, f), kRangeRed);
    applyRangeTint(f, rangeTint(testRange(), 1.0, 5.0));
    checkVec(tintedColour(base, f), base);
}
