// The foot-contact rule (core/motion/foot_contacts.h): hand-made trajectories with known answers,
// then the shipped walk.
#include "io/clip_loader.h"
#include "motion/foot_contacts.h"
#include "test_support.h"

using namespace mgp;

namespace {

// A foot at height h (cm above y = 0) moving at v cm/frame along x, frame by frame.
std::vector<Eigen::Vector3d> track(const std::vector<std::pair<double, double>>& heightAndSpeed) {
    std::vector<Eigen::Vector3d> p;
    double x = 0.0;
    for (const auto& [h, v] : heightAndSpeed) {
        x += v;
        p.emplace_back(x, h, 0.0);
    }
    return p;
}

std::vector<std::pair<double, double>> repeat(int n, double h, double v) {
    return std::vector<std::pair<double, double>>(n, {h, v});
}

// Still, rising by 0.3 cm a frame to 3 cm and back down (0.3 cm/frame: slower than the exit speed).
std::vector<std::pair<double, double>> wobble() {
    std::vector<std::pair<double, double>> out;
    for (int i = 1; i <= 10; ++i) out.push_back({0.3 * i, 0.0});
    for (int i = 9; i >= 0; --i) out.push_back({0.3 * i, 0.0});
    return out;
}

template <typename... Parts>
std::vector<std::pair<double, double>> join(const Parts&... parts) {
    std::vector<std::pair<double, double>> out;
    (out.insert(out.end(), parts.begin(), parts.end()), ...);
    return out;
}

}  // namespace

TEST_CASE("foot contacts: low and still is planted, hysteresis keeps a 3 cm foot planted") {
    ContactRule rule;
    rule.groundPercentile = 0.0;  // ground = the lowest point, 0 here
    // Frames 0-9 in the air, 10-29 planted, 30-49 a slow wobble up to 3 cm (between the enter
    // height 2.5 and the exit height 3.5: stays planted), 50-69 planted, 70-79 in the air.
    const auto foot =
        track(join(repeat(10, 20.0, 2.0), repeat(20, 0.0, 0.0), wobble(), repeat(20, 0.0, 0.0), repeat(10, 20.0, 2.0)));
    const ContactSet set = detectFootContacts(foot, {}, 120.0, rule);
    CHECK(set.groundCm == doctest::Approx(0.0));
    REQUIRE(set.contacts.size() == 1);
    // Frames 10 and 69 are low, but their central differences span the 20 cm drop and rise.
    CHECK(set.contacts[0].first == 11);
    CHECK(set.contacts[0].last == 68);
    CHECK(set.contacts[0].foot == Effector::kLFoot);
    CHECK(set.at(Effector::kLFoot, 30) != nullptr);
    CHECK(set.at(Effector::kLFoot, 5) == nullptr);
    CHECK(set.at(Effector::kRFoot, 30) == nullptr);
}

TEST_CASE("foot contacts: lift above the exit height ends a contact, short contacts and gaps") {
    ContactRule rule;
    rule.groundPercentile = 0.0;
    SUBCASE("a lift to 5 cm for 10 frames splits the contact") {
        const auto foot = track(join(repeat(20, 0.0, 0.0), repeat(10, 5.0, 0.0), repeat(20, 0.0, 0.0)));
        const ContactSet set = detectFootContacts({}, foot, 120.0, rule);
        REQUIRE(set.contacts.size() == 2);
        CHECK(set.contacts[0].foot == Effector::kRFoot);
        // The central differences at frames 19 and 30 see the 5 cm step: 2.5 cm/frame.
        CHECK(set.contacts[0].first == 0);
        CHECK(set.contacts[0].last == 18);
        CHECK(set.contacts[1].first == 31);
        CHECK(set.contacts[1].last == 49);
    }
    SUBCASE("a 1-frame spike is a jitter: the 3-frame gap it leaves is merged") {
        const auto foot = track(join(repeat(20, 0.0, 0.0), repeat(1, 5.0, 0.0), repeat(20, 0.0, 0.0)));
        const ContactSet set = detectFootContacts({}, foot, 120.0, rule);
        REQUIRE(set.contacts.size() == 1);
        CHECK(set.contacts[0].first == 0);
        CHECK(set.contacts[0].last == 40);
        rule.mergeGapFrames = 2;
        CHECK(detectFootContacts({}, foot, 120.0, rule).contacts.size() == 2);
    }
    SUBCASE("a 5-frame touch is shorter than minFrames (6): dropped") {
        const auto foot = track(join(repeat(10, 10.0, 0.0), repeat(5, 0.0, 0.0), repeat(10, 10.0, 0.0)));
        CHECK(detectFootContacts({}, foot, 120.0, rule).contacts.empty());
    }
}

