// Hermite interpolation conditions (docs/maths.md §12.1) on the paper's key pattern (89, 103, 117, 131).
#include "io/clip_loader.h"
#include "motion/hermite_path.h"
#include "skeleton/forward_kinematics.h"
#include "test_support.h"

using namespace mgp;

TEST_CASE("Hermite path: keys, tangents, C1 joins and captured end velocities") {
    const Clip clip = loadClip(test::mocap("asf_amc/10_02.amc"));
    std::vector<Eigen::Vector3d> foot;
    FkState fk;
    for (const Pose& p : clip.frames) {
        forwardKinematics(clip.skeleton, p, fk);
        foot.push_back(effectorCm(clip.skeleton, fk, Effector::kRFoot));
    }
    // Clip frames are counted from 1 in the UI; index = frame - 1.
    const int f[4] = {89 - 1, 103 - 1, 117 - 1, 131 - 1};
    const Eigen::Vector3d raise(0, 20, 0);
    std::vector<HermiteKey> keys = {{double(f[0]), foot[f[0]]},
                                    {double(f[1]), foot[f[1]] + raise},
                                    {double(f[2]), foot[f[2]] + raise},
                                    {double(f[3]), foot[f[3]]}};
    const Eigen::Vector3d m0 = capturedVelocity(foot, f[0]), m3 = capturedVelocity(foot, f[3]);
    CHECK((m0 - (foot[f[0] + 1] - foot[f[0] - 1]) / 2).norm() < 1e-12);
    const HermitePath path(keys, m0, m3);
    for (std::size_t i = 0; i < keys.size(); ++i)
        CHECK((path.position(keys[i].frame) - keys[i].positionCm).norm() < 1e-9);
    // Interior tangents are Catmull–Rom.
    const Eigen::Vector3d m1 = (keys[2].positionCm - keys[0].positionCm) / 28.0;
    const Eigen::Vector3d m2 = (keys[3].positionCm - keys[1].positionCm) / 28.0;
    CHECK((path.tangents()[1] - m1).norm() < 1e-12);
    CHECK((path.tangents()[2] - m2).norm() < 1e-12);
    // c'(t_i) = m_i, the same from both sides (C1 at 103 and 117), and the captured velocity at the ends.
    const double e = 1e-7;
    CHECK((path.velocity(f[0]) - m0).norm() < 1e-9);
    CHECK((path.velocity(f[3]) - m3).norm() < 1e-9);
    for (int i : {1, 2}) {
        CHECK((path.velocity(f[i] - e) - path.velocity(f[i] + e)).norm() < 1e-5);
        CHECK((path.velocity(f[i]) - path.tangents()[i]).norm() < 1e-9);
        // Second-order one-sided differences inside each segment agree with the tangent. (A central
        // difference across the knot would be only first order: c'' jumps there, the path is C1.)
        const double h = 1e-4;
        const Eigen::Vector3d right =
            (-3 * path.position(f[i]) + 4 * path.position(f[i] + h) - path.position(f[i] + 2 * h)) / (2 * h);
        const Eigen::Vector3d left =
            (3 * path.position(f[i]) - 4 * path.position(f[i] - h) + path.position(f[i] - 2 * h)) / (2 * h);
        CHECK((right - path.tangents()[i]).norm() < 1e-6);
        CHECK((left - path.tangents()[i]).norm() < 1e-6);
    }
}

TEST_CASE("Hermite path rejects fewer than 2 keys and unordered keys") {
    CHECK_THROWS_AS(HermitePath({{1.0, Eigen::Vector3d::Zero()}}, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()),
                    std::invalid_argument);
    CHECK_THROWS_AS(HermitePath({{2.0, Eigen::Vector3d::Zero()}, {2.0, Eigen::Vector3d::Ones()}},
                                Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()),
                    std::invalid_argument);
}

TEST_CASE("a straight line with matching tangents is reproduced exactly") {
    const Eigen::Vector3d v(1, 2, 3);
    const HermitePath path({{0, Eigen::Vector3d::Zero()}, {10, 10 * v}, {20, 20 * v}}, v, v);
    for (double t = 0; t <= 20; t += 0.5) CHECK((path.position(t) - t * v).norm() < 1e-12);
}
