// A handle drag with falloff (motion/drag_falloff.h): the dragged frame keeps the drag's pose bit
// for bit, a smooth displacement over t−r..t+r, no frame-to-frame jump at the span's edges beyond
// the capture's; a second drag's spread keeps what the first one put on the neighbouring frames,
// and a pinned hand does not jump.
#include <cmath>

#include "edit/editor_document.h"
#include "ik/constrained_ik.h"
#include "motion/captured_pose_request.h"
#include "motion/drag_falloff.h"
#include "motion/foot_contacts.h"
#include "motion/motion_quality.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

namespace {
// Largest wrapped DOF change between frames s and s + 1.
double jumpDeg(const std::vector<Pose>& f, const Skeleton& sk, int s) {
    return largestAngleChangeDeg(f[s + 1], f[s], sk);
}

// The pose a drag of `effector` on frame t to `target` ends in, solved as the editor solves it:
// the constrained learned IK from the captured frame, planted feet pinned.
ConstrainedIkResult dragPose(const gp::ModelVersionPtr& version, int t, Effector effector,
                             const Eigen::Vector3d& target) {
    ConstrainedIkSolver solver(version);
    return solver.solve(
        capturedPoseRequest(*version, t, {{effector, target, false}}, detectFootContacts(version->model->clip), 200));
}

// A document on `version` whose drags spread over ±20 frames, the adaptive update off.
void openWithFalloff(EditorDocument& doc, const gp::ModelVersionPtr& version) {
    doc.setModel(version, true);
    doc.setAdaptiveEnabled(false);
    doc.setDragFalloff(20);
}

// A drag of `effector` on the current frame to `target`, released, and its spread waited for;
// returns the spread's summary.
std::string dragAndSpread(EditorDocument& doc, Effector effector, const Eigen::Vector3d& target) {
    REQUIRE(doc.beginDrag(effector).empty());
    doc.dragTo(target, 200);
    REQUIRE(doc.endDrag());
    doc.waitIdle();
    return doc.pollRegenerate();
}
}  // namespace

TEST_CASE("a drag of the left foot up 15 cm on frame 110 spread over ±30 frames") {
    const auto version = test::walkModel35();
    const Clip& clip = version->model->clip;
    const int t = 109;
    CHECK(defaultFalloffRadius(120.0) == 30);
    const Eigen::Vector3d target =
        effectorCm(clip.skeleton, clip.frames[t], Effector::kLFoot) + Eigen::Vector3d(0, 15, 0);
    const ConstrainedIkResult drag = dragPose(version, t, Effector::kLFoot, target);
    REQUIRE(drag.reached);
    std::string problem;
    MotionEditJob job = dragFalloffJob(version, Effector::kLFoot, t, drag.pose, drag.x, 30, {}, &problem);
    REQUIRE(problem.empty());
    job.run();
    // The dragged frame is the drag's pose and latent point, bit for bit.
    for (int j = 0; j < clip.skeleton.jointCount(); ++j) CHECK(job.frames[t].anglesDeg[j] == drag.pose.anglesDeg[j]);
    CHECK(job.frames[t].rootCm == drag.pose.rootCm);
    const auto heldAt = std::find(job.solvedFrames.begin(), job.solvedFrames.end(), t) - job.solvedFrames.begin();
    CHECK(job.results[static_cast<std::size_t>(heldAt)].x == drag.x);
    CHECK((effectorCm(clip.skeleton, job.frames[t], Effector::kLFoot) - target).norm() < 0.05);
    CHECK(job.quality.worstKeyErrorCm < 0.5);
    // The neighbours join the held frame smoothly: the span's second differences within the motion
    // bars (p95 ≤ 1.5 × capture + 2°, max ≤ 1.5 × capture + 5°).
    MESSAGE("held-frame falloff: second difference p95 "
            << job.quality.edited.p95Deg << "° (captured " << job.quality.captured.p95Deg << "°), max "
            << job.quality.edited.maxDeg << "° (captured " << job.quality.captured.maxDeg << "°) at frame "
            << job.quality.edited.maxFrame + 1);
    CHECK(job.quality.edited.p95Deg <= 1.5 * job.quality.captured.p95Deg + 2.0);
    CHECK(job.quality.edited.maxDeg <= 1.5 * job.quality.captured.maxDeg + 5.0);
    const SecondDifferenceStats around = secondDifferences(job.frames, clip.skeleton, t - 1, t + 1);
    const SecondDifferenceStats capturedAround = secondDifferences(clip.frames, clip.skeleton, t - 1, t + 1);
    MESSAGE("around the held frame: max " << around.maxDeg << "° (captured " << capturedAround.maxDeg << "°)");
    CHECK(around.maxDeg <= 1.5 * capturedAround.maxDeg + 5.0);
    // The foot's displacement falls off: half-way out it is between zero and the full 15 cm.
    const double half = (effectorCm(clip.skeleton, job.frames[t + 15], Effector::kLFoot) -
                         effectorCm(clip.skeleton, clip.frames[t + 15], Effector::kLFoot))
                            .norm();
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
    const Clip& clip = version->model->clip;
    const Eigen::VectorXd noX;
    std::string problem;
    dragFalloffJob(version, Effector::kLFoot, 100, clip.frames[100], noX, 0, {}, &problem);
    CHECK(problem == "expected a falloff radius of at least 1 frame, found 0");
    dragFalloffJob(version, Effector::kLFoot, 358, clip.frames[0], noX, 30, {}, &problem);
    CHECK(problem == "expected a frame in 1..358 of a clip of at least 3 frames, found 359");
    Pose bad = clip.frames[100];
    bad.anglesDeg[3].x() = NAN;
    dragFalloffJob(version, Effector::kLFoot, 100, bad, noX, 30, {}, &problem);
    CHECK(problem == "expected a finite drag pose, found NaN or Inf");
    dragFalloffJob(version, Effector::kLFoot, 100, Pose{}, noX, 30, {}, &problem);
    CHECK(problem == "expected a drag pose of the model's skeleton, found one with 0 joints");
    dragFalloffJob(version, Effector::kLFoot, 100, clip.frames[100], Eigen::VectorXd::Zero(5), 30, {}, &problem);
    CHECK(problem == "expected a 2-D held latent point, found 5");
    // Near the clip's start the span is clamped to frame 1 (one-sided falloff).
    const MotionEditJob j = dragFalloffJob(version, Effector::kLFoot, 5, clip.frames[5], noX, 30, {}, &problem);
    CHECK(problem.empty());
    CHECK(j.keyFrames == std::vector<int>{0, 5, 35});
}

