// Held effectors (edit/held_effectors.h): what the animator placed on a frame stays there through
// later drags on that frame and through later falloffs on the frames that hold it, until released;
// the record of what is held follows undo and redo.
#include <algorithm>

#include "edit/editor_document.h"
#include "edit/held_effectors.h"
#include "edit/joint_rotation.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

namespace {
// A drag of `effector` on the current frame to `target`, released, and its spread (if any) waited for.
std::string heldTestDrag(EditorDocument& doc, Effector effector, const Eigen::Vector3d& target) {
    REQUIRE(doc.beginDrag(effector).empty());
    doc.dragTo(target, 200);
    REQUIRE(doc.endDrag());
    doc.waitIdle();
    return doc.pollRegenerate();
}

Eigen::Vector3d heldTestEffector(EditorDocument& doc, int frame, Effector e) {
    doc.setFrame(frame);
    return effectorCm(doc.clip().skeleton, doc.currentPose(), e);
}

// The walk fixture on `doc`, adaptive updates off, the given falloff.
void heldTestOpen(EditorDocument& doc, int falloff) {
    doc.setModel(test::walkModel35(), true);
    doc.setAdaptiveEnabled(false);
    doc.setDragFalloff(falloff);
}

// The effector's position on frames first..last (0-based) of the motion as edited now.
std::map<int, Eigen::Vector3d> heldTestPositions(EditorDocument& doc, Effector e, int first, int last) {
    std::map<int, Eigen::Vector3d> out;
    for (int s = first; s <= last; ++s) out[s] = heldTestEffector(doc, s, e);
    return out;
}

// The largest distance, over frames first..last, between the effector now and `before` there.
double heldTestLargestMove(EditorDocument& doc, Effector e, const std::map<int, Eigen::Vector3d>& before, int first,
                           int last) {
    double largest = 0.0;
    for (int s = first; s <= last; ++s)
        largest = std::max(largest, (heldTestEffector(doc, s, e) - before.at(s)).norm());
    return largest;
}

// The right hand's path around frame 140 (keys 119, 133, 147, 161, 0-based) with its two inner
// keys raised 12 cm, regenerated and applied; the hand meets both keys.
void heldTestRaiseRightHandPath(EditorDocument& doc) {
    doc.setFrame(140);
    REQUIRE(doc.beginPathEdit(Effector::kRHand) == "");
    REQUIRE(doc.paths().edit()->keyFrames == std::vector<int>{119, 133, 147, 161});
    for (int k : {1, 2}) REQUIRE(doc.paths().setKeyOffset(k, {0, 12, 0}) == "");
    REQUIRE(doc.startRegenerate(500) == "");
    doc.waitIdle();
    REQUIRE(doc.pollRegenerate().rfind("regenerated", 0) == 0);
    for (int k : {1, 2}) {
        const int t = doc.paths().edit()->keyFrames[static_cast<std::size_t>(k)];
        CHECK((heldTestEffector(doc, t, Effector::kRHand) - doc.paths().keyPosition(k)).norm() <= 0.5);
    }
}

ClipEdits heldTestEdits(std::map<int, std::vector<Effector>> moved) {
    ClipEdits edits;
    edits.reset(test::walkModel35()->model->clip, false);
    for (auto& [t, m] : moved) edits.set(t, EditRecord{edits.pose(t), Eigen::VectorXd(), m});
    return edits;
}
}  // namespace

