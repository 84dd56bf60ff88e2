// Mirror pose and rotate joint in the editor (label `gl`), offscreen: the shortcut, the menu's
// action, the Rotate joint window's slider gesture (a live preview, then one undo step) and the
// learned prior option with pinned feet.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "edit/joint_rotation.h"
#include "editor_harness.h"
#include "gl_test_paths.h"
#include "io/clip_loader.h"
#include "skeleton/forward_kinematics.h"
#include "ui/input/gui_script.h"
#include "ui/input/input_state.h"
#include "ui/shell/editor_app.h"
#include "ui/widgets/widgets.h"

using namespace mgp;
using test::tapKey;

namespace {

using test::Harness;
namespace key = ui::key;

}  // namespace

TEST_CASE("gui pose tools: Ctrl+Shift+M mirrors the pose as one undo step, and the script action does the same") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    doc.setFrame(30);
    h->frame(1);
    const Pose before = doc.currentPose();
    const Skeleton& sk = doc.clip().skeleton;
    const int lh = sk.findBone("lhumerus"), rh = sk.findBone("rhumerus");
    tapKey(*h, 'M', {key::kLeftCtrl, key::kLeftShift});
    REQUIRE(doc.isEdited(30));
    CHECK(doc.undoLabel() == "mirror pose on frame 31");
    CHECK(doc.currentPose().anglesDeg[lh][0] == before.anglesDeg[rh][0]);
    CHECK(doc.currentPose().anglesDeg[lh][2] == -before.anglesDeg[rh][2]);
    REQUIRE(s.messages.current() != nullptr);
    CHECK(s.messages.current()->text.find("mirrored the pose of frame 31") != std::string::npos);
    tapKey(*h, 'Z', {key::kLeftCtrl});
    CHECK_FALSE(doc.isEdited(30));
    CHECK(h->app->runAction({"mirror-pose"}) == "");
    CHECK(doc.undoLabel() == "mirror pose on frame 31");
    const auto errors = h->play(ui::GuiScript::parse("1 action mirror-pose\n"));
    REQUIRE(errors.empty());
    for (int j = 1; j < sk.jointCount(); ++j)
        CHECK((doc.currentPose().anglesDeg[j] - before.anglesDeg[j]).cwiseAbs().maxCoeff() < 1e-9);
}

TEST_CASE(
    "gui pose tools: dragging a Rotate joint slider previews, then changes only that joint's DOFs as one undo step") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    doc.setFrame(50);
    REQUIRE(h->app->runAction({"rotate-joint"}) == "");
    h->frame(3);
    REQUIRE(h->app->jointWindow().shown());
    const Skeleton& sk = doc.clip().skeleton;
    const int j = h->app->jointWindow().joint();
    REQUIRE(j == sk.findBone("lhumerus"));
    REQUIRE(s.controls.count("rotate joint: rx"));
    const auto rect = s.controls.at("rotate joint: rx");
    REQUIRE(rect.visible);
    const Pose before = doc.currentPose();
    const bool couldUndo = doc.canUndo();
    h->input.mouseX = 0.5f * (rect.x0 + rect.x1);
    h->input.mouseY = 0.5f * (rect.y0 + rect.y1);
    h->frame(2);
    h->input.setButton(0, true);
    h->frame(2);
    h->input.mouseX += 40.0f;
    h->frame(2);
    h->input.mouseX += 30.0f;
    h->frame(2);
    // During the gesture: a preview, and nothing in the document yet.
    CHECK(s.posePreview.has_value());
    CHECK_FALSE(doc.isEdited(50));
    h->input.setButton(0, false);
    h->frame(3);
    CHECK_FALSE(s.posePreview.has_value());
    REQUIRE(doc.isEdited(50));
    CHECK(doc.undoLabel() == "rotate lhumerus on frame 51");
    const Pose& after = doc.currentPose();
    CHECK(after.rootCm == before.rootCm);
    CHECK(after.anglesDeg[j][0] > before.anglesDeg[j][0] + 1.0);  // dragged right: a larger angle
    for (int k = 0; k < sk.jointCount(); ++k)
        if (k != j) CHECK(after.anglesDeg[k] == before.anglesDeg[k]);
    CHECK(after.anglesDeg[j][1] == before.anglesDeg[j][1]);
    CHECK(after.anglesDeg[j][2] == before.anglesDeg[j][2]);
    REQUIRE(doc.undo() == "");
    CHECK_FALSE(doc.isEdited(50));
    CHECK(doc.canUndo() == couldUndo);  // the whole gesture was one step
}

