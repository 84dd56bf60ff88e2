// Editor input tests (label `gl`), offscreen: taps shorter than a frame (the input replay),
// modifier-exact shortcuts, Esc on menus, keys blocked by a modal, the save dialog's focused
// default name, status messages that follow the state, copy/paste pose, and the axis-held
// handle drag with its offset readout.
#include <doctest/doctest.h>
#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <initializer_list>

#include "editor_harness.h"
#include "skip.h"
#include "ui/input/gui_script.h"
#include "ui/input/input_state.h"
#include "ui/shell/editor_app.h"

using namespace mgp;
using test::tapKey;

namespace {

using test::Harness;
namespace key = ui::key;

// Press and release within one frame, as `xdotool click` does (clickAt in the harness spreads them).
void quickClick(Harness& h, float x, float y) {
    h.input.mouseX = x;
    h.input.mouseY = y;
    h.frame(2);  // hover first
    h.input.setButton(0, true);
    h.input.setButton(0, false);
    h.frame(3);
}

constexpr float kFileMenuX = 20.0f, kMenuY = 8.0f;  // the "File" title of the menu bar

bool sameAngles(const Pose& a, const Pose& b) {
    if (a.anglesDeg.size() != b.anglesDeg.size()) return false;
    for (std::size_t i = 0; i < a.anglesDeg.size(); ++i)
        if (a.anglesDeg[i] != b.anglesDeg[i]) return false;
    return true;
}

}  // namespace

TEST_CASE("gui input: a click shorter than one frame opens a menu, and Esc closes it") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    // The old way (state only, no events): down and up before the frame, so ImGui never sees it.
    h->input.mouseX = kFileMenuX;
    h->input.mouseY = kMenuY;
    h->frame(2);
    h->input.mouseDown[0] = true;
    h->input.mouseDown[0] = false;
    h->frame(3);
    REQUIRE_FALSE(h->app->popupOpen());
    // Through the event queue: the same tap is replayed over two frames.
    quickClick(*h, kFileMenuX, kMenuY);
    CHECK(h->app->popupOpen());
    tapKey(*h, key::kEscape);
    CHECK_FALSE(h->app->popupOpen());
}

TEST_CASE(
    "gui input: a key tap shorter than one frame steps the timeline, and Ctrl+O tapped at once opens the dialog") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    doc.setFrame(10);
    h->frame(2);
    tapKey(*h, key::kRight);
    CHECK(doc.frame() == 11);
    tapKey(*h, key::kRight, {key::kLeftShift});
    CHECK(doc.frame() == 21);
    // Ctrl down, O down, O up, Ctrl up, all before one frame (xdotool key ctrl+o).
    tapKey(*h, 'O', {key::kLeftCtrl});
    CHECK(h->app->fileDialog().isOpen());
}

TEST_CASE("gui input: Ctrl released before the key in one frame (X11's order for a quick tap) is still Ctrl+Y") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    h->frame(2);
    REQUIRE(h->app->state().messages.latestText() != "nothing to redo");
    // Ctrl+Y with nothing to redo says so. The order GLFW reported under Xvfb for a tap: Ctrl↓
    // (a frame), then Y↓ Ctrl↑ Y↑ before the next frame.
    h->input.setKey(key::kLeftCtrl, true);
    h->frame(1);
    h->input.setKey('Y', true);
    h->input.setKey(key::kLeftCtrl, false);
    h->input.setKey('Y', false);
    h->frame(4);
    CHECK(h->app->state().messages.latestText() == "nothing to redo");
}

TEST_CASE("gui input: shortcuts match their modifiers exactly") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    tapKey(*h, 'O', {key::kLeftCtrl, key::kLeftAlt});
    CHECK_FALSE(h->app->fileDialog().isOpen());
    tapKey(*h, 'O', {key::kLeftCtrl, key::kLeftShift});
    CHECK_FALSE(h->app->fileDialog().isOpen());
    tapKey(*h, 'T', {key::kLeftCtrl, key::kLeftAlt});
    h->frame(2);
    CHECK_FALSE(h->app->state().training.running());
    doc.setFrame(10);
    tapKey(*h, key::kRight, {key::kLeftAlt});
    tapKey(*h, key::kRight, {key::kLeftCtrl});
    CHECK(doc.frame() == 10);
    tapKey(*h, 'O', {key::kLeftCtrl});
    CHECK(h->app->fileDialog().isOpen());
}

