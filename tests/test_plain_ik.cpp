// The plain (no prior) IK baseline: reachable targets met, pins held, unreachable targets safe.
#include <cmath>

#include "ik/locality.h"
#include "ik/plain_ik.h"
#include "io/clip_loader.h"
#include "skeleton/pose_layout.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("plain IK raises the right foot 20 cm with the left foot pinned") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Pose& start = clip.frames[100];
    PlainIkJob job;
    job.skeleton = &clip.skeleton;
    job.start = start;
    const Eigen::Vector3d target = effectorCm(clip.skeleton, start, Effector::kRFoot) + Eigen::Vector3d(0, 20, 0);
    const Eigen::Vector3d pinAt = effectorCm(clip.skeleton, start, Effector::kLFoot);
    job.constraints = {{Effector::kRFoot, target, false}, {Effector::kLFoot, pinAt, true}};
    CHECK(job.validate().empty());
    job.solve();
    MESSAGE("plain IK: " << job.iterations << " iterations, " << job.diagnostic << ", residuals "
                         << job.results[0].residualCm << " / " << job.results[1].residualCm << " cm");
    CHECK(job.reached);
    CHECK(job.results[0].residualCm < 0.5);
    CHECK(job.results[1].residualCm < 0.5);
    CHECK((effectorCm(clip.skeleton, job.pose, Effector::kRFoot) - target).norm() < 0.5);
    CHECK(job.pose.rootCm == start.rootCm);  // root translation fixed
}

TEST_CASE("plain IK: an unreachable target gives the best effort, reached = false, finite pose") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    PlainIkJob job;
    job.skeleton = &clip.skeleton;
    job.start = clip.frames[0];
    job.constraints = {{Effector::kRHand,
                        effectorCm(clip.skeleton, clip.frames[0], Effector::kRHand) + Eigen::Vector3d(0, 500, 0),
                        false}};
    job.solve();
    CHECK_FALSE(job.reached);
    CHECK(job.results[0].residualCm > 100.0);
    CHECK(std::isfinite(job.results[0].residualCm));
    for (const auto& a : job.pose.anglesDeg) CHECK(a.allFinite());
}

TEST_CASE("plain IK refuses NaN targets and duplicate effectors without touching the pose") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    PlainIkJob job;
    job.skeleton = &clip.skeleton;
    job.start = clip.frames[0];
    job.constraints = {{Effector::kHead, Eigen::Vector3d(0, NAN, 0), false}};
    job.solve();
    CHECK(job.diagnostic == "expected a finite target for head, found NaN or Inf");
    CHECK_FALSE(job.reached);
    job.constraints = {{Effector::kHead, Eigen::Vector3d::Zero(), false},
                       {Effector::kHead, Eigen::Vector3d::Zero(), true}};
    job.solve();
    CHECK(job.diagnostic == "expected each effector once, found head twice");
}

TEST_CASE("plain IK with the root translation free: every point moves with it one to one, and it reaches farther") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Skeleton& sk = clip.skeleton;
    const Pose& start = clip.frames[100];
    // The root translation's Jacobian columns are the identity: central differences agree.
    for (int k = 0; k < 3; ++k)
        for (Effector e : {Effector::kLHand, Effector::kRFoot, Effector::kHead}) {
            Pose plus = start, minus = start;
            plus.rootCm[k] += 0.5;
            minus.rootCm[k] -= 0.5;
            const Eigen::Vector3d d = effectorCm(sk, plus, e) - effectorCm(sk, minus, e);
            CHECK((d - Eigen::Vector3d::Unit(k)).norm() < 1e-9);
        }
    // A hand 150 cm higher is out of the arm's reach with the root fixed, in reach with it free.
    PlainIkJob job;
    job.skeleton = &sk;
    job.start = start;
    const Eigen::Vector3d target = effectorCm(sk, start, Effector::kRHand) + Eigen::Vector3d(0, 150, 0);
    job.constraints = {{Effector::kRHand, target, false}};
    job.solve();
    CHECK_FALSE(job.reached);
    CHECK(job.pose.rootCm == start.rootCm);
    job.freeRootTranslation = true;
    job.solve();
    MESSAGE("root free: " << job.iterations << " iterations, " << job.diagnostic << ", residual "
                          << job.results[0].residualCm << " cm, root moved "
                          << (job.pose.rootCm - start.rootCm).transpose());
    CHECK(job.reached);
    CHECK(job.results[0].residualCm < 1e-3);
    CHECK(job.pose.rootCm.y() - start.rootCm.y() > 50.0);
}

