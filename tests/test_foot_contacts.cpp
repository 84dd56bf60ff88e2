// The foot-contact rule (core/motion/foot_contacts.h): hand-made trajectories with known answers,
// then the shipped walk and run.
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
    rule.toe.exitHeightCm = 1.0;  // tighter than enter (2.5): no hysteresis
    CHECK_THROWS_WITH_AS(detectFootContacts(foot, {}, 120.0, rule),
                         doctest::Contains("expected exit thresholds at least the enter thresholds"),
                         std::invalid_argument);
    rule = ContactRule{};
    rule.minFrames = 0;
    CHECK_THROWS_AS(detectFootContacts(foot, {}, 120.0, rule), std::invalid_argument);
    CHECK_THROWS_AS(detectFootContacts(foot, {}, 0.0, ContactRule{}), std::invalid_argument);
    rule = ContactRule{};
    rule.heel.exitSpeedCmPerFrame = 0.5;  // tighter than the heel's enter speed (0.8)
    CHECK_THROWS_WITH_AS(detectFootContacts(foot, {}, 120.0, rule), doctest::Contains("(heel)"), std::invalid_argument);
    // A heel track must cover the toe track's frames.
    CHECK_THROWS_WITH_AS(detectFootContacts(FootTrack{foot, track(repeat(9, 0.0, 0.0))}, FootTrack{}, 120.0),
                         doctest::Contains("expected a heel track as long as its toe track (10 frames), found 9"),
                         std::invalid_argument);
}

TEST_CASE("foot contacts: a stance runs from heel strike to toe-off, each point down for its own phase") {
    ContactRule rule;
    rule.groundPercentile = 0.0;
    // 60 frames. The heel comes down at frame 10 and rolls forward at 0.6 cm/frame (slow enough
    // for the heel's enter speed, 0.8, too fast for the toe's, 0.2) until the foot is flat at 20;
    // the heel lifts at 40 (2 cm a frame), the toe stays down and pivots at 0.5 cm/frame (under the
    // toe's exit speed, 0.8) until it lifts at 50.
    std::vector<std::pair<double, double>> heel, toe;
    for (int t = 0; t < 60; ++t) {
        const bool heelDown = t >= 10 && t < 40, toeDown = t >= 20 && t < 50;
        heel.push_back({heelDown ? 0.0 : 10.0 + 2.0 * std::abs(t - 25), t < 20 ? 0.6 : 0.0});
        toe.push_back({toeDown ? 0.0 : 6.0, t >= 40 && t < 50 ? 0.5 : (toeDown ? 0.0 : 0.6)});
    }
    const auto heelPath = track(heel), toePath = track(toe);
    const ContactSet set = detectFootContacts(FootTrack{toePath, heelPath}, FootTrack{}, 120.0, rule);
    REQUIRE(set.contacts.size() == 1);
    const FootContact& c = set.contacts[0];
    MESSAGE("stance " << c.first << ".." << c.last << ", heel " << c.heel.first << ".." << c.heel.last << ", toe "
                      << c.toe.first << ".." << c.toe.last);
    // Frames 10 and 39 see the 10 cm step in their central differences (5 cm/frame), like 20 and
    // 49 for the toe: each phase starts a frame late and ends a frame early.
    CHECK(c.heel.first == 11);
    CHECK(c.heel.last == 38);
    CHECK(c.toe.first == 21);
    CHECK(c.toe.last == 48);
    CHECK(c.first == 11);
    CHECK(c.last == 48);
    // The toe alone, as before heel tracking: the stance would start 10 frames after heel strike.
    const ContactSet toeOnly = detectFootContacts(toePath, {}, 120.0, rule);
    REQUIRE(toeOnly.contacts.size() == 1);
    CHECK(toeOnly.contacts[0].first == 21);
    CHECK(toeOnly.contacts[0].heel.empty());
}

