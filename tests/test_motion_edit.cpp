// Motion regeneration (docs/maths.md §12): keys met, untouched frames bit-identical, deterministic over threads,
// no change from an edit that moves no key.
#include <algorithm>

#include "motion/motion_edit.h"
#include "motion/motion_quality.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

namespace {
MotionEditJob paperEdit(PathMode mode, int threads) {
    MotionEditJob job;
    job.version = test::walkModel35();
    job.effector = Effector::kRFoot;
    job.keyFrames = {89 - 1, 103 - 1, 117 - 1, 131 - 1};
    job.keyOffsetsCm = {Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 20, 0), Eigen::Vector3d(0, 20, 0),
                        Eigen::Vector3d::Zero()};
    job.mode = mode;
    job.threads = threads;
    return job;
}
}  // namespace

TEST_CASE("regenerating 89..131 with the middle keys raised 20 cm") {
    MotionEditJob job = paperEdit(PathMode::kDirect, 2);
    CHECK(job.validate().empty());
    job.run();
    const Clip& clip = job.version->model->clip;
    REQUIRE(job.solvedFrames.size() == 41);  // (89, 131) exclusive
    CHECK(job.solvedFrames.front() == 89);
    MESSAGE("max residual over the 41 solved frames: " << job.maxResidualCm << " cm");
    CHECK(job.maxResidualCm < 0.5);
    // FK at the moved keys meets the raised targets.
    const auto captured = job.capturedTrajectory();
    FkState fk;
    for (int key : {103 - 1, 117 - 1}) {
        forwardKinematics(clip.skeleton, job.frames[key], fk);
        CHECK((effectorCm(clip.skeleton, fk, Effector::kRFoot) - (captured[key] + Eigen::Vector3d(0, 20, 0))).norm() <
              0.5);
    }
    // Untouched frames (outside the open span, and the two end keys) are bit-identical.
    for (int t = 0; t < clip.frameCount(); ++t) {
        if (t > 88 && t < 130) continue;
        CAPTURE(t);
        CHECK(job.frames[t].rootCm == clip.frames[t].rootCm);
        for (std::size_t j = 0; j < clip.frames[t].anglesDeg.size(); ++j)
            CHECK(job.frames[t].anglesDeg[j] == clip.frames[t].anglesDeg[j]);
    }
}

TEST_CASE("regeneration gives identical bits with 1 and 2 threads, displacement mode also meets its path") {
    MotionEditJob a = paperEdit(PathMode::kDisplacement, 1), b = paperEdit(PathMode::kDisplacement, 2);
    a.solver = b.solver = EditSolver::kPerFrame;  // threads only matter to the per-frame solver
    a.run();
    b.run();
    CHECK(a.maxResidualCm < 0.5);
    for (std::size_t i = 0; i < a.solvedFrames.size(); ++i)
        for (std::size_t j = 0; j < a.frames[0].anglesDeg.size(); ++j)
            CHECK(a.frames[a.solvedFrames[i]].anglesDeg[j] == b.frames[b.solvedFrames[i]].anglesDeg[j]);
    // Displacement mode: zero offset at the end keys means the path starts on the captured motion.
    CHECK((a.pathCm.front() - a.capturedTrajectory()[89]).norm() < 2.0);
}

TEST_CASE("no edit, no change: a path with every key at its captured position regenerates the capture in either mode") {
    // The default mode is displacement; direct (the paper's) takes the captured path itself when no
    // key moved: its Hermite curve through the unmoved keys is not the captured path between them
    // (on the kick fixture it changed a joint by 33°).
    CHECK(MotionEditJob{}.mode == PathMode::kDisplacement);
    for (const gp::ModelVersionPtr& version : {test::walkModel35(), test::kickModel1003()}) {
        for (PathMode mode : {PathMode::kDisplacement, PathMode::kDirect}) {
            MotionEditJob job;
            job.version = version;
            job.effector = Effector::kRHand;
            job.keyFrames = {40, 54, 68, 82};
            job.keyOffsetsCm.assign(4, Eigen::Vector3d::Zero());
            job.mode = mode;
            job.run();
            const Clip& clip = version->model->clip;
            double worst = 0.0;
            for (int t : job.solvedFrames)
                worst = std::max(worst, largestAngleChangeDeg(job.frames[t], clip.frames[t], clip.skeleton));
            MESSAGE(clip.name << std::string(mode == PathMode::kDirect ? " direct" : " displacement")
                              << ": largest change " << worst << "°");
            CHECK(worst <= 0.1);
        }
    }
}