TEST_CASE("held effectors: runs per effector, release of one run, release everywhere") {
    const ClipEdits edits = heldTestEdits({{10, {Effector::kRFoot}},
                                           {11, {Effector::kRFoot, Effector::kLHand}},
                                           {12, {Effector::kRFoot}},
                                           {14, {Effector::kRFoot}},
                                           {20, {}}});
    CHECK(isHeld(edits, 11, Effector::kLHand));
    CHECK_FALSE(isHeld(edits, 13, Effector::kRFoot));
    CHECK(heldOn(edits, 11) == std::vector<Effector>{Effector::kLHand, Effector::kRFoot});
    CHECK(heldOn(edits, 20).empty());
    CHECK(heldOn(edits, 50).empty());  // a captured frame holds nothing
    // Runs inside 0..13: the foot on 10..12 (14 is outside), the hand on 11; the excepted effector never.
    const std::vector<ContactInterval> runs = heldRuns(edits, 0, 13, Effector::kHead);
    REQUIRE(runs.size() == 2);
    CHECK((runs[0].foot == Effector::kLHand && runs[0].first == 11 && runs[0].last == 11));
    CHECK((runs[1].foot == Effector::kRFoot && runs[1].first == 10 && runs[1].last == 12));
    CHECK(heldRuns(edits, 0, 30, Effector::kRFoot).size() == 1);
    CHECK(heldRuns(edits, 11, 11, Effector::kHead).size() == 2);  // a run clipped to the window
    // Releasing the foot on frame 11 releases its run 10..12, not frame 14 beyond the gap; the hand stays.
    const FrameEdits release = releaseRun(edits, 11, Effector::kRFoot);
    REQUIRE(release.size() == 3);
    CHECK(release.begin()->first == 10);
    CHECK(release.rbegin()->first == 12);
    CHECK(release.at(11)->moved == std::vector<Effector>{Effector::kLHand});
    CHECK(releaseRun(edits, 13, Effector::kRFoot).empty());
    CHECK(releaseEverywhere(edits).size() == 4);  // frame 20 holds nothing already
    CHECK(withHeld({Effector::kHead}, {Effector::kLHand, Effector::kHead}) ==
          std::vector<Effector>{Effector::kLHand, Effector::kHead});
}

TEST_CASE("editor: a second drag on the same frame holds the first drag's hand, with no falloff") {
    // The user's sequence with falloff 0: drag the left hand forward, then drag the right hand up on
    // the same frame. The left hand was placed, so the second drag holds it exactly where it is
    // (before, only the locality term kept it, approximately); the frame then holds both. (A foot
    // would not show this on a planted frame: the contact holds it anyway.)
    EditorDocument doc;
    heldTestOpen(doc, 0);
    const int t = 140;
    const Skeleton& sk = doc.clip().skeleton;
    doc.setFrame(t);
    CHECK(doc.heldEffectors().empty());
    heldTestDrag(doc, Effector::kLHand, heldTestEffector(doc, t, Effector::kLHand) + Eigen::Vector3d(0, 5, 8));
    CHECK(doc.heldEffectors() == std::vector<Effector>{Effector::kLHand});
    const Eigen::Vector3d left = heldTestEffector(doc, t, Effector::kLHand);
    const Eigen::Vector3d right = heldTestEffector(doc, t, Effector::kRHand);
    const Eigen::Vector3d target = right + Eigen::Vector3d(0, 25, 10);
    heldTestDrag(doc, Effector::kRHand, target);
    const double leftMoved = (effectorCm(sk, doc.currentPose(), Effector::kLHand) - left).norm();
    MESSAGE("the held left hand moved " << leftMoved << " cm during the right hand's drag");
    CHECK(leftMoved < 0.01);
    CHECK((effectorCm(sk, doc.currentPose(), Effector::kRHand) - target).norm() < 0.05);
    CHECK(doc.heldEffectors() == std::vector<Effector>{Effector::kLHand, Effector::kRHand});
    // What a drag here holds: both hands, each once, where they are.
    const std::vector<IkConstraint> holds = doc.holdConstraints();
    REQUIRE(holds.size() == 2);
    CHECK((holds[0].targetCm - left).norm() < 0.01);
    // Undo brings back the state after the first drag: the left hand alone is held; redo both again.
    REQUIRE(doc.undo().empty());
    CHECK(doc.heldEffectors() == std::vector<Effector>{Effector::kLHand});
    REQUIRE(doc.redo().empty());
    CHECK(doc.heldEffectors() == std::vector<Effector>{Effector::kLHand, Effector::kRHand});
    // A pinned hand is held once, by its pin.
    doc.setPinned(Effector::kLHand, true);
    CHECK(doc.holdConstraints().size() == 2);
    doc.setPinned(Effector::kLHand, false);
    // The same right-hand drag with the left hand released first: it is no longer held, and moves.
    REQUIRE(doc.undo().empty());
    REQUIRE(doc.releaseHeld(Effector::kLHand).empty());
    CHECK(doc.undoLabel() == "release lhand on frame " + std::to_string(t + 1));
    CHECK(doc.heldEffectors().empty());
    heldTestDrag(doc, Effector::kRHand, target);
    const double unheld = (effectorCm(sk, doc.currentPose(), Effector::kLHand) - left).norm();
    MESSAGE("released first, the left hand moved " << unheld << " cm");
    CHECK(unheld > 10.0 * leftMoved);
}

