// The plain (no prior) IK baseline: reachable targets met, pins held, unreachable targets safe.
#include <cmath>

#include "ik/plain_ik.h"
#include "io/clip_loader.h"
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
