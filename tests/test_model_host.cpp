// The document's model host (core/edit/model_host.h): worker, adaptive switch, history, status
// and the version log that undo reads, on the committed walk model.
#include <doctest/doctest.h>

#include <atomic>

#include "edit/model_host.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("model host: updates are counted, listed, and their versions resolved for undo") {
    const auto v0 = test::walkModel35();
    const gp::GpModel& m0 = *v0->model;
    std::atomic<int> accepted{0};
    ModelHost host([&] { ++accepted; });
    CHECK(!host.hasModel());
    CHECK(host.post({m0.X.row(3).transpose(), m0.Y.row(3).transpose(), 3}) == 0);  // no model: nothing posted
    host.install(v0);
    REQUIRE(host.hasModel());
    CHECK(host.current() == v0);
    CHECK(host.updating());
    CHECK(host.status().empty());

    EditStep step;
    step.samples.push_back(host.post({m0.X.row(3).transpose(), m0.Y.row(3).transpose(), 3}));
    CHECK(step.samples.front() == 1);
    host.waitIdle();
    CHECK(accepted == 1);
    CHECK(host.pending() == 0);
    REQUIRE(host.updates() == 1);
    const AdaptiveHistoryEntry h = host.history().front();
    CHECK(h.accepted);
    CHECK(h.frame == 3);
    CHECK(h.versionBefore == 0);
    CHECK(h.versionAfter == 1);
    CHECK(h.rowsAfter == m0.N() + 1);
    CHECK(host.status().find("update accepted") == 0);
    const gp::ModelVersionPtr v1 = host.current();
    CHECK(v1->number == 1);

    // Undo of that step: the version before its first sample, and back again.
    host.resolveStep(step);
    CHECK(step.modelResolved);
    CHECK(step.modelBefore == v0);
    CHECK(step.modelAfter == v1);
    CHECK(host.restore(v0));
    CHECK(host.current() == v0);
    CHECK(!host.restore(v0));  // already current
    CHECK(host.restore(v1));
    CHECK(host.current() == v1);

    // A refused pose is listed and said, not learned.
    host.noteRefused(7, *v1, "σ² above the training range");
    CHECK(host.updates() == 2);
    CHECK(!host.history().back().accepted);
    CHECK(host.history().back().diagnostic == "refused: σ² above the training range");
    CHECK(host.status() == "pose kept as an edit, not added to the model: σ² above the training range");
    CHECK(accepted == 1);
}

TEST_CASE("model host: the adaptive switch reports changes and a disabled host keeps the model") {
    const auto v0 = test::walkModel35();
    ModelHost host;
    CHECK(!host.setAdaptiveEnabled(true));  // on by default
    CHECK(host.setAdaptiveEnabled(false));
    host.install(v0);
    CHECK(!host.updating());
    host.post({v0->model->X.row(0).transpose(), v0->model->Y.row(0).transpose(), 0});
    host.waitIdle();
    CHECK(host.current() == v0);
    CHECK(host.setAdaptiveEnabled(true));
    CHECK(host.updating());
    host.clear();
    CHECK(!host.hasModel());
    CHECK(host.current() == nullptr);
    CHECK(!host.restore(v0));
}