TEST_CASE("editor: a foot placed by a drag's falloff stays through a later hand drag's falloff, until released") {
    // Foot up 15 cm on frame 140 spread over ±20 frames, then a hand drag on frame 150 spread over
    // ±20: on every frame both spreads cover, the foot stays where the first spread put it (≤ 1 cm).
    // Releasing the foot on frame 150 releases the whole run the first spread held, as one undo step.
    EditorDocument doc;
    heldTestOpen(doc, 20);
    const Skeleton& sk = doc.clip().skeleton;
    doc.setFrame(140);
    const std::string first =
        heldTestDrag(doc, Effector::kRFoot, heldTestEffector(doc, 140, Effector::kRFoot) + Eigen::Vector3d(0, 15, 0));
    REQUIRE(first.find(": spread over frames") != std::string::npos);
    std::map<int, Eigen::Vector3d> footBefore;
    for (int s = 121; s <= 159; ++s) {
        footBefore[s] = heldTestEffector(doc, s, Effector::kRFoot);
        CHECK(doc.held(Effector::kRFoot));  // every frame of the spread holds the foot
    }
    doc.setFrame(150);
    const std::string second =
        heldTestDrag(doc, Effector::kRHand, heldTestEffector(doc, 150, Effector::kRHand) + Eigen::Vector3d(0, 10, 5));
    REQUIRE(second.find(": spread over frames") != std::string::npos);
    double worst = 0.0;
    int worstFrame = -1;
    for (int s = 131; s <= 159; ++s) {
        const double moved = (heldTestEffector(doc, s, Effector::kRFoot) - footBefore[s]).norm();
        if (moved > worst) worst = moved, worstFrame = s + 1;
        CHECK(doc.held(Effector::kRFoot));
        CHECK(doc.held(Effector::kRHand));  // the hand's spread placed it too
    }
    MESSAGE("the held foot moved at most " << worst << " cm (frame " << worstFrame << ") during the hand's spread");
    CHECK(worst <= 1.0);
    // The same hand drag with the foot released first: the spread only starts from the edited
    // motion, nothing holds the foot, and it moves (what the holds are for).
    REQUIRE(doc.undo().empty());
    REQUIRE(doc.releaseAllHeld().empty());
    doc.setFrame(150);
    heldTestDrag(doc, Effector::kRHand, heldTestEffector(doc, 150, Effector::kRHand) + Eigen::Vector3d(0, 10, 5));
    const double unheld = heldTestLargestMove(doc, Effector::kRFoot, footBefore, 131, 159);
    MESSAGE("released first, the foot moved up to " << unheld << " cm");
    CHECK(unheld > 10.0 * worst);
    REQUIRE(doc.undo().empty());  // the unheld hand drag
    REQUIRE(doc.undo().empty());  // the release
    REQUIRE(doc.redo().empty());  // the release again …
    REQUIRE(doc.undo().empty());  // … and back: the foot held, the hand drag undone
    doc.setFrame(150);
    REQUIRE(doc.held(Effector::kRFoot));
    heldTestDrag(doc, Effector::kRHand, heldTestEffector(doc, 150, Effector::kRHand) + Eigen::Vector3d(0, 10, 5));
    // Release the foot where the user is (frame 150): its run over the first spread lets go.
    doc.setFrame(150);
    const int undoBefore = doc.history().undoCount();
    REQUIRE(doc.releaseHeld(Effector::kRFoot).empty());
    CHECK(doc.history().undoCount() == undoBefore + 1);
    for (int s = 115; s <= 165; ++s) {
        doc.setFrame(s);
        CHECK_FALSE(doc.held(Effector::kRFoot));
    }
    doc.setFrame(150);
    CHECK(doc.held(Effector::kRHand));
    CHECK_FALSE(doc.releaseHeld(Effector::kRFoot).empty());  // nothing left to release: says so
    REQUIRE(doc.undo().empty());
    doc.setFrame(150);
    CHECK(doc.held(Effector::kRFoot));
    // Release everything: nothing is held anywhere, one step; the poses are untouched.
    const Pose pose150 = doc.currentPose();
    REQUIRE(doc.releaseAllHeld().empty());
    for (int s = 120; s <= 170; ++s) {
        doc.setFrame(s);
        CHECK(doc.heldEffectors().empty());
    }
    doc.setFrame(150);
    CHECK(doc.currentPose().anglesDeg[sk.findBone("rfemur")] == pose150.anglesDeg[sk.findBone("rfemur")]);
    CHECK_FALSE(doc.releaseAllHeld().empty());
}

