// The range tint's steadied verdict (edit/steady_verdict.h): the majority rule on the flicker
// patterns measured through regenerated spans, then the document on hand-made edits of the walk.
#include <doctest/doctest.h>

#include <string>

#include "edit/editor_document.h"
#include "edit/steady_verdict.h"
#include "ik/learned_ik.h"
#include "trained_model_fixture.h"

using namespace mgp;

namespace {

// "nnuR" → natural, natural, unusual, refused.
std::vector<VerdictClass> classesOf(const std::string& s) {
    std::vector<VerdictClass> out;
    for (char c : s)
        out.push_back(c == 'n' ? VerdictClass::kNatural : c == 'u' ? VerdictClass::kUnusual : VerdictClass::kRefused);
    return out;
}

// Each frame's shown class over a whole span, its window clipped to ±2 frames as the document does.
std::string steadied(const std::string& span) {
    const std::vector<VerdictClass> all = classesOf(span);
    std::string out;
    for (std::size_t t = 0; t < all.size(); ++t) {
        const std::size_t a = t >= 2 ? t - 2 : 0, b = std::min(all.size() - 1, t + 2);
        const std::vector<VerdictClass> window(all.begin() + static_cast<std::ptrdiff_t>(a),
                                               all.begin() + static_cast<std::ptrdiff_t>(b) + 1);
        const VerdictClass c = steadyClass(window, t - a);
        out += c == VerdictClass::kNatural ? 'n' : c == VerdictClass::kUnusual ? 'u' : 'R';
    }
    return out;
}

}  // namespace

TEST_CASE("steady verdict: one- and two-frame blips take their neighbours' class, a ramp and a held class stay") {
    // The three spans that blinked (of 70 measured), each now changing class once.
    CHECK(steadied("nnnnnnnRRnnRRRR") == "nnnnnnnnnRRRRRR");
    CHECK(steadied("nnnnnnnnRnnnnnnnRRR") == "nnnnnnnnnnnnnnnnRRR");
    CHECK(steadied("nnnnnRnnnnn") == "nnnnnnnnnnn");
    // What did not blink is unchanged: a ramp in and out, and a held class.
    CHECK(steadied("nnnRRRRRRRnn") == "nnnRRRRRRRnn");
    CHECK(steadied("nnuRRRRRuuu") == "nnuRRRRRuuu");
    CHECK(steadied("nnuRRRRRu") == "nnuRRRRRR");  // a last frame alone takes its neighbours' class
    CHECK(steadied("uuuuuu") == "uuuuuu");
    // No class holds more than half: the frame's own.
    CHECK(steadyClass(classesOf("nnuRR"), 2) == VerdictClass::kUnusual);
    CHECK(steadyClass(classesOf("nR"), 1) == VerdictClass::kRefused);
    CHECK(steadyClass(classesOf("R"), 0) == VerdictClass::kRefused);
}

TEST_CASE("editor: the range tint of an edited span is steadied, the frame's own verdict kept beside it") {
    const gp::ModelVersionPtr v = test::walkModel35();
    EditorDocument doc;
    doc.setModel(v, true);
    doc.setAdaptiveEnabled(false);
    const Clip& clip = v->model->clip;
    const int neck = clip.skeleton.findBone("upperneck");
    REQUIRE(neck >= 0);
    // Frames 100..110 edited: the captured pose (natural), or with the neck bent 80° past it (out of
    // the walk's captured range).
    auto edits = [&](int bentFirst, int bentLast) {
        std::map<int, EditRecord> out;
        for (int t = 100; t <= 110; ++t) {
            EditRecord e;
            e.pose = clip.frames[t];
            if (t >= bentFirst && t <= bentLast) e.pose.anglesDeg[neck].x() += 80.0;
            e.x = latentStartForFrame(*v, t);
            out[t] = e;
        }
        return out;
    };
    SUBCASE("one bent frame shows its neighbours' class; its own verdict says why it is refused") {
        doc.restoreEdits(edits(105, 105));
        doc.setFrame(105);
        const std::optional<AdmissionVerdict> own = doc.currentPoseVerdict();
        REQUIRE(own);
        CHECK_FALSE(own->admitted);
        const std::optional<ShownVerdict> shown = doc.shownPoseVerdict();
        REQUIRE(shown);
        CHECK_FALSE(shown->own.admitted);
        CHECK(shown->own.reason == own->reason);
        REQUIRE(shown->steadied);
        CHECK(shown->shown().admitted);
        CHECK(shown->steadiedFrame == 104);
        CHECK(shown->first == 103);
        CHECK(shown->last == 107);
        doc.setFrame(104);
        REQUIRE(doc.shownPoseVerdict());
        CHECK(doc.shownPoseVerdict()->shown().admitted);
        CHECK_FALSE(doc.shownPoseVerdict()->steadied);
    }
    SUBCASE("three bent frames show as refused; the window stops at the edited run's ends") {
        doc.restoreEdits(edits(105, 107));
        for (int t = 105; t <= 107; ++t) {
            CAPTURE(t);
            doc.setFrame(t);
            const std::optional<ShownVerdict> shown = doc.shownPoseVerdict();
            REQUIRE(shown);
            CHECK_FALSE(shown->shown().admitted);
            CHECK_FALSE(shown->steadied);
        }
        for (int t : {104, 108}) {
            doc.setFrame(t);
            CHECK(doc.shownPoseVerdict()->shown().admitted);
        }
        doc.setFrame(100);  // frame 99 is captured: not in the window
        CHECK(doc.shownPoseVerdict()->first == 100);
        CHECK(doc.shownPoseVerdict()->last == 102);
        doc.setFrame(99);
        CHECK_FALSE(doc.shownPoseVerdict());
    }
    SUBCASE("a drag that misses its target is not steadied: red among natural neighbours, as dragged") {
        doc.restoreEdits(edits(1, 0));  // 100..110 natural
        doc.setDragFalloff(0);          // the neighbours stay the natural edits
        doc.setFrame(105);
        REQUIRE(doc.beginDrag(Effector::kRHand).empty());
        doc.dragTo(doc.effectorPosition(Effector::kRHand) + Eigen::Vector3d(0, 0, 300), 200);  // out of reach
        REQUIRE(doc.endDrag());
        const std::optional<ShownVerdict> shown = doc.shownPoseVerdict();
        REQUIRE(shown);
        CHECK(shown->own.judgement == PoseJudgement::kOutOfReach);
        CHECK_FALSE(shown->steadied);
        CHECK_FALSE(shown->shown().admitted);
        doc.setFrame(104);
        CHECK(doc.shownPoseVerdict()->shown().admitted);
    }
    SUBCASE("switching the frame's judgement inputs is seen: an undo of the bend") {
        doc.restoreEdits(edits(104, 106));
        doc.setFrame(105);
        CHECK_FALSE(doc.shownPoseVerdict()->shown().admitted);
        doc.restoreEdits(edits(105, 105));  // 104 and 106 natural again: judged anew, not from the cache
        CHECK(doc.shownPoseVerdict()->shown().admitted);
    }
}