namespace {
// 35_01 frame 145, both feet planted and held where they stand; the settle tests bend its right knee.
struct PlantedFeet {
    Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Skeleton& sk = clip.skeleton;
    const Pose& start = clip.frames[145];
    const int knee = sk.findBone("rtibia");
    std::vector<IkConstraint> holds;
    PlantedFeet() {
        for (Effector foot : {Effector::kLFoot, Effector::kRFoot})
            holds.push_back({foot, effectorCm(sk, start, foot), true});
    }
};
}  // namespace

TEST_CASE_FIXTURE(PlantedFeet,
                  "settle on holds: a knee bent over its planted foot keeps the feet by the hips and the legs alone") {
    CHECK_FALSE(settleOnHolds(sk, start, knee, holds).has_value());  // nothing to settle
    CHECK(worstHoldMissCm(sk, start, holds) == 0.0);
    Pose bent = start;
    bent.anglesDeg[knee].x() += 40.0;
    const double miss = worstHoldMissCm(sk, bent, holds);
    REQUIRE(miss > 5.0);  // the bent knee lifts its foot
    const std::optional<Pose> settled = settleOnHolds(sk, bent, knee, holds);
    REQUIRE(settled.has_value());
    MESSAGE("bent knee: the foot " << miss << " cm off, settled to " << worstHoldMissCm(sk, *settled, holds)
                                   << " cm; the root moved " << (settled->rootCm - start.rootCm).transpose());
    CHECK(worstHoldMissCm(sk, *settled, holds) <= kSettledHoldCm);
    CHECK(settled->anglesDeg[knee] == bent.anglesDeg[knee]);  // the rotation as asked
    CHECK(settled->anglesDeg[0] == start.anglesDeg[0]);       // the root rotation kept
    CHECK(settled->rootCm.y() < start.rootCm.y() - 1.0);      // the hips came down
    const int lf = sk.effectorSite(Effector::kLFoot).joint, rf = sk.effectorSite(Effector::kRFoot).joint;
    for (int j = 1; j < sk.jointCount(); ++j)
        if (!sk.isAncestorOrSelf(j, lf) && !sk.isAncestorOrSelf(j, rf))
            CHECK(settled->anglesDeg[j] == start.anglesDeg[j]);
    // Held by the ball alone the foot may pivot on it; with the sole's reference its ankle stays too.
    FkState s0, s1, s2;
    forwardKinematics(sk, start, s0);
    forwardKinematics(sk, *settled, s1);
    const double pivot = (s1.jointCm[rf] - s0.jointCm[rf]).norm();
    const std::optional<Pose> flat = settleOnHolds(sk, bent, knee, holds, &start);
    REQUIRE(flat.has_value());
    forwardKinematics(sk, *flat, s2);
    MESSAGE("the right ankle moved " << pivot << " cm on the ball alone, " << (s2.jointCm[rf] - s0.jointCm[rf]).norm()
                                     << " cm with the sole held; the hips " << flat->rootCm.y() - start.rootCm.y()
                                     << " cm");
    CHECK(worstHoldMissCm(sk, *flat, holds) <= kSettledHoldCm);
    for (int foot : {lf, rf}) CHECK((s2.jointCm[foot] - s0.jointCm[foot]).norm() <= kSettledHoldCm);
    CHECK(pivot > 0.5);  // the reference is what keeps it
    // Soles kept for the left foot only (the planted one; the right as if pinned in the air): the
    // right ankle pivots on its ball as with no reference, the left stays.
    const std::vector<Effector> onlyLeft{Effector::kLFoot};
    const std::optional<Pose> leftSole = settleOnHolds(sk, bent, knee, holds, &start, 500, true, &onlyLeft);
    REQUIRE(leftSole.has_value());
    FkState s3;
    forwardKinematics(sk, *leftSole, s3);
    CHECK(worstHoldMissCm(sk, *leftSole, holds) <= kSettledHoldCm);
    CHECK((s3.jointCm[lf] - s0.jointCm[lf]).norm() <= kSettledHoldCm);
    CHECK((s3.jointCm[rf] - s0.jointCm[rf]).norm() > 0.5);
    // A joint hold of a joint the skeleton lacks is refused.
    PlainIkJob bad;
    bad.skeleton = &sk;
    bad.start = start;
    bad.jointHolds = {{sk.jointCount(), Eigen::Vector3d::Zero()}};
    CHECK(bad.validate().find("expected a held joint") != std::string::npos);
}

