// Unwrapping (docs/maths.md §2.5), constant columns (docs/maths.md §5), the pose matrix and the pose layout.
#include "io/clip_loader.h"
#include "skeleton/clip.h"
#include "skeleton/forward_kinematics.h"
#include "test_support.h"

using namespace mgp;

TEST_CASE("subject 35 drops the clavicle columns {33, 34, 40, 41}: D = 43") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Eigen::MatrixXd y = poseMatrix(clip);
    CHECK(y.rows() == 358);
    CHECK(y.cols() == 47);
    const auto constant = constantColumns(y);
    CHECK(constant == std::vector<int>{33, 34, 40, 41});
    CHECK(47 - static_cast<int>(constant.size()) == 43);
}

TEST_CASE("pose matrix columns follow the docs/maths.md §2.1 order") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Eigen::MatrixXd y = poseMatrix(clip);
    const Skeleton& sk = clip.skeleton;
    // Frame 1 of 35_01: root 4.40047 17.8934 -21.0986 -0.943965 -8.37963 -7.42612, rwrist -1.10026,
    // lfoot -6.36063 8.24507, rtibia 25.6934 (values straight from the file).
    CHECK(y(0, 0) == -0.943965);
    CHECK(y(0, 1) == -8.37963);
    CHECK(y(0, 2) == -7.42612);
    CHECK(y(0, 7) == -6.36063);
    CHECK(y(0, 8) == 8.24507);
    CHECK(y(0, 12) == 25.6934);
    CHECK(y(0, 46) == -1.10026);
    CHECK(clip.frames[0].rootCm.x() == doctest::Approx(4.40047 * 2.54 / 0.45));
    // Round trip through the layout.
    const PoseLayout layout(sk);
    Pose p = clip.frames[3];
    Eigen::VectorXd v = layout.extract(p);
    v[12] += 10.0;
    layout.apply(v.data(), p);
    CHECK(p.anglesDeg[sk.findBone("rtibia")].x() == clip.frames[3].anglesDeg[sk.findBone("rtibia")].x() + 10.0);
}

TEST_CASE("unwrapping removes jumps larger than 180 degrees, for that frame and all later ones (docs/maths.md §2.5)") {
    Eigen::MatrixXd a(6, 2);
    a << 170, 0, 179, -10, -178, 350,  // +3° across the seam; second column jumps by +360 → -10
        -170, 355, 175, -5,            // -15° across the seam
        -180, 0;
    unwrapAngles(a);
    Eigen::MatrixXd want(6, 2);
    want << 170, 0, 179, -10, 182, -10, 190, -5, 175, -5, 180, 0;
    CHECK(a.isApprox(want, 1e-12));
    // Small changes are left alone, and values outside ±180 stay where they are.
    Eigen::MatrixXd b(3, 1);
    b << 400, 410, 420;
    unwrapAngles(b);
    CHECK(b(0, 0) == 400);
    CHECK(b(2, 0) == 420);
}

TEST_CASE("constant-column test uses the population std with tolerance 1e-6 degrees") {
    Eigen::MatrixXd y(4, 3);
    y << 1, 5, 0, 2, 5, 1e-14, 3, 5, -1e-14, 4, 5, 0;
    CHECK(constantColumns(y) == std::vector<int>{1, 2});
    y(0, 1) = 5.00001;  // std ≈ 4.3e-6 > 1e-6
    CHECK(constantColumns(y) == std::vector<int>{2});
}

TEST_CASE("unwrapClip writes the unwrapped angles back without moving any joint") {
    Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    // Force a wrap: shift root ry of the later half by +360°, which FK cannot see.
    const int root = 0;
    for (int t = 200; t < clip.frameCount(); ++t) clip.frames[t].anglesDeg[root].y() += 360.0;
    const Clip before = clip;
    unwrapClip(clip);
    const Eigen::MatrixXd y = poseMatrix(clip);
    const PoseLayout layout(clip.skeleton);
    for (int t = 0; t < clip.frameCount(); t += 17)
        CHECK((layout.extract(clip.frames[t]) - y.row(t).transpose()).norm() == 0.0);
    CHECK(std::abs(clip.frames[250].anglesDeg[root].y() - before.frames[250].anglesDeg[root].y() + 360.0) < 1e-9);
    FkState a, b;
    forwardKinematics(clip.skeleton, clip.frames[250], a);
    forwardKinematics(before.skeleton, before.frames[250], b);
    CHECK((a.jointCm[5] - b.jointCm[5]).norm() < 1e-9);
}

TEST_CASE("appendFrames: a slice keeps the rest frame only if it starts on it") {
    const Clip bvh = loadClip(test::mocap("bvh/49_04.bvh"));
    REQUIRE(bvh.restFrame);
    REQUIRE(bvh.frameCount() > 20);
    Clip fromStart, later;
    appendFrames(fromStart, bvh, 0, 10);
    appendFrames(later, bvh, 5, 10);
    CHECK(fromStart.restFrame);
    CHECK(fromStart.firstMotionFrame() == 1);
    CHECK_FALSE(later.restFrame);
    CHECK(later.firstMotionFrame() == 0);
    CHECK(later.frames[0].anglesDeg == bvh.frames[5].anglesDeg);
    // Appending to a clip leaves its own frame 0, and so its flag, as it was.
    appendFrames(later, bvh, 0, 3);
    CHECK_FALSE(later.restFrame);
    appendFrames(fromStart, bvh, 12, 3);
    CHECK(fromStart.restFrame);
    CHECK(fromStart.frameCount() == 13);
}
