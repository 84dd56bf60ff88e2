// The pose-range tint (render/range_tint.h): the colour and weight of each verdict, and the colour
// a bone is drawn in (render/scene.h tintedColour). Pure: no GL context.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "render/range_tint.h"

using namespace mgp;
using namespace mgp::render;

namespace {

AdmissionVerdict verdict(PoseJudgement j, double unusual = 0.0) {
    AdmissionVerdict v;
    v.judgement = j;
    v.admitted = j == PoseJudgement::kNatural || j == PoseJudgement::kUnusual;
    v.unusual = unusual;
    return v;
}

void checkVec(const glm::vec3& a, const glm::vec3& b) {
    CHECK(a.r == b.r);
    CHECK(a.g == b.g);
    CHECK(a.b == b.b);
}

}  // namespace

TEST_CASE("range tint: a natural pose keeps its side colours") {
    const RangeTint t = rangeTint(verdict(PoseJudgement::kNatural));
    CHECK(t.band == RangeBand::kInRange);
    CHECK(t.weight == 0.0f);
}

TEST_CASE("range tint: an unusual pose is amber, weighted by how far it is along the ramp") {
    for (double u : {0.0, 0.25, 0.5, 1.0}) {
        const RangeTint t = rangeTint(verdict(PoseJudgement::kUnusual, u));
        CHECK(t.band == RangeBand::kNearLimit);
        checkVec(t.colour, kRangeAmber);
        CHECK(t.weight == float(u));
    }
    CHECK(rangeTint(verdict(PoseJudgement::kUnusual, std::numeric_limits<double>::quiet_NaN())).weight == 1.0f);
    CHECK(rangeTint(verdict(PoseJudgement::kUnusual, 7.0)).weight == 1.0f);
}

TEST_CASE("range tint: every refusal is red at full weight") {
    for (PoseJudgement j : {PoseJudgement::kUnlikeCapture, PoseJudgement::kOutOfReach, PoseJudgement::kThroughFloor,
                            PoseJudgement::kOffBalance}) {
        CAPTURE(judgementWords(j));
        const RangeTint t = rangeTint(verdict(j));
        CHECK(t.band == RangeBand::kOutOfRange);
        checkVec(t.colour, kRangeRed);
        CHECK(t.weight == 1.0f);
    }
}

TEST_CASE("range tint: bone colours are the side colour at weight 0 and the tint at weight 1") {
    const glm::vec3 base{0.96f, 0.52f, 0.18f};
    Figure f;
    checkVec(tintedColour(base, f), base);
    applyRangeTint(f, rangeTint(verdict(PoseJudgement::kUnusual, 0.5)));
    const glm::vec3 half = tintedColour(base, f);
    CHECK(half.r == doctest::Approx(0.98f).epsilon(1e-6));
    CHECK(half.g == doctest::Approx(0.62f).epsilon(1e-6));
    CHECK(half.b == doctest::Approx(0.09f).epsilon(1e-6));
    applyRangeTint(f, rangeTint(verdict(PoseJudgement::kUnusual, 1.0)));
    checkVec(tintedColour(base, f), kRangeAmber);
    applyRangeTint(f, rangeTint(verdict(PoseJudgement::kUnlikeCapture)));
    checkVec(tintedColour(base, f), kRangeRed);
    applyRangeTint(f, rangeTint(verdict(PoseJudgement::kNatural)));
    checkVec(tintedColour(base, f), base);
}
