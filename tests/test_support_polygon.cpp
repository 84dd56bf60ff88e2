// Balance (core/motion/support_polygon.h): the convex hull and the distance outside it by hand,
// the planted feet's polygon on the walk, and the off-balance judgement.
#include <cmath>

#include "motion/support_polygon.h"
#include "skeleton/centre_of_mass.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("support polygon: the convex hull drops interior and collinear points and runs counter-clockwise") {
    const std::vector<Eigen::Vector2d> hull =
        convexHull({{0, 0}, {4, 0}, {2, 0}, {4, 3}, {0, 3}, {2, 1}, {0, 3}, {4, 1.5}});
    REQUIRE(hull.size() == 4);
    CHECK(hull[0] == Eigen::Vector2d(0, 0));
    CHECK(hull[1] == Eigen::Vector2d(4, 0));
    CHECK(hull[2] == Eigen::Vector2d(4, 3));
    CHECK(hull[3] == Eigen::Vector2d(0, 3));
    CHECK(convexHull({{1, 1}, {1, 1}}).size() == 1);
    CHECK(convexHull({{0, 0}, {1, 1}, {2, 2}}).size() == 2);  // collinear: the two ends
}

TEST_CASE("support polygon: the distance outside the polygon grown by half a sole") {
    SupportPolygon square;
    square.hull = {{0, 0}, {20, 0}, {20, 30}, {0, 30}};
    CHECK(square.outsideCm({10, 10}) == 0.0);
    CHECK(square.outsideCm({20, 30}) == 0.0);                   // a corner
    CHECK(square.outsideCm({24, 10}) == 0.0);                   // within the half sole
    CHECK(square.outsideCm({28, 10}) == doctest::Approx(3.0));  // 8 cm from the edge
    CHECK(square.outsideCm({23, 34}) == doctest::Approx(0.0));  // 5 cm from the corner
    CHECK(square.outsideCm({26, 38}) == doctest::Approx(5.0));  // 10 cm from the corner
    SupportPolygon foot;                                        // one foot seen edge-on: a segment
    foot.hull = {{0, 0}, {0, 20}};
    CHECK(foot.outsideCm({3, 10}) == 0.0);
    CHECK(foot.outsideCm({9, 10}) == doctest::Approx(4.0));
    CHECK(foot.outsideCm({0, 27}) == doctest::Approx(2.0));
    SupportPolygon point;
    point.hull = {{1, 1}};
    CHECK(point.outsideCm({1, 11}) == doctest::Approx(5.0));
    // The outline drawn is the boundary outsideCm measures from: its points are half a sole from the
    // hull, on it (0 outside), and a point 1 cm beyond one of them along the outward normal is outside.
    for (const SupportPolygon& s : {square, foot, point}) {
        const std::vector<Eigen::Vector2d> outline = s.grownOutline();
        REQUIRE(outline.size() >= 12);
        for (const Eigen::Vector2d& p : outline) CHECK(s.outsideCm(p) <= 1e-9);
    }
    CHECK(square.outsideCm({25 + 1, 10}) == doctest::Approx(1.0));
}

TEST_CASE("support polygon: the walk's planted feet, and balance judged only where the capture was balanced") {
    const auto version = test::walkModel35();
    const Clip& clip = version->model->clip;
    const ContactSet contacts = detectFootContacts(clip);
    int planted = 0, inAir = 0, balanced = 0;
    for (int t = 0; t < clip.frameCount(); ++t) {
        FkState fk;
        forwardKinematics(clip.skeleton, clip.frames[t], fk);
        const std::optional<SupportPolygon> support = supportPolygon(clip.skeleton, fk, contacts, t);
        const bool anyFoot = contacts.at(Effector::kLFoot, t) || contacts.at(Effector::kRFoot, t);
        CHECK(support.has_value() == anyFoot);
        if (!support) {
            ++inAir;
            CHECK_FALSE(judgeBalance(clip.skeleton, clip.frames[t], clip.frames[t], contacts, t).judged);
            continue;
        }
        ++planted;
        // A flat foot stands on its ankle, ball and toe; a heel alone on one point, a toe on two.
        bool flat = false;
        for (Effector foot : {Effector::kLFoot, Effector::kRFoot})
            if (const FootContact* c = contacts.at(foot, t)) flat = flat || (c->heel.contains(t) && c->toe.contains(t));
        CHECK(support->hull.size() >= (flat ? 3u : 1u));
        // The captured pose judged against itself: off balance never, judged where it stands over its feet.
        const Balance self = judgeBalance(clip.skeleton, clip.frames[t], clip.frames[t], contacts, t);
        CHECK_FALSE(self.offBalance);
        const Eigen::Vector3d com = *centreOfMass(clip.skeleton, fk);
        const double outside = support->outsideCm({com.x(), com.z()});
        CHECK(self.judged == (outside <= kBalanceToleranceCm));
        if (self.judged) {
            ++balanced;
            CHECK(self.outsideCm == outside);
        }
    }
    MESSAGE("35_01: " << planted << " frames with a planted foot (" << balanced << " balanced over it), " << inAir
                      << " without");
    CHECK(planted > 0);
    CHECK(balanced > 0);
}

TEST_CASE("support polygon: leaning the trunk far over a balanced frame's support is off balance") {
    const auto version = test::walkModel35();
    const Clip& clip = version->model->clip;
    const ContactSet contacts = detectFootContacts(clip);
    const int lowerback = clip.skeleton.findBone("lowerback");
    REQUIRE(lowerback >= 0);
    bool tried = false;
    for (int t = 0; t < clip.frameCount() && !tried; ++t) {
        if (!judgeBalance(clip.skeleton, clip.frames[t], clip.frames[t], contacts, t).judged) continue;
        tried = true;
        double lastOutside = -1.0;
        for (double lean : {0.0, 30.0, 60.0, 90.0}) {
            Pose pose = clip.frames[t];
            pose.anglesDeg[lowerback].x() += lean;
            const Balance b = judgeBalance(clip.skeleton, clip.frames[t], pose, contacts, t);
            CAPTURE(lean);
            CHECK(b.judged);
            CHECK(b.offBalance == (b.outsideCm > kBalanceToleranceCm));
            CHECK(b.outsideCm >= lastOutside);  // leaning further only moves the mass further out
            lastOutside = b.outsideCm;
        }
        CHECK(lastOutside > kBalanceToleranceCm);  // bent double, the mass hangs past the toes or heels
    }
    CHECK(tried);
}
