// Fill between keys in the editor, driven by real key presses offscreen with the committed walk
// model: K marks keys, Ctrl+I regenerates the frames between the two keys around the playhead in
// the background (motion/inbetween.h), the keys and everything outside stay, one undo step takes
// it all back and redo brings it again; without keys or a model the editor says why.
#include <doctest/doctest.h>

#include <string>

#include "editor_harness.h"
#include "skeleton/pose_layout.h"
#include "ui/input/input_state.h"
#include "ui/shell/editor_app.h"

using namespace mgp;
using test::makeHarness;

namespace {
bool contains(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }
}  // namespace

TEST_CASE("gui fill between keys: K marks keys, Ctrl+I fills the gap around the playhead, one undo step") {
    auto h = makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    REQUIRE(doc.hasModel());
    // No keys yet: Ctrl+I says what it needs.
    doc.setFrame(130);
    h->frame(2);
    test::tapKey(*h, 'I', {ui::key::kLeftCtrl});
    CHECK(contains(s.messages.latestText(), "expected a key before the playhead and one after it"));
    CHECK_FALSE(doc.filling());

    for (int f : {100, 160}) {
        doc.setFrame(f);
        h->frame(2);
        test::tapKey(*h, 'K');
    }
    REQUIRE(doc.keys() == std::set<int>{100, 160});
    doc.setFrame(130);
    h->frame(2);
    REQUIRE(doc.keyGapAt(130));
    CHECK(doc.keyGapAt(130)->a == 100);
    CHECK(doc.keyGapAt(130)->b == 160);
    test::tapKey(*h, 'I', {ui::key::kLeftCtrl});
    doc.waitIdle();
    h->frame(3);
    CHECK_FALSE(doc.filling());
    INFO("status: " << s.messages.latestText());
    CHECK(contains(s.messages.latestText(), "filled frames 102-160"));
    const Clip& clip = doc.clip();
    int changed = 0;
    for (int t = 0; t < doc.frameCount(); ++t) {
        const bool inner = t > 100 && t < 160;
        if (!inner)
            CHECK(posesIdentical(doc.poseAt(t), clip.frames[t]));
        else
            changed += doc.isEdited(t) ? 1 : 0;
    }
    CHECK(changed == 59);
    CHECK(doc.undoLabel() == "fill frames 102-160");
    // One undo takes the whole fill back; redo brings it again.
    test::tapKey(*h, 'Z', {ui::key::kLeftCtrl});
    CHECK(doc.edits().empty());
    test::tapKey(*h, 'Z', {ui::key::kLeftCtrl, ui::key::kLeftShift});
    CHECK(doc.edits().size() == 59u);
    // While a fill runs, a drag waits (the fill would overwrite it): refused with a reason.
    REQUIRE(doc.startFill() == "");
    CHECK(doc.filling());
    CHECK(doc.beginDrag(Effector::kRHand) == "a fill between keys is running: wait for it or cancel it");
    CHECK_FALSE(doc.beginLatentDrag());
    doc.waitIdle();
    h->frame(3);
    CHECK(doc.undoLabel() == "fill frames 102-160");  // the second fill is its own step
    test::tapKey(*h, 'Z', {ui::key::kLeftCtrl});
    CHECK(doc.edits().size() == 59u);
    // View > Interpolation between keys: a yellow ghost of the keys' plain interpolation inside the gap.
    doc.setFrame(130);
    h->frame(2);
    const std::size_t figures = h->app->viewport().lastScene().figures.size();
    s.showInterpolationGhost = true;
    h->app->requestRedraw();
    h->frame(2);
    const render::Scene& scene = h->app->viewport().lastScene();
    REQUIRE(scene.figures.size() == figures + 1);
    CHECK(scene.figures.back().ghost);
    CHECK(scene.figures.back().ghostTint == glm::vec3(0.95f, 0.8f, 0.25f));
    s.showInterpolationGhost = false;
    // K on a key unmarks it; the gap is gone.
    doc.setFrame(160);
    h->frame(2);
    test::tapKey(*h, 'K');
    CHECK(doc.keys() == std::set<int>{100});
    CHECK_FALSE(doc.keyGapAt(130));
}

TEST_CASE("gui fill between keys: a Shift+drag range on the timeline fills every gap between the keys inside it") {
    auto h = makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    for (int f : {40, 100, 101, 160, 250}) doc.toggleKey(f);
    h->frame(2);
    // A real Shift+drag over the timeline track, from about frame 30 to about frame 200 (the
    // track maps frames 1..358 linearly onto its width, less 8 px at each end).
    REQUIRE(s.controls.count("timeline track"));
    const ui::EditorState::ControlRect track = s.controls.at("timeline track");
    const float y = 0.5f * (track.y0 + track.y1);
    auto xOf = [&](int f) {
        return track.x0 + 8.0f + (track.x1 - track.x0 - 16.0f) * float(f) / float(doc.frameCount() - 1);
    };
    const int frameBefore = doc.frame();
    const std::vector<std::string> errors =
        h->play(ui::GuiScript::parse("0 keydown SHIFT\n1 move " + std::to_string(int(xOf(30))) + " " +
                                     std::to_string(int(y)) + "\n3 down left\n5 move " + std::to_string(int(xOf(200))) +
                                     " " + std::to_string(int(y)) + "\n7 up left\n9 keyup SHIFT\n"));
    REQUIRE(errors.empty());
    REQUIRE(s.timelineRange);
    CHECK(doc.frame() == frameBefore);  // selecting does not scrub
    INFO("range " << s.timelineRange->first << ".." << s.timelineRange->second);
    // The gaps inside: 40-100 and 101-160 (100-101 has no frame between); 160-250 only if the range reaches 250.
    const std::vector<InbetweenGap> gaps = doc.keyGapsIn(s.timelineRange->first, s.timelineRange->second);
    REQUIRE(gaps.size() >= 2u);
    CHECK(gaps[0].a == 40);
    CHECK(gaps[0].b == 100);
    CHECK(gaps[1].a == 101);
    CHECK(gaps[1].b == 160);
    // Scripted, exactly: frames 30..200.
    REQUIRE(h->app->runAction({"timeline-range", "30", "200"}) == "");
    REQUIRE(h->app->runAction({"fill-between-keys"}) == "");
    doc.waitIdle();
    h->frame(3);
    CHECK(contains(s.messages.latestText(), "filled frames 42-160, 2 gaps"));
    CHECK(doc.edits().size() == 59u + 58u);
    for (int f : {40, 100, 101, 160}) CHECK_FALSE(doc.isEdited(f));
    CHECK(doc.undoLabel() == "fill frames 42-160");
    REQUIRE(doc.undo() == "");
    CHECK(doc.edits().empty());
    CHECK(h->app->runAction({"timeline-range", "0", "5"}).find("expected 1 ≤ FIRST ≤ LAST") == 0);
    REQUIRE(h->app->runAction({"timeline-range", "off"}) == "");
    CHECK_FALSE(s.timelineRange);
}

TEST_CASE("gui fill between keys: without a model the editor says so") {
    auto h = makeHarness(false, false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    REQUIRE_FALSE(doc.hasModel());
    doc.toggleKey(20);
    doc.toggleKey(80);
    doc.setFrame(50);
    h->frame(2);
    test::tapKey(*h, 'I', {ui::key::kLeftCtrl});
    CHECK(contains(s.messages.latestText(), "needs a model"));
    CHECK(doc.edits().empty());
}