TEST_CASE("a drag on the clip's first or last frame falls off on the one side it has") {
    const auto version = test::walkModel35();
    const Clip& clip = version->model->clip;
    const int n = clip.frameCount();
    for (const int t : {0, n - 1}) {
        CAPTURE(t);
        const Eigen::Vector3d captured = effectorCm(clip.skeleton, clip.frames[t], Effector::kRHand);
        const Eigen::Vector3d target = captured + Eigen::Vector3d(0, 12, 0);
        const ConstrainedIkResult drag = dragPose(version, t, Effector::kRHand, target);
        REQUIRE(drag.reached);
        std::string problem;
        MotionEditJob job = dragFalloffJob(version, Effector::kRHand, t, drag.pose, drag.x, 30, {}, &problem);
        REQUIRE(problem.empty());
        CHECK(job.keyFrames == (t == 0 ? std::vector<int>{0, 30} : std::vector<int>{n - 31, n - 1}));
        job.run();
        // The dragged frame keeps the drag's pose bit for bit; the 29 frames beside it are solved.
        for (int j = 0; j < clip.skeleton.jointCount(); ++j)
            CHECK(job.frames[t].anglesDeg[j] == drag.pose.anglesDeg[j]);
        CHECK(job.frames[t].rootCm == drag.pose.rootCm);
        CHECK(job.solvedFrames.size() == 29);
        // The hand's raise fades out: most of it next to the frame, none at the far end, each
        // frame's raise no larger than the one nearer the drag (the Hermite displacement, ±0.3 cm).
        const int away = t == 0 ? 1 : -1;
        auto raise = [&](int s) {
            return (effectorCm(clip.skeleton, job.frames[s], Effector::kRHand) -
                    effectorCm(clip.skeleton, clip.frames[s], Effector::kRHand))
                .y();
        };
        MESSAGE("raise next to the drag " << raise(t + away) << " cm, half-way " << raise(t + 15 * away)
                                          << " cm, at the far end " << raise(t + 30 * away) << " cm");
        CHECK(raise(t + away) > 10.0);
        CHECK(raise(t + 15 * away) > 3.0);
        CHECK(raise(t + 15 * away) < 9.0);
        CHECK(std::abs(raise(t + 30 * away)) < 1e-9);
        for (int k = 1; k < 30; ++k) CHECK(raise(t + (k + 1) * away) <= raise(t + k * away) + 0.3);
        // No frame-to-frame jump next to the drag beyond the capture's + 2°.
        const int s = t == 0 ? 0 : n - 2;
        CHECK(jumpDeg(job.frames, clip.skeleton, s) <= jumpDeg(clip.frames, clip.skeleton, s) + 2.0);
    }
}