TEST_CASE_FIXTURE(PlantedFeet, "settle on holds: a sole the legs cannot reach never pulls a held ball off its place") {
    Pose bent = start;
    bent.anglesDeg[knee].x() += 40.0;
    REQUIRE(worstHoldMissCm(sk, bent, holds) > 5.0);
    // A sole reference whose ankles are 30 cm above where they stood: no foot reaches that with its
    // ball on the floor, so holding the soles would trade the balls for them.
    Pose lifted = start;
    lifted.rootCm.y() += 30.0;
    for (bool moveRoot : {true, false}) {
        CAPTURE(moveRoot);
        const std::optional<Pose> settled = settleOnHolds(sk, bent, knee, holds, &lifted, 500, moveRoot);
        REQUIRE(settled.has_value());
        MESSAGE("holds " << worstHoldMissCm(sk, *settled, holds) << " cm off after the settle");
        // Each hold ends no farther than it was, and the hips reach both balls back exactly; the
        // legs alone, the bent knee kept, bring the right one closer.
        for (const IkConstraint& h : holds)
            CHECK((effectorCm(sk, *settled, h.effector) - h.targetCm).norm() <=
                  std::max(kSettledHoldCm, (effectorCm(sk, bent, h.effector) - h.targetCm).norm()));
        if (moveRoot) CHECK(worstHoldMissCm(sk, *settled, holds) <= kSettledHoldCm);
        CHECK(worstHoldMissCm(sk, *settled, holds) < 0.5 * worstHoldMissCm(sk, bent, holds));
        CHECK(settled->anglesDeg[knee] == bent.anglesDeg[knee]);
    }
    // Holds already met and an unreachable sole: nothing is settled (the holds would only get worse).
    CHECK_FALSE(settleOnHolds(sk, start, -1, holds, &lifted).has_value());
}

TEST_CASE("plain IK with a DOF metric: the locality weights keep a hand raise in the arm") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Skeleton& sk = clip.skeleton;
    const Pose& start = clip.frames[100];
    PlainIkJob job;
    job.skeleton = &sk;
    job.start = start;
    const Eigen::Vector3d target = effectorCm(sk, start, Effector::kRHand) + Eigen::Vector3d(0, 20, 0);
    job.constraints = {{Effector::kRHand, target, false},
                       {Effector::kLFoot, effectorCm(sk, start, Effector::kLFoot), true},
                       {Effector::kRFoot, effectorCm(sk, start, Effector::kRFoot), true}};
    PlainIkJob local = job;
    job.solve();
    local.dofCost = localityDofCost(sk, {Effector::kRHand}, 1000.0);
    REQUIRE(local.validate().empty());
    local.solve();
    REQUIRE(job.reached);
    REQUIRE(local.reached);
    const auto moved = [&](const Pose& p, Effector e) {
        return (effectorCm(sk, p, e) - effectorCm(sk, start, e)).norm();
    };
    MESSAGE("head moved " << moved(job.pose, Effector::kHead) << " cm with the unit metric, "
                          << moved(local.pose, Effector::kHead) << " cm with the locality metric");
    CHECK(moved(local.pose, Effector::kHead) < 0.25 * moved(job.pose, Effector::kHead));
    CHECK(moved(local.pose, Effector::kLHand) < 0.25 * moved(job.pose, Effector::kLHand));
    // Every DOF of weight 1 (the spine, the legs, the other arm) changes less than with the unit metric, in all.
    const PoseLayout layout(sk);
    const Eigen::VectorXd y0 = layout.extract(start), yu = layout.extract(job.pose), yl = layout.extract(local.pose);
    const std::vector<double> w = localityWeights(sk, {Effector::kRHand});
    double bodyUnit = 0.0, bodyLocal = 0.0;
    for (int k = 0; k < layout.size(); ++k)
        if (w[static_cast<std::size_t>(k)] == 1.0) {
            bodyUnit += (yu[k] - y0[k]) * (yu[k] - y0[k]);
            bodyLocal += (yl[k] - y0[k]) * (yl[k] - y0[k]);
        }
    CHECK(bodyLocal < 0.1 * bodyUnit);

    PlainIkJob bad = job;
    bad.dofCost.assign(3, 1.0);
    CHECK(bad.validate() == "expected " + std::to_string(layout.size()) + " DOF costs, found 3");
    bad.dofCost.assign(static_cast<std::size_t>(layout.size()), 1.0);
    bad.dofCost[5] = 0.0;
    CHECK(bad.validate().rfind("expected positive finite DOF costs, found 0", 0) == 0);
}
