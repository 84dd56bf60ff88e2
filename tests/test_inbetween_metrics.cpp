// The in-betweening measures (eval/inbetween_metrics.h) against values computed by hand, and the
// window frame they are taken in.
#include <doctest/doctest.h>

#include <cmath>

#include "eval/inbetween_metrics.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/rotation.h"
#include "skeleton/synthetic_clip.h"

using namespace mgp;

TEST_CASE("NPSS of one window: the power spectra's cumulative distance, weighted by the truth's power") {
    // Truth (1, 0): DFT (1, 1), power (1, 1), normalised (½, ½), cumulative (½, 1), total 2.
    // Prediction (1, 1): DFT (2, 0), power (4, 0), normalised (1, 0), cumulative (1, 1).
    // EMD = |1 − ½| + |1 − 1| = ½, weighted by 2. A channel whose truth is all zero has no power
    // and no weight, whatever the prediction does.
    Eigen::MatrixXd truth(2, 2), prediction(2, 2);
    truth << 1.0, 0.0, 0.0, 0.0;
    prediction << 1.0, 3.0, 1.0, -1.0;
    const NpssTerms n = npssTerms(truth, prediction);
    CHECK(n.weight == doctest::Approx(2.0).epsilon(1e-12));
    CHECK(n.weightedEmd == doctest::Approx(1.0).epsilon(1e-12));
    const NpssTerms same = npssTerms(truth, truth);
    CHECK(same.weightedEmd == doctest::Approx(0.0));
    CHECK_THROWS_AS(npssTerms(truth, Eigen::MatrixXd::Zero(3, 2)), std::invalid_argument);
}

TEST_CASE("L2P, L2Q and NPSS pooled over windows, by hand") {
    // One joint, two transition frames. Positions: truth (0,0,0), (1,2,2); prediction zero; σ = (1,2,1):
    // per-frame ‖(p − p̂)/σ‖ = 0 and √(1 + 1 + 4) = √6, so L2P = √6 / 2.
    // Quaternions: equal on frame 1, (1,0,0,0) against (0,1,0,0) on frame 2: L2Q = √2 / 2.
    WindowGlobals truth, prediction;
    truth.positions.resize(2, 3);
    truth.positions << 0, 0, 0, 1, 2, 2;
    prediction.positions = Eigen::MatrixXd::Zero(2, 3);
    truth.quaternions.resize(2, 4);
    truth.quaternions << 1, 0, 0, 0, 1, 0, 0, 0;
    prediction.quaternions.resize(2, 4);
    prediction.quaternions << 1, 0, 0, 0, 0, 1, 0, 0;
    const Eigen::Vector3d sd(1.0, 2.0, 1.0);
    InbetweenScore score;
    score.add(truth, prediction, sd);
    CHECK(score.frames() == 2);
    CHECK(score.l2p() == doctest::Approx(std::sqrt(6.0) / 2.0).epsilon(1e-12));
    CHECK(score.l2q() == doctest::Approx(std::sqrt(2.0) / 2.0).epsilon(1e-12));
    // NPSS: the w channel: truth (1, 1) has power (4, 0), prediction (1, 0) has (1, 1): EMD ½ with
    // weight 4; the x channel: truth zero, no weight. So NPSS = ½.
    CHECK(score.npss() == doctest::Approx(0.5).epsilon(1e-12));
    // A second window, predicted exactly, adds two frames of zero error: the means halve.
    score.add(truth, truth, sd);
    CHECK(score.frames() == 4);
    CHECK(score.l2p() == doctest::Approx(std::sqrt(6.0) / 4.0).epsilon(1e-12));
    CHECK(score.l2q() == doctest::Approx(std::sqrt(2.0) / 4.0).epsilon(1e-12));
    CHECK(score.npss() == doctest::Approx(2.0 / 8.0).epsilon(1e-12));  // (4·½ + 4·0) / (4 + 4)
    CHECK_THROWS_AS(score.add(truth, prediction, Eigen::Vector2d(1.0, 1.0)), std::invalid_argument);
}

TEST_CASE("the position spread is the population standard deviation per coordinate, 1 where nothing varies") {
    WindowGlobals a, b;
    a.positions.resize(1, 3);
    a.positions << 1.0, 5.0, 0.0;
    b.positions.resize(2, 3);
    b.positions << 3.0, 5.0, 0.0, 2.0, 5.0, 3.0;
    // x: 1, 3, 2 → mean 2, variance 2/3; y constant → 1; z: 0, 0, 3 → mean 1, variance 2.
    const Eigen::VectorXd sd = positionSpread({a, b});
    CHECK(sd[0] == doctest::Approx(std::sqrt(2.0 / 3.0)).epsilon(1e-12));
    CHECK(sd[1] == 1.0);
    CHECK(sd[2] == doctest::Approx(std::sqrt(2.0)).epsilon(1e-12));
    CHECK_THROWS_AS(positionSpread({}), std::invalid_argument);
}

namespace {
// The whole window turned about the vertical by `yawDeg` and moved by `shift` on the ground.
std::vector<Pose> movedWindow(const Skeleton& sk, std::vector<Pose> frames, double yawDeg,
                              const Eigen::Vector3d& shift) {
    const Joint& root = sk.joints[0];
    const Eigen::Matrix3d ry = axisRotation(kAxisY, yawDeg * kDegToRad);
    for (Pose& p : frames) {
        p.rootCm = ry * p.rootCm + shift;
        p.anglesDeg[0] = eulerFromMatrix(
            root.axis.transpose() * ry * root.axis * eulerMatrix(p.anglesDeg[0], root.order), root.order);
    }
    return frames;
}
}  // namespace

TEST_CASE("a window is measured in its first key's frame: turning and moving it on the ground changes nothing") {
    const Clip clip = makeSyntheticWalk(60);
    const std::vector<Pose> window(clip.frames.begin() + 10, clip.frames.begin() + 41);
    const WindowGlobals here = windowGlobals(clip.skeleton, window);
    REQUIRE(here.positions.rows() == 29);
    REQUIRE(here.positions.cols() == 3 * clip.skeleton.jointCount());
    const WindowGlobals there =
        windowGlobals(clip.skeleton, movedWindow(clip.skeleton, window, 73.0, Eigen::Vector3d(120.0, 0.0, -40.0)));
    CHECK((here.positions - there.positions).cwiseAbs().maxCoeff() < 1e-9);
    CHECK((here.quaternions - there.quaternions).cwiseAbs().maxCoeff() < 1e-9);
    // Each joint's quaternions stay on one side from frame to frame (no sign flips).
    for (Eigen::Index t = 1; t < here.quaternions.rows(); ++t)
        for (int j = 0; j < clip.skeleton.jointCount(); ++j)
            CHECK(here.quaternions.row(t).segment<4>(4 * j).dot(here.quaternions.row(t - 1).segment<4>(4 * j)) > 0.0);
    // The first key's root sits above the origin, facing +z.
    FkState fk;
    forwardKinematics(clip.skeleton, window.front(), fk);
    const Eigen::Matrix3d h = headingRemoval(fk);
    const Eigen::Vector3d forward = h * fk.global[0].col(2);
    CHECK(std::abs(forward.x()) < 1e-12);
    CHECK(forward.z() > 0.0);
    CHECK_THROWS_AS(windowGlobals(clip.skeleton, {window[0], window[1]}), std::invalid_argument);
}