TEST_CASE("gui pose tools: rotate-joint with the learned prior holds the joint's values and the pinned feet") {
    auto h = test::makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    const auto errors =
        h->play(ui::GuiScript::parse("1 action frame 61\n2 action pin lfoot\n3 action pin rfoot\n"
                                     "4 action follow-prior on\n5 action rotate-joint lowerback 20 0 5\n"));
    REQUIRE(errors.empty());
    const Skeleton& sk = doc.clip().skeleton;
    const int j = sk.findBone("lowerback");
    REQUIRE(doc.isEdited(60));
    CHECK(doc.undoLabel() == "rotate lowerback on frame 61");
    CHECK(std::abs(doc.currentPose().anglesDeg[j][0] - 20.0) <= 1e-6);
    CHECK(std::abs(doc.currentPose().anglesDeg[j][1]) <= 1e-6);
    CHECK(std::abs(doc.currentPose().anglesDeg[j][2] - 5.0) <= 1e-6);
    const Pose captured = doc.clip().frames[60];
    for (Effector foot : {Effector::kLFoot, Effector::kRFoot})
        CHECK((effectorCm(sk, doc.currentPose(), foot) - effectorCm(sk, captured, foot)).norm() <= 0.05);
    // The window's readout keeps the solve's line (the status line moves on to the spread's).
    CHECK(h->app->jointWindow().readout().find("the prior re-solved the rest") != std::string::npos);
    // A wrong number of angles says how many the joint takes.
    const std::string err = h->app->runAction({"rotate-joint", "ltibia", "10", "20"});
    CHECK(err.find("expected 1 angle for ltibia (x), found 2") != std::string::npos);
    CHECK(h->app->runAction({"rotate-joint", "nosuchbone", "1"}).find("unknown joint") != std::string::npos);
}

TEST_CASE("gui pose tools: with the Rotate joint window shown, clicking a bone in the viewport picks its joint") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    const Skeleton& sk = s.doc.clip().skeleton;
    REQUIRE(h->app->runAction({"rotate-joint"}) == "");
    h->frame(3);
    for (const char* bone : {"rtibia", "lfemur"}) {
        CAPTURE(std::string(bone));
        const int j = sk.findBone(bone);
        FkState fk;
        forwardKinematics(sk, s.doc.currentPose(), fk);
        const Eigen::Vector3d mid = 0.5 * (fk.jointCm[j] + boneEndCm(sk, fk, j));
        glm::vec3 p;
        REQUIRE(s.camera.project(glm::vec3(float(mid.x()), float(mid.y()), float(mid.z())), s.viewportWidth,
                                 s.viewportHeight, p));
        h->input.mouseX = s.viewportX + p.x;
        h->input.mouseY = s.viewportY + p.y;
        h->frame(2);
        h->input.setButton(0, true);
        h->input.setButton(0, false);
        h->frame(4);
        CHECK(h->app->jointWindow().joint() == j);
    }
    CHECK_FALSE(s.doc.canUndo());  // picking is not an edit
}

TEST_CASE("gui pose tools: Ctrl+C then Ctrl+V 70 frames on spreads the pasted pose over the falloff, one undo step") {
    auto h = test::makeHarness(false);  // with the walk model: the spread needs it
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    doc.setAdaptiveEnabled(false);
    doc.setFrame(40);
    h->frame(1);
    tapKey(*h, 'C', {key::kLeftCtrl});
    doc.setFrame(110);
    h->frame(1);
    tapKey(*h, 'V', {key::kLeftCtrl});
    REQUIRE(doc.isEdited(110));
    h->app->waitIdle();
    h->frame(2);
    REQUIRE(s.messages.current() != nullptr);
    CHECK(s.messages.current()->text.find("paste pose on frame 111: spread over frames") == 0);
    CHECK(doc.edits().size() > 40);  // ± the falloff (30 frames), not one frame
    CHECK(doc.isEdited(100));
    CHECK(doc.undoLabel() == "paste pose on frame 111");
    tapKey(*h, 'Z', {key::kLeftCtrl});
    CHECK(doc.edits().empty());
}

