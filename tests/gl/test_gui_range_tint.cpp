// The viewport's pose-range tint and legend, driven through the editor offscreen with the committed
// walk model: a hand dragged far out of reach turns the figure red and the legend says, in words,
// that the model does not learn from it; a small drag stays admissible; a captured frame is never tinted. The
// tint is read from the scene the viewport built (plain data), not from pixels.
#include <doctest/doctest.h>

#include <string>

#include "editor_harness.h"
#include "render/range_tint.h"
#include "ui/input/gui_script.h"
#include "ui/shell/editor_app.h"

using namespace mgp;
using test::makeHarness;

namespace {

const render::Figure& shownFigure(const ui::EditorApp& app) {
    const render::Scene& scene = app.viewport().lastScene();
    REQUIRE_FALSE(scene.figures.empty());
    REQUIRE_FALSE(scene.figures.front().ghost);
    return scene.figures.front();
}

bool contains(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

}  // namespace

TEST_CASE("gui range tint: a hand dragged far out of reach is red and refused") {
    auto h = makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    REQUIRE(doc.hasModel());
    doc.setDragFalloff(0);
    doc.setFrame(60);
    h->frame(2);
    // A captured frame: not tinted, and the legend says so.
    CHECK(shownFigure(*h->app).tintWeight == 0.0f);
    CHECK(contains(s.rangeLegend, "no solved pose"));

    std::string script = "0 hover rhand\n2 down left\n";
    for (int k = 0; k < 10; ++k) script += std::to_string(4 + 2 * k) + " moveby 25 -25\n";
    // Hold the drag: check the live solve's tint before releasing.
    auto errors = h->play(ui::GuiScript::parse(script));
    REQUIRE(errors.empty());
    REQUIRE(doc.dragging());
    std::optional<AdmissionVerdict> v = doc.currentPoseVerdict();
    REQUIRE(v);
    INFO("reason '" << v->reason << "'  legend: " << s.rangeLegend);
    CHECK_FALSE(v->admitted);
    CHECK((v->judgement == PoseJudgement::kOutOfReach || v->judgement == PoseJudgement::kUnlikeCapture));
    const render::Figure& live = shownFigure(*h->app);
    CHECK(live.tintWeight == 1.0f);
    CHECK(live.tint == render::kRangeRed);
    CHECK(contains(s.rangeLegend, std::string("this pose is ") + judgementWords(v->judgement)));
    CHECK(contains(s.rangeLegend, "the model does not learn from it"));

    errors = h->play(ui::GuiScript::parse("0 up left\n"));
    REQUIRE(errors.empty());
    CHECK_FALSE(doc.dragging());
    REQUIRE(doc.isEdited(60));
    h->app->waitIdle();
    h->frame(2);
    // The accepted edit is judged again from its x and pose: still red, still refused.
    v = doc.currentPoseVerdict();
    REQUIRE(v);
    CHECK_FALSE(v->admitted);
    CHECK(shownFigure(*h->app).tint == render::kRangeRed);
    CHECK(shownFigure(*h->app).tintWeight == 1.0f);
    CHECK(contains(s.rangeLegend, "the model does not learn from it"));
    CHECK(contains(doc.models().status(), "not added to the model"));

    // View > Pose range tint off: side colours and no legend.
    s.showRangeTint = false;
    h->frame(2);
    CHECK(shownFigure(*h->app).tintWeight == 0.0f);
    CHECK(s.rangeLegend.empty());
    s.showRangeTint = true;

    // Another, captured frame keeps the side colours.
    doc.setFrame(10);
    h->frame(2);
    CHECK(shownFigure(*h->app).tintWeight == 0.0f);
}

TEST_CASE("gui range tint: a small drag stays in range and would be admitted") {
    auto h = makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    REQUIRE(doc.hasModel());
    doc.setDragFalloff(0);
    doc.setFrame(40);
    h->frame(2);
    const auto errors = h->play(ui::GuiScript::parse("0 hover rhand\n2 down left\n4 moveby 0 -2\n"));
    REQUIRE(errors.empty());
    REQUIRE(doc.dragging());
    const std::optional<AdmissionVerdict> v = doc.currentPoseVerdict();
    REQUIRE(v);
    INFO("reason '" << v->reason << "'  nearest captured frame " << v->capture.nearestCm << " cm (median "
                    << v->nearestMedianCm << ", limit " << v->nearestLimitCm << ")  legend: " << s.rangeLegend);
    CHECK(v->admitted);
    const render::RangeTint expected = render::rangeTint(*v);
    CHECK(expected.band != render::RangeBand::kOutOfRange);
    const render::Figure& f = shownFigure(*h->app);
    CHECK(f.tintWeight == expected.weight);
    CHECK(f.tintWeight < 1.0f);
    CHECK(f.tint != render::kRangeRed);
    CHECK(contains(s.rangeLegend, "the model learns from it"));
    CHECK_FALSE(contains(s.rangeLegend, "unlike"));
    const int rowsBefore = static_cast<int>(doc.model()->model->X.rows());
    REQUIRE(h->play(ui::GuiScript::parse("0 up left\n")).empty());
    REQUIRE(doc.isEdited(40));
    h->app->waitIdle();
    h->frame(2);
    CHECK(contains(s.rangeLegend, "the model learns from it"));
    // The update taught the model the pose: it is judged at the latent point the update gave its
    // new training row, not at the x solved on the previous version.
    const gp::ModelVersionPtr now = doc.model();
    REQUIRE(now->number == 1);
    const gp::GpModel& m = *now->model;
    REQUIRE(m.X.rows() == rowsBefore + 1);
    const Eigen::VectorXd xRow = m.X.row(m.X.rows() - 1).transpose();
    const Eigen::VectorXd yRow = m.Y.row(m.Y.rows() - 1).transpose();
    CHECK(m.trainingFrames.back() == 40);
    CHECK((xRow - doc.edits().at(40).x).norm() > 0.0);  // the update moved it
    const std::optional<AdmissionVerdict> after = doc.currentPoseVerdict();
    REQUIRE(after);
    CHECK(after->lik == doctest::Approx(now->posterior->evaluate(xRow, yRow, nullptr, nullptr)).epsilon(1e-12));
}

TEST_CASE("gui balance: View > Balance draws the support and says where the centre of mass falls") {
    auto h = makeHarness(false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    h->frame(2);
    CHECK(s.balanceCaption.empty());  // off by default
    s.showBalance = true;
    int planted = 0, inAir = 0;
    for (int t = 0; t < doc.frameCount(); t += 7) {
        doc.setFrame(t);
        h->frame(1);
        CAPTURE(t);
        const bool anyFoot = doc.contacts().at(Effector::kLFoot, t) || doc.contacts().at(Effector::kRFoot, t);
        if (anyFoot) {
            ++planted;
            // The captured walk never tips past its support by much: the caption says which side of the limit it is.
            CHECK(contains(s.balanceCaption, "balance: centre of mass "));
            CHECK(contains(s.balanceCaption, "cm outside the support"));
        } else {
            ++inAir;
            CHECK(s.balanceCaption == "balance: no foot planted on this frame");
        }
    }
    CHECK(planted > 0);
    // The walk has a foot down on every frame (heel strike to toe-off, docs/maths.md §13); with the
    // contacts of frame 100 switched off, nothing holds it.
    CHECK(inAir == 0);
    const int t = 100;
    for (std::size_t i = 0; i < doc.contacts().contacts.size(); ++i)
        if (doc.contacts().contacts[i].contains(t)) doc.setContactEnabled(i, false);
    doc.setFrame(t);
    h->frame(1);
    CHECK(s.balanceCaption == "balance: no foot planted on this frame");
    s.showBalance = false;
    h->frame(1);
    CHECK(s.balanceCaption.empty());
}
