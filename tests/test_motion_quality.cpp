// The span report (motion/motion_quality.h) on tiny hand-made motions with known answers.
#include "motion/motion_quality.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/synthetic_clip.h"
#include "test_support.h"

using namespace mgp;

namespace {
// A still clip: every frame the synthetic walk's frame 0.
Clip stillClip(int frames) {
    Clip c = makeSyntheticWalk(frames);
    for (Pose& p : c.frames) p = c.frames[0];
    return c;
}
void setDof(const Clip& c, Pose& p, int dof, double value) {
    const PoseLayout layout(c.skeleton);
    Eigen::VectorXd y = layout.extract(p);
    y[dof] = value;
    layout.apply(y.data(), p);
}
}  // namespace

TEST_CASE("second differences: zero for a still or uniformly turning joint, 2a for a·t², wrapped at ±180°") {
    Clip c = stillClip(20);
    const int dof = 12;  // rtibia rx
    SecondDifferenceStats s = secondDifferences(c.frames, c.skeleton, 1, 18);
    CHECK(s.perFrameDeg.size() == 18);
    CHECK(s.maxDeg == doctest::Approx(0.0));
    // Constant velocity through ±180°: still zero once wrapped.
    for (int t = 0; t < 20; ++t) setDof(c, c.frames[t], 30, 170.0 + 3.0 * t - (170.0 + 3.0 * t > 180.0 ? 360.0 : 0.0));
    s = secondDifferences(c.frames, c.skeleton, 1, 18);
    CHECK(s.maxDeg == doctest::Approx(0.0).epsilon(1e-9));
    // a·t² has second difference 2a everywhere.
    for (int t = 0; t < 20; ++t) setDof(c, c.frames[t], dof, 0.5 * t * t);
    s = secondDifferences(c.frames, c.skeleton, 1, 18);
    CHECK(s.p95Deg == doctest::Approx(1.0));
    CHECK(s.maxDeg == doctest::Approx(1.0));
    // One frame 10° off: second differences 10, 20, 10 at t−1, t, t+1 (on top of 1°).
    Clip d = stillClip(20);
    setDof(d, d.frames[10], dof, PoseLayout(d.skeleton).extract(d.frames[10])[dof] + 10.0);
    s = secondDifferences(d.frames, d.skeleton, 1, 18);
    CHECK(s.maxDeg == doctest::Approx(20.0));
    CHECK(s.maxFrame == 10);
    // 18 values {0×15, 10, 10, 20}: the nearest-rank p95 is the ceil(0.95·18) = 18th smallest, 20.
    CHECK(s.perFrameDeg.size() == 18);
    CHECK(s.p95Deg == doctest::Approx(20.0));
    // The span's counted centres stop at the clip's ends.
    CHECK(secondDifferences(d.frames, d.skeleton, 0, 19).perFrameDeg.size() == 18);
}

TEST_CASE("nearest-rank percentile") {
    CHECK(percentile({}, 0.95) == 0.0);
    std::vector<double> v;
    for (int i = 1; i <= 100; ++i) v.push_back(i);
    CHECK(percentile(v, 0.95) == 95.0);
    CHECK(percentile(v, 1.0) == 100.0);
    CHECK(percentile(v, 0.0) == 1.0);
    CHECK(percentile({3.0, 1.0, 2.0}, 0.5) == 2.0);
}

TEST_CASE("horizontal travel is the widest XZ spread, heights ignored") {
    std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {3, 50, 0}, {3, 0, 4}, {100, 0, 100}};
    CHECK(horizontalTravelCm(p, 0, 2) == doctest::Approx(5.0));  // (0,0) to (3,4)
    CHECK(horizontalTravelCm(p, 0, 1) == doctest::Approx(3.0));
    CHECK(horizontalTravelCm(p, 2, 2) == 0.0);
    CHECK(horizontalTravelCm(p, -5, 1) == doctest::Approx(3.0));  // clipped to the trajectory
}

TEST_CASE("span report: pose change, key and path error, contact travel of a known edit") {
    const Clip c = stillClip(30);
    std::vector<Pose> edited = c.frames;
    // Frames 11..19 turn the right knee by 30°·sin; frame 15 (a key) by 30°.
    for (int t = 11; t <= 19; ++t)
        setDof(c, edited[t], 12,
               PoseLayout(c.skeleton).extract(c.frames[t])[12] + 30.0 * std::sin(3.14159265358979 * (t - 10) / 10.0));
    std::vector<Eigen::Vector3d> path;
    for (int t = 10; t <= 20; ++t) path.push_back(effectorCm(c.skeleton, c.frames[t], Effector::kRFoot));
    // The left foot is "held" 12..18 and does not move; the right foot is reported too.
    const SpanQuality q = measureSpan(c, edited, 10, 20, Effector::kRFoot, path, {10, 15, 20},
                                      {{Effector::kLFoot, 12, 18}, {Effector::kRFoot, 14, 16}});
    CHECK(q.worstPoseChangeDeg == doctest::Approx(30.0).epsilon(1e-6));
    CHECK(q.worstPoseChangeFrame == 15);
    const double keyErr = (effectorCm(c.skeleton, edited[15], Effector::kRFoot) - path[5]).norm();
    CHECK(keyErr > 1.0);
    CHECK(q.worstKeyErrorCm == doctest::Approx(keyErr));
    CHECK(q.worstPathErrorCm >= q.worstKeyErrorCm);
    REQUIRE(q.contacts.size() == 2);
    CHECK(q.contacts[0].editedCm == doctest::Approx(0.0));
    CHECK(q.contacts[0].capturedCm == doctest::Approx(0.0));
    CHECK(q.contacts[1].editedCm > 1.0);  // the bent knee swings the right foot
    CHECK(q.captured.maxDeg == doctest::Approx(0.0));
    CHECK(q.edited.maxDeg > 0.0);
}