TEST_CASE("foot contacts: speed thresholds are per frame at 120 fps, scaled for other rates") {
    ContactRule rule;
    rule.groundPercentile = 0.0;
    // 0.15 cm/frame: planted at 120 fps (≤ 0.2), but at 60 fps the same per-frame step is twice
    // the speed in cm/s and the threshold becomes 0.4 cm/frame, so still planted; at 240 fps the
    // threshold is 0.1 cm/frame and the foot is sliding.
    const auto foot = track(repeat(30, 0.0, 0.15));
    CHECK(detectFootContacts(foot, {}, 120.0, rule).contacts.size() == 1);
    CHECK(detectFootContacts(foot, {}, 60.0, rule).contacts.size() == 1);
    CHECK(detectFootContacts(foot, {}, 240.0, rule).contacts.empty());
}

TEST_CASE("foot contacts: the ground is the lower foot's height percentile, disabled contacts are skipped") {
    std::vector<Eigen::Vector3d> left, right;
    for (int t = 0; t < 100; ++t) {
        left.emplace_back(0.0, 10.0 + (t % 10 == 0 ? 30.0 : 0.0), 0.0);  // 10 cm, sometimes 40
        right.emplace_back(0.0, 12.0, 0.0);
    }
    ContactSet set = detectFootContacts(left, right, 120.0);
    CHECK(set.groundCm == doctest::Approx(10.0));
    REQUIRE(set.at(Effector::kRFoot, 50) != nullptr);  // 2 cm above ground: planted
    set.at(Effector::kRFoot, 50)->enabled = false;
    CHECK(set.at(Effector::kRFoot, 50) == nullptr);
}

TEST_CASE("foot contacts: a bad rule is refused with a clear message") {
    const auto foot = track(repeat(10, 0.0, 0.0));
    ContactRule rule;
    rule.exitHeightCm = 1.0;  // tighter than enter (2.5): no hysteresis
    CHECK_THROWS_WITH_AS(detectFootContacts(foot, {}, 120.0, rule),
                         doctest::Contains("expected exit thresholds at least the enter thresholds"),
                         std::invalid_argument);
    rule = ContactRule{};
    rule.minFrames = 0;
    CHECK_THROWS_AS(detectFootContacts(foot, {}, 120.0, rule), std::invalid_argument);
    CHECK_THROWS_AS(detectFootContacts(foot, {}, 0.0, ContactRule{}), std::invalid_argument);
}

TEST_CASE("foot contacts on the shipped walk (35_01): three plants per foot, alternating, each held") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const ContactSet set = detectFootContacts(clip);
    int left = 0, right = 0;
    const auto lfoot = effectorTrajectory(clip, Effector::kLFoot);
    const auto rfoot = effectorTrajectory(clip, Effector::kRFoot);
    for (const FootContact& c : set.contacts) {
        (c.foot == Effector::kLFoot ? left : right) += 1;
        const auto& p = c.foot == Effector::kLFoot ? lfoot : rfoot;
        double travel = 0.0;
        for (int t = c.first; t <= c.last; ++t) {
            CHECK(p[t].y() - set.groundCm <= 3.5 + 1e-9);  // never above the exit height
            travel = std::max(travel, (p[t] - p[c.first]).norm());
        }
        CHECK(travel < 5.0);  // a planted ankle rolls a few cm, never a step (≈ 60 cm)
    }
    CHECK(left == 3);
    CHECK(right == 3);
    // A walk always has a foot on the ground except in brief double-float-free transitions: at
    // least 60 % of frames have a planted foot.
    int covered = 0;
    for (int t = 0; t < clip.frameCount(); ++t) covered += set.at(Effector::kLFoot, t) || set.at(Effector::kRFoot, t);
    CHECK(covered >= 0.6 * clip.frameCount());
}