TEST_CASE("rotate joint holds a placed hand unless the rotated joint is above it") {
    EditorDocument doc;
    heldTestOpen(doc, 0);
    const int t = 140;
    doc.setFrame(t);
    heldTestDrag(doc, Effector::kRHand, heldTestEffector(doc, t, Effector::kRHand) + Eigen::Vector3d(0, 6, 4));
    REQUIRE(doc.held(Effector::kRHand));
    const Skeleton& sk = doc.clip().skeleton;
    auto holdsRHand = [&](const char* bone) {
        const std::vector<IkConstraint> holds = rotationHolds(doc, sk.findBone(bone));
        return std::count_if(holds.begin(), holds.end(),
                             [](const IkConstraint& c) { return c.effector == Effector::kRHand; });
    };
    CHECK(holdsRHand("rradius") == 0);  // the elbow carries the hand: it moves with the rotation
    CHECK(holdsRHand("lfemur") == 1);   // the other leg: the hand stays
    doc.setPinned(Effector::kRHand, true);
    CHECK(holdsRHand("rradius") == 1);  // a pin holds wherever it is
    // Each planted foot once, whether a contact, a placement or both hold it.
    for (Effector foot : {Effector::kLFoot, Effector::kRFoot}) {
        const std::vector<IkConstraint> holds = rotationHolds(doc, sk.findBone("rradius"));
        CHECK(std::count_if(holds.begin(), holds.end(), [&](const IkConstraint& c) { return c.effector == foot; }) <=
              1);
    }
}

TEST_CASE(
    "hands placed on a frame move with the chest rotated there with the prior, and their neighbours follow them") {
    // The rotation solves with the frame's holds except the hands below the chest (rotationMovers):
    // on the rotated frame both go where the chest takes them. The spread re-solves one effector's
    // displaced path (the most moved hand) and holds the frame's other holds where they were, except
    // the other hand, held where the rotation's layer carries it (EditBase::followLayer): the
    // neighbours do not hold it back at its old place.
    EditorDocument doc;
    heldTestOpen(doc, 20);
    const int t = 140;
    doc.setFrame(t);
    for (Effector hand : {Effector::kRHand, Effector::kLHand}) {
        doc.setFrame(t);
        heldTestDrag(doc, hand, heldTestEffector(doc, t, hand) + Eigen::Vector3d(0, 6, 4));
    }
    REQUIRE(doc.held(Effector::kRHand));
    REQUIRE(doc.held(Effector::kLHand));
    const Skeleton& sk = doc.clip().skeleton;
    const int chest = sk.findBone("thorax");
    REQUIRE(chest >= 0);
    std::vector<Effector> movers = rotationMovers(doc, chest);
    std::sort(movers.begin(), movers.end());
    CHECK(movers == std::vector<Effector>{Effector::kLHand, Effector::kRHand});
    CHECK(rotationMovers(doc, sk.findBone("lfemur")).empty());
    Eigen::Vector3d placed[2];
    for (int h = 0; h < 2; ++h) placed[h] = heldTestEffector(doc, t, h == 0 ? Effector::kLHand : Effector::kRHand);
    doc.setFrame(t);
    JointRotation r;
    r.joint = chest;
    r.anglesDeg = doc.currentPose().anglesDeg[chest] + Eigen::Vector3d(0, 25, 0);
    r.followPrior = true;
    REQUIRE(applyJointRotation(doc, r) == "");
    doc.waitIdle();
    CHECK(doc.pollRegenerate().find(": spread over frames") != std::string::npos);
    for (int h = 0; h < 2; ++h) {
        const Effector hand = h == 0 ? Effector::kLHand : Effector::kRHand;
        INFO(std::string(effectorName(hand)));
        const Eigen::Vector3d rotated = heldTestEffector(doc, t, hand);
        const double moved = (rotated - placed[h]).norm();
        REQUIRE(moved > 5.0);
        // Its one-frame steps next to the rotated frame stay a fraction of that move (the spread's
        // blend, not a jump back to the old place).
        const double before = (rotated - heldTestEffector(doc, t - 1, hand)).norm();
        const double after = (heldTestEffector(doc, t + 1, hand) - rotated).norm();
        MESSAGE(std::string(effectorName(hand)) << " moved " << moved << " cm; steps next to the rotated frame "
                                                << before << " and " << after << " cm");
        CHECK(before < 0.25 * moved);
        CHECK(after < 0.25 * moved);
        CHECK(doc.held(hand));  // still placed, where the rotation put it
    }
}

