// A handle drag with falloff (motion/drag_falloff.h): the target met on the dragged frame, a smooth
// displacement over t−r..t+r, no frame-to-frame jump at the span's edges beyond the capture's.
#include <cmath>

#include "motion/drag_falloff.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

namespace {
// Largest wrapped DOF change between frames s and s + 1.
double jumpDeg(const std::vector<Pose>& f, const Skeleton& sk, int s) { return largestAngleChangeDeg(f[s + 1], f[s], sk); }
}  // namespace

TEST_CASE("a drag of the left foot up 15 cm on frame 110 spread over ±30 frames") {
    const auto version = test::walkModel35();
    const Clip& clip = version->model->clip;
    const int t = 109;
    CHECK(defaultFalloffRadius(120.0) == 30);
    const Eigen::Vector3d target = effectorCm(clip.skeleton, clip.frames[t], Effector::kLFoot) + Eigen::Vector3d(0, 15, 0);
    std::string problem;
    MotionEditJob job = dragFalloffJob(version, Effector::kLFoot, t, target, 30, {}, &problem);
    REQUIRE(problem.empty());
    job.run();
    CHECK((effectorCm(clip.skeleton, job.frames[t], Effector::kLFoot) - target).norm() < 0.5);
    CHECK(job.quality.worstKeyErrorCm < 0.5);
    // The foot's displacement falls off: half-way out it is between zero and the full 15 cm.
    const double half = (effectorCm(clip.skeleton, job.frames[t + 15], Effector::kLFoot) -
                         effectorCm(clip.skeleton, clip.frames[t + 15], Effector::kLFoot)).norm();
    CHECK(half > 2.0);
    CHECK(half < 15.0);
    // Edges: frame-to-frame jumps no larger than the capture's + 2°.
    for (int s : {t - 31, t - 30, t - 29, t + 28, t + 29, t + 30}) {
        CAPTURE(s);
        CHECK(jumpDeg(job.frames, clip.skeleton, s) <= jumpDeg(clip.frames, clip.skeleton, s) + 2.0);
    }
    // The planted right foot (100..157) stays.
    for (const ContactTravel& c : job.quality.contacts) CHECK(std::abs(c.editedCm - c.capturedCm) <= 1.0);
}

TEST_CASE("drag falloff refuses what it cannot do, with one clear reason") {
    const auto version = test::walkModel35();
    std::string problem;
    dragFalloffJob(version, Effector::kLFoot, 100, Eigen::Vector3d::Zero(), 0, {}, &problem);
    CHECK(problem == "expected a falloff radius of at least 1 frame, found 0");
    dragFalloffJob(version, Effector::kLFoot, 0, Eigen::Vector3d::Zero(), 30, {}, &problem);
    CHECK(problem == "expected a frame with a captured frame on each side (2..357), found 1");
    dragFalloffJob(version, Effector::kLFoot, 100, Eigen::Vector3d::Constant(NAN), 30, {}, &problem);
    CHECK(problem == "expected a finite drag target, found NaN or Inf");
    // Near the clip's start the span is clamped to frame 1 (one-sided falloff).
    const MotionEditJob j = dragFalloffJob(version, Effector::kLFoot, 5, Eigen::Vector3d(0, 0, 0), 30, {}, &problem);
    CHECK(problem.empty());
    CHECK(j.keyFrames == std::vector<int>{0, 5, 35});
}

#include "edit/editor_document.h"

TEST_CASE("editor: a drag with falloff re-solves t−r..t+r on release and is one undo step") {
    EditorDocument doc;
    const auto version = test::walkModel35();
    doc.setModel(version, true);
    doc.setAdaptiveEnabled(false);
    doc.setDragFalloff(20);
    doc.setFrame(109);
    REQUIRE(doc.beginDrag(Effector::kLFoot).empty());
    const Clip& clip = version->model->clip;
    const Eigen::Vector3d target = effectorCm(clip.skeleton, clip.frames[109], Effector::kLFoot) + Eigen::Vector3d(0, 10, 0);
    doc.dragTo(target, 200);
    REQUIRE(doc.endDrag());
    doc.waitIdle();
    const std::string summary = doc.pollRegenerate();
    CHECK(summary.rfind("drag spread over frames 91-129", 0) == 0);
    auto poseAt = [&](int t) {
        doc.setFrame(t);
        return doc.currentPose();
    };
    // Frames 90..128 (0-based) changed, 109 meets the target, and one undo restores all of them.
    CHECK((effectorCm(clip.skeleton, poseAt(109), Effector::kLFoot) - target).norm() < 0.5);
    CHECK(largestAngleChangeDeg(poseAt(100), clip.frames[100], clip.skeleton) > 0.1);
    CHECK(doc.edits().size() == 39);
    CHECK(doc.undo().empty());
    CHECK(doc.edits().empty());
    for (int t : {90, 100, 109, 120, 128}) CHECK(largestAngleChangeDeg(poseAt(t), clip.frames[t], clip.skeleton) == 0.0);
    CHECK_FALSE(doc.undo().empty());  // nothing else was pushed
}