TEST_CASE(
    "gui input: Save session as opens with a default name in a focused field, a modal keeps P from pinning, P pins "
    "only the handle under the mouse") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    tapKey(*h, 'S', {key::kLeftCtrl, key::kLeftShift});
    REQUIRE(h->app->fileDialog().isOpen());
    CHECK(std::string(h->app->fileDialog().typedPath()) == "35_01.mgsession");
    CHECK(ImGui::GetIO().WantTextInput);  // the name field has the keyboard
    tapKey(*h, key::kEscape);
    CHECK_FALSE(h->app->fileDialog().isOpen());

    // Unsaved changes, then Quit: the modal question is up; P must not reach the viewport.
    s.selected = Effector::kRHand;
    REQUIRE(h->app->runAction({"copy-pose"}) == "");
    s.doc.setFrame(40);
    REQUIRE(h->app->runAction({"paste-pose"}) == "");
    h->app->requestQuit();
    h->frame(3);
    REQUIRE(h->app->askingAboutUnsavedChanges());
    tapKey(*h, 'P');
    CHECK_FALSE(s.doc.pinned(Effector::kRHand));
    tapKey(*h, key::kEscape);  // Cancel
    CHECK_FALSE(h->app->askingAboutUnsavedChanges());
    CHECK_FALSE(h->app->quitRequested());
    tapKey(*h, 'P');  // no modal now, but the mouse is not over a handle: nothing is pinned
    CHECK_FALSE(s.doc.pinned(Effector::kRHand));
    CHECK(s.messages.latestText().find("P pins the handle under the mouse") == 0);
    float x = 0, y = 0;
    REQUIRE(h->app->handleScreenPosition(Effector::kRHand, x, y));
    h->input.mouseX = x;
    h->input.mouseY = y;
    h->frame(2);
    REQUIRE(s.hoveredHandle == int(Effector::kRHand));
    tapKey(*h, 'P');  // over the handle: it pins
    CHECK(s.doc.pinned(Effector::kRHand));
}

TEST_CASE("gui input: status messages follow the state they describe and stay in the history") {
    auto h = test::makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;

    // A red "nothing to undo" goes once the document changes (here a paste), not only by time.
    tapKey(*h, 'Z', {key::kLeftCtrl});
    REQUIRE(s.messages.current() != nullptr);
    CHECK(s.messages.current()->error);
    CHECK(s.messages.current()->text == "nothing to undo");
    doc.setFrame(40);
    REQUIRE(doc.pastePose(doc.clip().frames[10]) == "");
    h->frame(1);
    CHECK(s.messages.current() == nullptr);

    // "accepted … (adaptive update running)" becomes "… done" once the update has finished.
    REQUIRE(doc.undo() == "");
    doc.setDragFalloff(0);          // this frame only: no spread job posts its own message
    doc.holdAdaptiveUpdates(true);  // the update stays pending until released below
    const auto errors = h->play(ui::GuiScript::parse("2 hover rhand\n4 down left\n6 moveby 0 -2\n10 up left\n"));
    REQUIRE(errors.empty());
    const std::string during = s.messages.latestText();
    INFO("after the release: " << during << "  adaptive: " << doc.models().status());
    CHECK(during == "accepted pose for frame 41 (adaptive update running)");
    h->frame(3);
    CHECK(s.messages.latestText() == "accepted pose for frame 41 (adaptive update running)");  // still pending
    doc.holdAdaptiveUpdates(false);
    h->app->waitIdle();
    h->frame(2);
    REQUIRE(s.messages.current() != nullptr);
    CHECK(s.messages.current()->text == "accepted pose for frame 41 (adaptive update done)");

    // An informational message expires after a while.
    h->app->frame(h->input, ui::MessageLog::kInfoSeconds + 1.0, test::kGuiWidth, test::kGuiHeight);
    CHECK(s.messages.current() == nullptr);

    // Training: "training…" while it runs, and it says it stopped after Cancel.
    s.trainOptions.activeSize = 30;
    REQUIRE(h->app->startTraining() == "");
    test::answerUnsaved(*h, "Don't save");  // the model taught the accepted pose: no file holds it
    h->frame(1);
    REQUIRE(s.messages.current() != nullptr);
    CHECK(s.messages.current()->text.find("training") == 0);
    s.training.cancel();
    s.training.join();
    h->frame(2);
    REQUIRE(s.messages.current() != nullptr);
    CHECK(s.messages.current()->text.find("training stopped") == 0);

    // View > Messages keeps them all, the expired ones too.
    bool sawUndo = false, sawAccepted = false;
    for (const ui::StatusMessage& m : s.messages.history()) {
        sawUndo |= m.text == "nothing to undo";
        sawAccepted |= m.text.find("accepted pose") == 0;
    }
    CHECK(sawUndo);
    CHECK(sawAccepted);
}

