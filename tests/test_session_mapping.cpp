// The document's half of a session (core/session/session_mapping.h), both ways, without GL.
#include <doctest/doctest.h>

#include "document_helpers.h"
#include "io/parse_error.h"
#include "session/session_mapping.h"
#include "skeleton/synthetic_clip.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("session mapping: compare-mode names both ways, and only the three") {
    for (CompareMode m : {CompareMode::kNone, CompareMode::kPlainIk, CompareMode::kSecondModel}) {
        CompareMode back = CompareMode::kNone;
        REQUIRE(parseCompareMode(compareModeName(m), back));
        CHECK(back == m);
    }
    CHECK(std::string(compareModeName(CompareMode::kPlainIk)) == "plain");
    CHECK(std::string(compareModeName(CompareMode::kSecondModel)) == "model");
    CompareMode untouched = CompareMode::kPlainIk;
    CHECK(!parseCompareMode("Plain", untouched));
    CHECK(!parseCompareMode("", untouched));
    CHECK(untouched == CompareMode::kPlainIk);
}

TEST_CASE("session mapping: a document's edits, frame, pins, compare mode and path survive the round trip") {
    EditorDocument doc;
    doc.setClip(makeSyntheticWalk(), true);
    doc.setFrame(30);
    test::dragBy(doc, Effector::kRHand, Eigen::Vector3d(0, 6, 0));
    REQUIRE(doc.isEdited(30));
    doc.setPinned(Effector::kLFoot, true);
    doc.setCompareMode(CompareMode::kPlainIk);
    doc.setAdaptiveEnabled(false);
    REQUIRE(doc.beginPathEdit(Effector::kRFoot) == "");
    REQUIRE(doc.paths().setKeyOffset(1, Eigen::Vector3d(0, 3, 0)) == "");

    const SessionData d = sessionFromDocument(doc);
    CHECK(d.syntheticClip);
    CHECK(d.clipPath.empty());
    CHECK(d.frame == doc.frame());
    CHECK(d.compareMode == "plain");
    CHECK(!d.adaptiveEnabled);
    CHECK(d.pins[static_cast<int>(Effector::kLFoot)]);
    CHECK(!d.pins[static_cast<int>(Effector::kRHand)]);
    CHECK(d.edits.size() == doc.edits().size());
    REQUIRE(d.path.present);
    CHECK(d.path.keyFrames == doc.paths().edit()->keyFrames);

    // Through the file's text, as a real save and open.
    const SessionData read = sessionFromJsonText(sessionToJsonText(d, "/tmp/x.mgsession"), "x.mgsession");
    EditorDocument back;
    CheckedSession checked = checkSession(read, "x.mgsession");
    applySession(back, checked, "x.mgsession");
    CHECK(back.synthetic());
    CHECK(back.frame() == doc.frame());
    CHECK(back.compareMode() == CompareMode::kPlainIk);
    CHECK(!back.models().adaptiveEnabled());
    CHECK(back.pinned(Effector::kLFoot));
    REQUIRE(back.edits().size() == doc.edits().size());
    for (const auto& [frame, record] : doc.edits()) {
        REQUIRE(back.isEdited(frame));
        CHECK(posesIdentical(back.edits().at(frame).pose, record.pose));
    }
    REQUIRE(back.paths().edit());
    CHECK(back.paths().edit()->keyFrames == doc.paths().edit()->keyFrames);
    CHECK(back.paths().edit()->keyOffsetsCm[1].isApprox(doc.paths().edit()->keyOffsetsCm[1]));
    CHECK(posesIdentical(back.currentPose(), doc.currentPose()));
}

TEST_CASE("session mapping: a path outside the clip is refused before the document changes") {
    EditorDocument doc;
    doc.setClip(makeSyntheticWalk(), true);
    SessionData d = sessionFromDocument(doc);
    d.path.present = true;
    d.path.effector = Effector::kRFoot;
    d.path.keyFrames = {10, 20, 100000};
    d.path.keyOffsetsCm.assign(3, Eigen::Vector3d::Zero());
    CHECK_THROWS_AS(checkSession(d, "bad.mgsession"), ParseError);
    d.path.keyFrames = {10, 20, 30};
    d.path.keyOffsetsCm.assign(2, Eigen::Vector3d::Zero());
    CHECK_THROWS_WITH_AS(checkSession(d, "bad.mgsession"), "bad.mgsession: path: expected one offset per key",
                         ParseError);
}

TEST_CASE("session mapping: the undo history and the adaptive table come back with the session") {
    EditorDocument doc;
    doc.setModel(test::walkModel35(), true);
    doc.setFrame(40);
    test::dragBy(doc, Effector::kRHand, Eigen::Vector3d(0, 5, 0));
    doc.setFrame(80);
    test::dragBy(doc, Effector::kLHand, Eigen::Vector3d(0, 4, 2));
    doc.waitIdle();
    doc.pollRegenerate();  // the drag's falloff joins its step (it re-solves frame 80 too)
    REQUIRE(doc.canUndo());
    const Pose dragged80 = doc.edits().at(80).pose;
    REQUIRE(doc.undo() == "");  // the second drag goes to the redo stack
    REQUIRE(doc.canRedo());
    const std::string undoLabel = doc.undoLabel(), redoLabel = doc.redoLabel();
    const std::vector<AdaptiveHistoryEntry> table = doc.models().history();
    REQUIRE_FALSE(table.empty());

    const SessionData read =
        sessionFromJsonText(sessionToJsonText(sessionFromDocument(doc), "/tmp/h.mgsession"), "h.mgsession");
    EditorDocument back;
    CheckedSession checked = checkSession(read, "h.mgsession");
    applySession(back, checked, "h.mgsession");
    CHECK(back.undoLabel() == undoLabel);
    CHECK(back.redoLabel() == redoLabel);
    const std::vector<AdaptiveHistoryEntry> tableBack = back.models().history();
    REQUIRE(tableBack.size() == table.size());
    for (std::size_t i = 0; i < table.size(); ++i) {
        CHECK(tableBack[i].frame == table[i].frame);
        CHECK(tableBack[i].accepted == table[i].accepted);
        CHECK(tableBack[i].diagnostic == table[i].diagnostic);
        CHECK(tableBack[i].versionAfter == table[i].versionAfter);
    }
    // Undo and redo act on the frames as before the save; the model stays the one the session saved.
    const int version = back.model()->number;
    REQUIRE(back.isEdited(40));
    REQUIRE_FALSE(back.isEdited(80));
    REQUIRE(back.redo() == "");
    CHECK(back.isEdited(80));
    CHECK(posesIdentical(back.edits().at(80).pose, dragged80));
    REQUIRE(back.undo() == "");
    REQUIRE(back.undo() == "");
    CHECK_FALSE(back.isEdited(40));
    CHECK_FALSE(back.isEdited(80));
    CHECK(back.model()->number == version);
    CHECK(back.undo() == "nothing to undo");
}