TEST_CASE("foot contacts on the shipped walk (35_01): heel strike to toe-off, alternating, always a foot down") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const ContactSet set = detectFootContacts(clip);
    const ContactRule rule;
    int left = 0, right = 0;
    const FootTrack ltrack = footTrack(clip, Effector::kLFoot), rtrack = footTrack(clip, Effector::kRFoot);
    for (const FootContact& c : set.contacts) {
        (c.foot == Effector::kLFoot ? left : right) += 1;
        const FootTrack& p = c.foot == Effector::kLFoot ? ltrack : rtrack;
        MESSAGE(std::string(effectorName(c.foot))
                << " " << c.first + 1 << ".." << c.last + 1 << " heel " << c.heel.first + 1 << ".." << c.heel.last + 1
                << " toe " << c.toe.first + 1 << ".." << c.toe.last + 1);
        // Each point is low for its own phase. The ball of the foot stays put while the foot is flat
        // (both points down), and at toe-off pivots about the toes: a few cm, never a step (≈ 60 cm).
        for (int t = c.heel.first; t <= c.heel.last; ++t)
            CHECK(p.heelCm[t].y() - set.heelGroundCm <= rule.heel.exitHeightCm + 1e-9);
        double flatTravel = 0.0, toeTravel = 0.0;
        for (int t = c.toe.first; t <= c.toe.last; ++t) {
            CHECK(p.toeCm[t].y() - set.groundCm <= rule.toe.exitHeightCm + 1e-9);
            const double d = (p.toeCm[t] - p.toeCm[c.toe.first]).norm();
            toeTravel = std::max(toeTravel, d);
            if (c.heel.contains(t)) flatTravel = std::max(flatTravel, d);
        }
        MESSAGE("ball travel while flat " << flatTravel << " cm, over the toe phase " << toeTravel << " cm");
        CHECK(flatTravel < 2.0);
        CHECK(toeTravel < 8.0);
        // A stance the clip does not cut starts at heel strike and ends at toe-off.
        if (c.first > 0 && c.last < clip.frameCount() - 1) {
            CHECK(c.heel.first == c.first);
            CHECK(c.toe.last == c.last);
            CHECK(c.heel.first < c.toe.first);
            CHECK(c.heel.last < c.toe.last);
        }
    }
    // Three stances a foot, and the right heel striking again at the clip's end.
    CHECK(left == 3);
    CHECK(right == 4);
    // A walk has a foot on the ground at every frame (double support between a heel strike and the
    // other foot's toe-off); the toe alone left a third of the frames with no foot held.
    int covered = 0;
    for (int t = 0; t < clip.frameCount(); ++t) covered += set.at(Effector::kLFoot, t) || set.at(Effector::kRFoot, t);
    CHECK(covered == clip.frameCount());
}

TEST_CASE("foot contacts on a real run (16_35): each stance from heel strike to toe-off") {
    const Clip clip = loadClip(test::mocap("asf_amc/16_35.amc"));
    const ContactSet set = detectFootContacts(clip);
    // Frames as 1-based in the comments; 0-based in the checks. The left foot's second stance, the
    // one the span tests edit across: the heel lands at 102, the toe is down 106..123.
    const FootContact* c = set.at(Effector::kLFoot, 110);
    REQUIRE(c != nullptr);
    MESSAGE("left stance " << c->first + 1 << ".." << c->last + 1 << " heel " << c->heel.first + 1 << ".."
                           << c->heel.last + 1 << " toe " << c->toe.first + 1 << ".." << c->toe.last + 1);
    CHECK(c->first == 101);
    CHECK(c->heel.first == 101);
    CHECK(c->toe.first == 105);
    CHECK(c->last == 122);
    CHECK(c->toe.last == 122);
    // The toe's phase alone (the rule before heel tracking) held 14 of these 22 frames.
    CHECK(c->length() == 22);
}

TEST_CASE("foot contacts: a BVH's rest frame sets neither the floor nor the ground") {
    // 49_04 (cgspeed conversion): frame 1 is a T-pose whose feet sit about 9 cm below the capture's.
    const Clip clip = loadClip(test::mocap("bvh/49_04.bvh"));
    REQUIRE(clip.restFrame);
    double restLowest = INFINITY, capturedLowest = INFINITY;
    for (int t = 0; t < clip.frameCount(); ++t)
        for (Effector foot : {Effector::kLFoot, Effector::kRFoot})
            (t == 0 ? restLowest : capturedLowest) =
                std::min(t == 0 ? restLowest : capturedLowest, effectorCm(clip.skeleton, clip.frames[t], foot).y());
    MESSAGE("lowest foot point: rest frame " << restLowest << " cm, captured frames " << capturedLowest << " cm");
    REQUIRE(restLowest < capturedLowest - 5.0);  // the case this test is about
    const ContactSet set = detectFootContacts(clip);
    REQUIRE(set.floorCm.has_value());
    CHECK(*set.floorCm == doctest::Approx(capturedLowest).epsilon(1e-12));
    // The ground levels and contacts are those of the clip whose first frame stands in for the
    // rest frame.
    Clip standIn = clip;
    standIn.frames[0] = standIn.frames[1];
    standIn.restFrame = false;
    const ContactSet ref = detectFootContacts(standIn);
    CHECK(set.groundCm == ref.groundCm);
    CHECK(set.heelGroundCm == ref.heelGroundCm);
    REQUIRE(set.contacts.size() == ref.contacts.size());
    for (std::size_t k = 0; k < ref.contacts.size(); ++k) {
        CHECK(set.contacts[k].first == ref.contacts[k].first);
        CHECK(set.contacts[k].last == ref.contacts[k].last);
    }
}
