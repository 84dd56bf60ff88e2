// A model at once (label `gl`, offscreen): Train publishes the model as it stands while the run goes
// on, the editor installs each one between gestures (never during a drag), the Model panel says
// it is refining, and a cancelled run leaves the last published model in place.
#include <doctest/doctest.h>

#include <string>

#include "editor_harness.h"
#include "ui/shell/editor_app.h"

using namespace mgp;

namespace {

// Runs UI frames until `done` or `limit` frames have passed; whether `done` came true.
template <class Pred>
bool frameUntil(test::Harness& h, Pred done, int limit = 20000) {
    for (int i = 0; i < limit; ++i) {
        if (done()) return true;
        h.frame();
    }
    return done();
}

}  // namespace

TEST_CASE("gui: training publishes models the viewport drags against, installed between gestures only") {
    auto h = test::makeHarness(false, false);
    if (!h) return;
    ui::EditorState& s = h->app->state();
    EditorDocument& doc = s.doc;
    gp::TrainOptions& o = s.trainOptions;
    o.activeSize = 40;
    o.outerIterations = 1000;  // ends by Cancel below
    o.scgIterations = 10;
    o.pointIterations = 10;
    s.training.setPublishPolicy({1, 0.0, true});
    REQUIRE_FALSE(doc.hasModel());
    REQUIRE(h->app->runAction({"train"}) == "");
    REQUIRE(frameUntil(*h, [&] { return doc.hasModel(); }));
    CHECK(doc.refining());
    CHECK(s.training.running());
    CHECK(s.modelLabel.find("refining") == 0);

    // During a drag the model stays the one the drag started on, though newer ones are published.
    doc.setFrame(99);
    REQUIRE(doc.beginDrag(Effector::kRHand) == "");
    const gp::ModelVersionPtr during = doc.model();
    const int publishedAtStart = s.training.progress().published;
    REQUIRE(frameUntil(*h, [&] { return s.training.progress().published >= publishedAtStart + 2; }));
    h->frame(3);
    CHECK(doc.model() == during);
    doc.endDrag();
    // After the drag's falloff (a regeneration, also a gesture the model waits for) has landed.
    REQUIRE(frameUntil(*h, [&] { return doc.model() != during; }));
    CHECK_FALSE(doc.regenerating());
    CHECK(doc.refining());

    // Cancel: the last published model stays, said in the status line.
    REQUIRE(h->app->runAction({"cancel-train"}) == "");
    s.training.join();
    h->frame(3);
    CHECK_FALSE(s.training.running());
    CHECK(doc.hasModel());
    CHECK_FALSE(doc.refining());
    CHECK(s.messages.latestText().find("keeping the model from iteration") != std::string::npos);
}