TEST_CASE("bad edit jobs say what is wrong") {
    MotionEditJob job = paperEdit(PathMode::kDirect, 1);
    job.keyFrames = {10, 5};
    job.keyOffsetsCm.resize(2);
    CHECK(job.validate() == "expected strictly increasing key frames");
    job.keyFrames = {10, 5000};
    CHECK(job.validate() == "expected key frames in 1..358, found 5001");
    CHECK_THROWS_AS(job.run(), std::invalid_argument);
}

TEST_CASE("a path that dips below the floor is lifted onto it smoothly, and only near the dip") {
    // A smooth path dipping 2 cm below the floor at y = 0 around frame 20 (frames 17-23 below),
    // curving by 0.4 cm per frame² (its second difference).
    std::vector<Eigen::Vector3d> path;
    for (int t = 0; t <= 40; ++t) path.emplace_back(t, 0.2 * (t - 20) * (t - 20) - 2.0, 0.0);
    const std::vector<Eigen::Vector3d> asked = path;
    const int lift = 10;  // frames: kFloorLiftSeconds at 120 fps
    liftPathAboveFloor(path, 0.0, lift);
    for (int t = 0; t <= 40; ++t) {
        CAPTURE(t);
        CHECK(path[t].y() >= -1e-12);        // on the floor or above
        CHECK(path[t].x() == asked[t].x());  // only heights change
        if (std::abs(t - 20) > 3 + lift) CHECK(path[t].y() == asked[t].y());
        if (asked[t].y() < 0.0) CHECK(path[t].y() < 2.0);  // lifted onto it, not above the dip's depth
    }
    CHECK(path[20].y() == doctest::Approx(0.0));  // the deepest frame lands on the floor exactly
    // No corner: a hard clamp max(y, 0) turns the path by about 1.2 cm per frame² where it meets the
    // floor; the lift keeps the path's own curvature within 0.1 cm per frame² of what was asked.
    auto largestSecondDifference = [](const std::vector<double>& y) {
        double worst = 0.0;
        for (std::size_t t = 1; t + 1 < y.size(); ++t)
            worst = std::max(worst, std::abs(y[t - 1] - 2 * y[t] + y[t + 1]));
        return worst;
    };
    std::vector<double> lifted, clamped;
    for (std::size_t t = 0; t < path.size(); ++t) {
        lifted.push_back(path[t].y());
        clamped.push_back(std::max(asked[t].y(), 0.0));
    }
    const double smooth = largestSecondDifference(lifted), hard = largestSecondDifference(clamped);
    MESSAGE("largest second difference: asked 0.4, lifted " << smooth << ", clamped " << hard << " cm");
    CHECK(smooth <= 0.4 + 0.1);
    CHECK(hard > 1.0);
    // A path above the floor is left alone.
    std::vector<Eigen::Vector3d> high = asked;
    for (auto& p : high) p.y() += 5.0;
    const std::vector<Eigen::Vector3d> highAsked = high;
    liftPathAboveFloor(high, 0.0, lift);
    CHECK(high == highAsked);
    // A key on or above the floor near the dip keeps its place: the bumps end before it.
    std::vector<Eigen::Vector3d> keyed = asked;
    std::vector<bool> fixed(keyed.size(), false);
    fixed[25] = true;  // 3 cm above the floor, 5 frames from the deepest frame
    liftPathAboveFloor(keyed, 0.0, lift, fixed);
    CHECK(keyed[25].y() == asked[25].y());
    for (int t = 0; t <= 40; ++t) CHECK(keyed[t].y() >= -1e-12);
    CHECK(keyed[20].y() == doctest::Approx(0.0));
    // A dip at either end of the path, a key beside it: the bumps stop at the path's ends.
    std::vector<Eigen::Vector3d> ends;
    for (int t = 0; t <= 12; ++t) ends.emplace_back(t, 0.2 * (t - 6) * (t - 6) - 4.0, 0.0);  // below at 2..10
    std::vector<bool> endKeys(ends.size(), false);
    endKeys[12] = true;  // 3.2 cm above the floor
    liftPathAboveFloor(ends, 0.0, lift, endKeys);
    for (const Eigen::Vector3d& p : ends) CHECK(p.y() >= -1e-12);
    CHECK(ends[12].y() == doctest::Approx(3.2));
}