TEST_CASE(
    "editor: a foot placed by a drag stays through a later path regeneration of the hand, which still meets its keys") {
    // Frames 0-based. Foot up 15 cm on frame 140 spread over ±20 frames (121..159 hold it), then
    // the right hand's path around frame 140 (keys 119, 133, 147, 161) raised 12 cm and regenerated
    // from the capture: the foot stays where the drag put it on every frame it is held (≤ 1 cm),
    // the records there still hold it, and the hand meets its keys. Released first, the
    // regeneration brings the foot back to the capture.
    EditorDocument doc;
    heldTestOpen(doc, 20);
    doc.setFrame(140);
    heldTestDrag(doc, Effector::kRFoot, heldTestEffector(doc, 140, Effector::kRFoot) + Eigen::Vector3d(0, 15, 0));
    const std::map<int, Eigen::Vector3d> footBefore = heldTestPositions(doc, Effector::kRFoot, 121, 159);
    heldTestRaiseRightHandPath(doc);
    double worst = 0.0;
    int worstFrame = -1;
    for (int s = 121; s <= 159; ++s) {
        const double moved = (heldTestEffector(doc, s, Effector::kRFoot) - footBefore.at(s)).norm();
        if (moved > worst) worst = moved, worstFrame = s + 1;
        CHECK(doc.held(Effector::kRFoot));
    }
    MESSAGE("the held foot moved at most " << worst << " cm (frame " << worstFrame
                                           << ") during the hand's regeneration");
    CHECK(worst <= 1.0);
    // Without the hold the regeneration re-solves the foot from the capture: it drops back.
    REQUIRE(doc.undo().empty());
    REQUIRE(doc.releaseAllHeld().empty());
    doc.paths().end();
    heldTestRaiseRightHandPath(doc);
    const double unheld = heldTestLargestMove(doc, Effector::kRFoot, footBefore, 121, 159);
    MESSAGE("released first, the foot moved up to " << unheld << " cm");
    CHECK(unheld > 10.0);
}

TEST_CASE(
    "editor: where a placed foot's hold ends inside a regenerated path span, the foot's motion stays as smooth as the "
    "capture's") {
    // Frames 0-based. Foot up 10 cm on frame 135 spread over ±8 frames (128..142 hold it), inside
    // the right hand's path span 119..161: the foot stays placed on 128..142 and is re-solved from
    // the capture elsewhere. Its second difference stays within the capture's largest plus 0.5 cm
    // on every frame of the span and next to it.
    EditorDocument doc;
    heldTestOpen(doc, 8);
    doc.setFrame(135);
    heldTestDrag(doc, Effector::kRFoot, heldTestEffector(doc, 135, Effector::kRFoot) + Eigen::Vector3d(0, 10, 0));
    for (int s = 120; s <= 160; ++s) {
        doc.setFrame(s);
        CHECK(doc.held(Effector::kRFoot) == (s >= 128 && s <= 142));
    }
    const std::map<int, Eigen::Vector3d> footBefore = heldTestPositions(doc, Effector::kRFoot, 128, 142);
    heldTestRaiseRightHandPath(doc);
    const double held = heldTestLargestMove(doc, Effector::kRFoot, footBefore, 128, 142);
    CHECK(held <= 1.0);
    const Skeleton& sk = doc.clip().skeleton;
    double edited = 0.0, captured = 0.0;
    int worstFrame = -1;
    const auto editedAt = [&](int s) { return heldTestEffector(doc, s, Effector::kRFoot); };
    const auto capturedAt = [&](int s) {
        return effectorCm(sk, doc.clip().frames[static_cast<std::size_t>(s)], Effector::kRFoot);
    };
    for (int s = 118; s <= 162; ++s) {
        const double e = test::positionSecondDifferenceCm(editedAt, s);
        if (e > edited) edited = e, worstFrame = s + 1;
        captured = std::max(captured, test::positionSecondDifferenceCm(capturedAt, s));
    }
    MESSAGE("held foot moved at most " << held << " cm; its largest second difference " << edited << " cm (frame "
                                       << worstFrame << "), the capture's " << captured << " cm");
    CHECK(edited <= captured + 0.5);
}