TEST_CASE("gui input: copy a pose, paste it on another frame (root kept), one undo step") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    EditorDocument& doc = h->app->state().doc;
    doc.setFrame(10);
    h->frame(1);
    tapKey(*h, 'C', {key::kLeftCtrl});
    const Pose copied = doc.currentPose();
    doc.setFrame(60);
    h->frame(1);
    const Eigen::Vector3d root60 = doc.currentPose().rootCm;
    tapKey(*h, 'V', {key::kLeftCtrl});
    REQUIRE(doc.isEdited(60));
    CHECK(sameAngles(doc.currentPose(), copied));
    CHECK(doc.currentPose().rootCm == root60);
    CHECK(doc.undoLabel() == "paste pose on frame 61");
    tapKey(*h, 'Z', {key::kLeftCtrl});
    CHECK_FALSE(doc.isEdited(60));
    // The status line says what went (it showed what the paste had said).
    const auto* said = h->app->state().messages.current();
    REQUIRE(said != nullptr);
    CHECK(said->text == "undid paste pose on frame 61");
    tapKey(*h, 'Z', {key::kLeftCtrl, key::kLeftShift});
    CHECK(doc.isEdited(60));
    REQUIRE(h->app->state().messages.current() != nullptr);
    CHECK(h->app->state().messages.current()->text == "redid paste pose on frame 61");
}

TEST_CASE(
    "gui input: X or Y during a handle drag holds the target on that world axis, and the readout shows the offset in "
    "cm") {
    auto h = test::makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    for (const char axis : {'X', 'Y'}) {
        const int a = axis == 'X' ? 0 : 1;
        auto errors = h->play(ui::GuiScript::parse(std::string("2 hover rhand\n4 down left\n6 moveby 0 -6\n8 key ") +
                                                   axis + "\n10 moveby 25 -30\n12 moveby 10 -10\n"));
        REQUIRE(errors.empty());
        REQUIRE(doc.dragging());
        CHECK(s.dragAxis == a);
        const Eigen::Vector3d d = doc.dragTarget() - s.dragStartCm;
        INFO(axis << ": offset " << d.transpose() << "  readout " << s.dragReadout);
        CHECK(std::abs(d[a]) > 1.0);
        for (int o = 0; o < 3; ++o)
            if (o != a) CHECK(std::abs(d[o]) < 1e-9);
        char expected[32];
        std::snprintf(expected, sizeof expected, "d%c %+.1f", axis, d[a]);
        CHECK(s.dragReadout.find(std::string("along ") + axis) == 0);
        CHECK(s.dragReadout.find(expected) != std::string::npos);
        h->input.setButton(0, false);
        h->frame(3);
        CHECK_FALSE(doc.dragging());
        CHECK(s.dragReadout.empty());
        h->app->waitIdle();
    }
}