TEST_CASE("editor: a drag with falloff re-solves t−r..t+r on release and is one undo step") {
    EditorDocument doc;
    const auto version = test::walkModel35();
    doc.setModel(version, true);
    doc.setAdaptiveEnabled(false);
    doc.setDragFalloff(20);
    doc.setFrame(109);
    REQUIRE(doc.beginDrag(Effector::kLFoot).empty());
    const Clip& clip = version->model->clip;
    const Eigen::Vector3d target =
        effectorCm(clip.skeleton, clip.frames[109], Effector::kLFoot) + Eigen::Vector3d(0, 10, 0);
    doc.dragTo(target, 200);
    REQUIRE(doc.endDrag());
    const Pose released = doc.currentPose();  // what the user saw on release
    const std::optional<AdmissionVerdict> releasedVerdict = doc.currentPoseVerdict();
    REQUIRE(releasedVerdict);
    doc.waitIdle();
    const std::string summary = doc.pollRegenerate();
    CHECK(summary == "drag lfoot on frame 110: spread over frames 91-129 (falloff 20 frames)");
    CHECK_FALSE(doc.lastRegenerateQuality());  // the Path panel reports path regenerations only
    auto poseAt = [&](int t) {
        doc.setFrame(t);
        return doc.currentPose();
    };
    // Frames 90..128 (0-based) changed, 109 is still the drag's pose, and one undo restores all of them.
    const Pose dragged = poseAt(109);
    for (int j = 0; j < clip.skeleton.jointCount(); ++j) CHECK(dragged.anglesDeg[j] == released.anglesDeg[j]);
    // So the range legend still judges the pose the user released (it judged a re-solved one).
    const std::optional<AdmissionVerdict> verdict = doc.currentPoseVerdict();
    REQUIRE(verdict);
    CHECK(verdict->lik == releasedVerdict->lik);
    CHECK(verdict->sigma2 == releasedVerdict->sigma2);
    CHECK((effectorCm(clip.skeleton, dragged, Effector::kLFoot) - target).norm() < 0.05);
    CHECK(largestAngleChangeDeg(poseAt(100), clip.frames[100], clip.skeleton) > 0.1);
    CHECK(doc.edits().size() == 39);
    CHECK(doc.undo().empty());
    CHECK(doc.edits().empty());
    for (int t : {90, 100, 109, 120, 128})
        CHECK(largestAngleChangeDeg(poseAt(t), clip.frames[t], clip.skeleton) == 0.0);
    CHECK_FALSE(doc.undo().empty());  // nothing else was pushed
}

TEST_CASE("editor: a hand drag's falloff keeps where an earlier foot drag put the foot on the neighbouring frames") {
    // The user's sequence: on one frame drag the right foot up 15 cm (spread over ±20 frames), then
    // drag the right hand. The hand drag's spread fades into the motion as edited so far, so the
    // foot stays raised on t−1..t+1; it used to start from the capture and put the foot back on
    // the ground there (a 15 cm one-frame spike).
    EditorDocument doc;
    const auto version = test::walkModel35();
    const Clip& clip = version->model->clip;
    const Skeleton& sk = clip.skeleton;
    openWithFalloff(doc, version);
    const int t = 140;
    doc.setFrame(t);
    dragAndSpread(doc, Effector::kRFoot, effectorCm(sk, clip.frames[t], Effector::kRFoot) + Eigen::Vector3d(0, 15, 0));
    auto footAt = [&](int s) {
        doc.setFrame(s);
        return effectorCm(sk, doc.currentPose(), Effector::kRFoot);
    };
    const Eigen::Vector3d footBefore[3] = {footAt(t - 1), footAt(t), footAt(t + 1)};
    CHECK(footBefore[1].y() - effectorCm(sk, clip.frames[t], Effector::kRFoot).y() > 14.0);
    doc.setFrame(t);
    const std::string spread = dragAndSpread(
        doc, Effector::kRHand, effectorCm(sk, doc.currentPose(), Effector::kRHand) + Eigen::Vector3d(0, 10, 5));
    CHECK(spread.find(": spread over frames") != std::string::npos);
    for (int k = 0; k < 3; ++k) {
        const double moved = (footAt(t - 1 + k) - footBefore[k]).norm();
        MESSAGE("frame " << t - 1 + k << ": the foot moved " << moved << " cm during the hand drag");
        CHECK(moved <= 1.0);
    }
    // The hand drag is its own undo step: undoing it brings back the foot drag's motion exactly.
    REQUIRE(doc.undo().empty());
    for (int k = 0; k < 3; ++k) CHECK((footAt(t - 1 + k) - footBefore[k]).norm() == 0.0);
}