TEST_CASE(
    "gui pose tools: a pose pasted from 180 frames away and a mirrored pose blend into their neighbours with the "
    "planted feet kept, and the exported BVH carries it") {
    auto h = test::makeHarness(false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    doc.setAdaptiveEnabled(false);  // the spreads below are judged against one model
    const std::string dir = test::kOutDir + "/gui_pose_spread";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    // Standing frames (both feet planted, as a pose operation's bar asks): the first from frame 101 for
    // the paste (its source 180 frames later), the first from frame 231 for the mirror.
    auto standing = [&](int from) {
        for (int t = from; t < doc.frameCount(); ++t)
            if (doc.contacts().at(Effector::kLFoot, t) && doc.contacts().at(Effector::kRFoot, t)) return t;
        return -1;
    };
    const int tp = standing(100), tm = standing(230);
    REQUIRE(tp >= 0);
    REQUIRE(tp + 180 < doc.frameCount());
    REQUIRE(tm > tp + 60);
    const std::string pasted = std::to_string(tp + 1), mirrored = std::to_string(tm + 1);
    ui::GuiScript s;
    s.add(0, "action", {"export-bvh", dir + "/before.bvh"});
    s.add(1, "action", {"frame", std::to_string(tp + 181)});
    s.add(2, "action", {"copy-pose"});
    s.add(3, "action", {"frame", pasted});
    s.add(4, "action", {"paste-pose"});
    s.add(5, "action", {"wait"});
    s.add(7, "action", {"frame", mirrored});
    s.add(8, "action", {"mirror-pose"});
    s.add(9, "action", {"wait"});
    s.add(11, "action", {"export-bvh", dir + "/after.bvh"});
    s.add(12, "action", {"wait"});
    REQUIRE(h->play(s).empty());
    const auto& history = h->app->state().messages.history();
    for (const std::string& said : {"paste pose on frame " + pasted + ": spread over frames",
                                    "mirror pose on frame " + mirrored + ": spread over"})
        CHECK(std::any_of(history.begin(), history.end(),
                          [&](const auto& m) { return m.text.find(said) != std::string::npos; }));
    CHECK(doc.isEdited(tp));
    CHECK(doc.isEdited(tm));
    CHECK(doc.edits().size() > 60);  // both spread, not one frame each

    // The exported motion against the exported capture, hands and feet (their joints) frame by frame.
    const Clip before = loadClip(dir + "/before.bvh"), after = loadClip(dir + "/after.bvh");
    REQUIRE(before.frameCount() == doc.frameCount());
    REQUIRE(after.frameCount() == doc.frameCount());
    const Skeleton& asf = doc.clip().skeleton;
    auto jointOf = [&](Effector e) { return after.skeleton.findJoint(asf.joints[asf.effectorSite(e).joint].name); };
    const Effector ends[] = {Effector::kLHand, Effector::kRHand, Effector::kLFoot, Effector::kRFoot};
    std::vector<FkState> fb(before.frameCount()), fa(after.frameCount());
    for (int t = 0; t < doc.frameCount(); ++t) {
        forwardKinematics(before.skeleton, before.frames[t], fb[t]);
        forwardKinematics(after.skeleton, after.frames[t], fa[t]);
    }
    double worstJump = 0.0, worstFoot = 0.0, worstFrameGap = 0.0;
    for (Effector e : ends) {
        REQUIRE(after.skeleton.effectorSite(e).joint >= 0);
        auto at = [&](const std::vector<FkState>& fk, int t) { return effectorCm(after.skeleton, fk[t], e); };
        for (int t = 0; t + 1 < doc.frameCount(); ++t)
            worstJump = std::max(worstJump, (at(fa, t + 1) - at(fa, t)).norm() - (at(fb, t + 1) - at(fb, t)).norm());
        if (e == Effector::kLFoot || e == Effector::kRFoot)
            for (int t = 0; t < doc.frameCount(); ++t)
                if (doc.contacts().at(e, t) && t != tp && t != tm)
                    worstFoot = std::max(worstFoot, (at(fa, t) - at(fb, t)).norm());
        // The exported frames are the document's (the joint that carries the effector).
        const int j = jointOf(e);
        REQUIRE(j >= 0);
        for (int t : {tp, tm}) {
            FkState fk;
            forwardKinematics(asf, doc.edits().at(t).pose, fk);
            worstFrameGap = std::max(worstFrameGap, (fa[t].jointCm[j] - fk.jointCm[asf.effectorSite(e).joint]).norm());
        }
    }
    MESSAGE("paste on frame " << pasted << ", mirror on frame " << mirrored
                              << "; exported: worst one-frame step of a hand or foot over the capture's " << worstJump
                              << " cm, planted feet within " << worstFoot << " cm");
    CHECK(worstJump <= 1.0);
    CHECK(worstFoot <= 1.0);
    CHECK(worstFrameGap < 1e-3);
}

TEST_CASE("gui pose tools: the Rotate joint readout breaks its lines at spaces only, never inside a number") {
    const auto width = [](std::string_view s) { return 7.0f * static_cast<float>(s.size()); };
    const std::string text = "2 held effectors within 0.002 cm (converged)";
    // ImGui's own wrapping at this width breaks after the full stop: "... within 0." / "002 cm".
    const std::vector<std::string> lines = ui::linesBrokenAtSpaces(text, 7.0f * 26.0f, width);
    REQUIRE(lines.size() == 2);
    CHECK(lines[0] == "2 held effectors within");
    CHECK(lines[1] == "0.002 cm (converged)");
    // Wide enough: one line; a word wider than the room keeps a line of its own.
    CHECK(ui::linesBrokenAtSpaces(text, 7.0f * 100.0f, width) == std::vector<std::string>{text});
    CHECK(ui::linesBrokenAtSpaces("a 1234567890 b", 7.0f * 5.0f, width) ==
          std::vector<std::string>{"a", "1234567890", "b"});
    CHECK(ui::linesBrokenAtSpaces("", 70.0f, width) == std::vector<std::string>{""});
}
