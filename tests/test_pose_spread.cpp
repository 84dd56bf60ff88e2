// Every pose operation is a motion edit: paste, mirror and a joint rotation set the frame's pose
// and then spread it over t−r..t+r as a drag's release is (EditorDocument::setCurrentPose →
// the drag falloff, motion/drag_falloff.h), the frame itself held bit for bit, one undo step.
#include <doctest/doctest.h>

#include "edit/editor_document.h"
#include "edit/joint_rotation.h"
#include "edit/mirror_edit.h"
#include "motion/motion_quality.h"
#include "trained_model_fixture.h"

using namespace mgp;

namespace {

struct SpreadDoc {
    EditorDocument doc;
    gp::ModelVersionPtr version = test::walkModel35();
    SpreadDoc() {
        doc.setModel(version, true);
        doc.setAdaptiveEnabled(false);
        doc.setDragFalloff(20);
    }
    const Clip& clip() const { return version->model->clip; }
    Pose poseAt(int t) {
        doc.setFrame(t);
        return doc.currentPose();
    }
    // The largest joint-angle step between frames t and t+1 as the document has them now.
    double stepDeg(int t) { return largestAngleChangeDeg(poseAt(t + 1), poseAt(t), clip().skeleton); }
};

}  // namespace

TEST_CASE("editor: a pose pasted 70 frames away blends into its neighbours, is held on its frame, one undo step") {
    SpreadDoc s;
    const Pose source = s.poseAt(40);
    s.doc.setFrame(110);
    REQUIRE(s.doc.pastePose(source).empty());
    const Pose pasted = s.doc.currentPose();
    const double oneFrameJump = std::max(s.stepDeg(109), s.stepDeg(110));  // before the spread lands
    s.doc.waitIdle();
    const std::string summary = s.doc.pollRegenerate();
    // The pose of frame 41 is far from frame 111's (its hands 40-odd cm away): the layer widens
    // from the falloff's 20 frames until no hand or foot gains more than 90 cm/s (poseLayerRadius).
    CHECK(summary ==
          "paste pose on frame 111: spread over frames 25-197 (falloff 20 frames, widened to 87 to keep the motion "
          "smooth)");
    const Pose held = s.poseAt(110);
    CHECK(held.rootCm == pasted.rootCm);
    for (int j = 0; j < s.clip().skeleton.jointCount(); ++j) CHECK(held.anglesDeg[j] == pasted.anglesDeg[j]);
    const double spreadJump = std::max(s.stepDeg(109), s.stepDeg(110));
    MESSAGE("largest step next to the pasted frame: " << oneFrameJump << " deg as one frame, " << spreadJump
                                                      << " deg spread");
    CHECK(spreadJump < 0.25 * oneFrameJump);
    // Over the whole span, no step exceeds the capture's by more than the falloff's blend's own
    // steepest step would (the Hermite weight's slope is at most 1.5 / r, r = 20; the widened
    // layer's is 1.5 / 87).
    double worst = 0.0;
    int worstAt = -1;
    for (int t = 22; t <= 197; ++t) {
        const double excess =
            s.stepDeg(t) - largestAngleChangeDeg(s.clip().frames[t + 1], s.clip().frames[t], s.clip().skeleton);
        if (excess > worst) {
            worst = excess;
            worstAt = t;
        }
    }
    MESSAGE("largest step above the capture's over frames 23-198: " << worst << " deg at frame " << worstAt + 1);
    CHECK(worst <= 1.5 * oneFrameJump / 20.0);
    CHECK(s.doc.edits().size() == 173);
    CHECK(s.doc.undo().empty());
    CHECK(s.doc.edits().empty());
}

TEST_CASE("editor: mirror and a joint rotation spread over the falloff too") {
    SpreadDoc s;
    s.doc.setFrame(100);
    REQUIRE(mirrorCurrentPose(s.doc).empty());
    s.doc.waitIdle();
    CHECK(s.doc.pollRegenerate().find("mirror pose on frame 101: spread over frames") == 0);
    CHECK(s.doc.edits().size() > 1);
    CHECK(s.doc.undo().empty());
    REQUIRE(s.doc.edits().empty());

    const int knee = s.clip().skeleton.findBone("rtibia");
    REQUIRE(knee >= 0);
    s.doc.setFrame(100);
    JointRotation r;
    r.joint = knee;
    r.anglesDeg = s.doc.currentPose().anglesDeg[knee] + Eigen::Vector3d(30, 0, 0);
    REQUIRE(applyJointRotation(s.doc, r).empty());
    s.doc.waitIdle();
    CHECK(s.doc.pollRegenerate().find("rotate ") == 0);
    CHECK(s.doc.edits().size() > 1);
    CHECK(s.stepDeg(100) < 30.0);  // the 30° is not a one-frame jump any more
}

TEST_CASE("editor: a pose change on the clip's first or last frame spreads to the one side it has") {
    SpreadDoc s;
    const int n = s.clip().frameCount();
    for (const int t : {0, n - 1}) {
        CAPTURE(t);
        const Pose source = s.poseAt(t == 0 ? 40 : n - 41);
        s.doc.setFrame(t);
        REQUIRE(s.doc.pastePose(source).empty());
        const Pose pasted = s.doc.currentPose();
        const int inner = t == 0 ? 1 : n - 2;
        const double oneFrameJump = s.stepDeg(std::min(t, inner));  // before the spread lands
        s.doc.waitIdle();
        const std::string said = s.doc.pollRegenerate();
        CHECK(
            said ==
            (t == 0
                 ? "paste pose on frame 1: spread over frames 2-140 (falloff 20 frames, widened to 140 to keep the "
                   "motion smooth)"
                 : "paste pose on frame 358: spread over frames 256-357 (falloff 20 frames, widened to 103 to keep the "
                   "motion smooth)"));
        CHECK(s.doc.edits().size() == (t == 0 ? 140u : 103u));  // the pasted frame and those beside it
        const Pose held = s.poseAt(t);
        CHECK(held.rootCm == pasted.rootCm);
        for (int j = 0; j < s.clip().skeleton.jointCount(); ++j) CHECK(held.anglesDeg[j] == pasted.anglesDeg[j]);
        const double spreadJump = s.stepDeg(std::min(t, inner));
        MESSAGE("step next to the pasted frame: " << oneFrameJump << " deg as one frame, " << spreadJump
                                                  << " deg spread");
        CHECK(spreadJump < 0.25 * oneFrameJump);
        CHECK(s.doc.undo().empty());
        CHECK(s.doc.edits().empty());
    }
}