TEST_CASE("editor: a hand pinned after a head drag does not jump during a drag of the other hand") {
    // The user's sequence on the walk: drag the head on frame 101, pin the left hand, drag the right
    // hand. Both drags spread over ±20 frames. The pinned hand is held where the motion has it on
    // every frame of the second spread, so its path has no one-frame jump at the dragged frame:
    // its second difference there stays within the capture's + 0.5 cm.
    EditorDocument doc;
    const auto version = test::walkModel35();
    const Clip& clip = version->model->clip;
    const Skeleton& sk = clip.skeleton;
    openWithFalloff(doc, version);
    const int t = 100;
    auto handAt = [&](int s) {
        doc.setFrame(s);
        return effectorCm(sk, doc.currentPose(), Effector::kLHand);
    };
    doc.setFrame(t);
    dragAndSpread(doc, Effector::kHead, effectorCm(sk, clip.frames[t], Effector::kHead) + Eigen::Vector3d(5, -8, 0));
    doc.setFrame(t);
    doc.setPinned(Effector::kLHand, true);
    const std::string spread = dragAndSpread(
        doc, Effector::kRHand, effectorCm(sk, doc.currentPose(), Effector::kRHand) + Eigen::Vector3d(0, 15, 5));
    CHECK(spread.find(": spread over frames") != std::string::npos);
    const double edited = test::positionSecondDifferenceCm(handAt, t);
    const double captured = test::positionSecondDifferenceCm(
        [&](int s) { return effectorCm(sk, clip.frames[static_cast<std::size_t>(s)], Effector::kLHand); }, t);
    MESSAGE("the pinned hand's second difference at the dragged frame: " << edited << " cm (capture " << captured
                                                                         << " cm)");
    CHECK(edited <= captured + 0.5);
}

TEST_CASE("a whole-pose spread that holds feet at their old place guides a foot from it where its contact ends") {
    // The base motion is layered (the whole body shifted up to 20 cm sideways around frame 110), the
    // holds are at the old place (EditBase::holdFrames, as after a paste). Where a contact ends (or
    // starts) inside the span, the foot must not jump from its old place to the layered one in one
    // frame: it is guided there along a smoothstep of up to 20 frames (at most 1.5 × 20 cm / 20 per
    // frame above the capture's step).
    const auto version = test::walkModel35();
    const Clip& clip = version->model->clip;
    const int t = 109, radius = 30;
    auto base = std::make_shared<EditBase>();
    base->frames = clip.frames;
    base->x.assign(clip.frames.size(), Eigen::VectorXd());
    base->holdFrames = clip.frames;
    constexpr double kShiftCm = 20.0;
    for (int s = t - radius; s <= t + radius; ++s) {
        const double w = 0.5 * (1.0 + std::cos(M_PI * double(s - t) / double(radius + 1)));
        base->frames[static_cast<std::size_t>(s)].rootCm.x() += w * kShiftCm;
    }
    std::string problem;
    MotionEditJob job =
        dragFalloffJob(version, Effector::kHead, t, base->frames[t], Eigen::VectorXd(), radius, {}, &problem, base);
    REQUIRE(problem.empty());
    const ContactSet contacts = detectFootContacts(clip);
    job.contacts = std::make_shared<const ContactSet>(contacts);
    job.run();
    const Skeleton& sk = clip.skeleton;
    int edges = 0;
    for (const FootContact& c : contacts.contacts) {
        for (const int edge : {c.first, c.last}) {
            if (edge <= t - radius || edge >= t + radius) continue;  // not inside the span
            const int next = edge == c.last ? edge + 1 : edge - 1;   // the first frame off the contact
            if (next == t) continue;
            ++edges;
            CAPTURE(edge);
            CAPTURE(next);
            const double edited =
                (effectorCm(sk, job.frames[next], c.foot) - effectorCm(sk, job.frames[edge], c.foot)).norm();
            const double captured =
                (effectorCm(sk, clip.frames[next], c.foot) - effectorCm(sk, clip.frames[edge], c.foot)).norm();
            MESSAGE(std::string(effectorName(c.foot)) << " contact edge at frame " << edge + 1 << ": step " << edited
                                                      << " cm (captured " << captured << " cm)");
            CHECK(edited - captured <= 1.5 * kShiftCm / 20.0 + 0.5);
            // On the contact itself the foot is at its old place.
            CHECK((effectorCm(sk, job.frames[edge], c.foot) - effectorCm(sk, clip.frames[edge], c.foot)).norm() <= 0.5);
        }
    }
    REQUIRE(edges > 0);  // the case does exercise a contact that ends inside the span
}
