// The adaptive active set (docs/maths.md §11): a new immutable version with N + 1 rows; a high-variance sample
// enters the active set; bad samples are discarded; updates never block the caller.
#include <cmath>
#include <future>

#include "edit/adaptive_worker.h"
#include "gp/model_file.h"
#include "gp/train/adaptive_update.h"
#include "gp/train/ivm.h"
#include "ik/learned_ik.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("adaptive update appends the sample, keeps μ, and publishes version n + 1") {
    const auto v0 = test::walkModel35();
    const gp::GpModel& m0 = *v0->model;
    const Eigen::VectorXd x = m0.X.row(5).transpose();
    const Eigen::VectorXd y = m0.Y.row(5).transpose();
    const gp::AdaptiveUpdateResult r = gp::adaptiveUpdate(*v0, x, y, 5);
    REQUIRE(r.accepted);
    const gp::GpModel& m1 = *r.version->model;
    CHECK(r.version->number == v0->number + 1);
    CHECK(m1.N() == m0.N() + 1);
    CHECK(m1.mu == m0.mu);
    CHECK(m1.Y.row(m0.N()) == y.transpose());
    CHECK(m1.trainingFrames.back() == 5);
    CHECK(m1.active.size() == m0.active.size());
    CHECK(std::isfinite(r.objectiveAfter));
    CHECK(r.objectiveAfter <= r.objectiveBefore + 1e-9);  // SCG never accepts an uphill step
    CHECK(m0.N() == 358);                                 // the old version is untouched
    // Σ ln w = 0 still holds (gauge).
    CHECK(std::abs(m1.w.array().log().sum()) < 1e-9);
}

TEST_CASE("a sample where the posterior variance beats the smallest active variance enters the active set") {
    const auto v0 = test::walkModel35();
    const gp::GpModel& m0 = *v0->model;
    // The smallest posterior variance among the points the IVM picked, and a far-away x* whose
    // variance is larger (it is near the prior variance).
    const gp::IvmResult ivm = gp::selectActiveSet(m0.kernel(), m0.X, m0.settings.activeSize);
    Eigen::VectorXd xFar = m0.X.colwise().mean().transpose();
    xFar[0] += 6.0 * std::sqrt((m0.X.col(0).array() - m0.X.col(0).mean()).square().mean());
    Eigen::VectorXd mean;
    double varFar = 0.0;
    v0->posterior->predict(xFar, mean, varFar);
    double varNear = 0.0;
    v0->posterior->predict(m0.X.row(m0.active[0]).transpose(), mean, varNear);
    CHECK(varFar > varNear);
    const gp::AdaptiveUpdateResult r = gp::adaptiveUpdate(*v0, xFar, m0.Y.row(0).transpose(), 0);
    REQUIRE(r.accepted);
    CHECK(r.newPointActive);
    MESSAGE("far sample: σ² " << varFar << " vs " << varNear << " at an active point; active set changed by "
                              << r.activeChanged);
}

TEST_CASE("non-finite or mis-sized samples are discarded and reported") {
    const auto v0 = test::walkModel35();
    const gp::GpModel& m0 = *v0->model;
    Eigen::VectorXd x = m0.X.row(0).transpose();
    x[0] = NAN;
    gp::AdaptiveUpdateResult r = gp::adaptiveUpdate(*v0, x, m0.Y.row(0).transpose(), 0);
    CHECK_FALSE(r.accepted);
    CHECK(r.version == nullptr);
    CHECK(r.diagnostic == "expected a finite sample, found NaN or Inf (update discarded)");
    r = gp::adaptiveUpdate(*v0, Eigen::VectorXd::Zero(3), m0.Y.row(0).transpose(), 0);
    CHECK_FALSE(r.accepted);
}

TEST_CASE("the worker never blocks: posting and solving go on while an update is held in progress") {
    const auto v0 = test::walkModel35();
    AdaptiveWorker worker(v0, 20);
    std::promise<void> releaseWorker;
    std::shared_future<void> release = releaseWorker.get_future().share();
    std::promise<AdaptiveReport> firstReport;
    bool first = true;
    worker.setListener([&](const AdaptiveReport& r) {
        if (first) {
            first = false;
            firstReport.set_value(r);
            release.wait();  // hold the worker busy until the main thread has solved
        }
    });
    const gp::GpModel& m0 = *v0->model;
    worker.post({m0.X.row(3).transpose(), m0.Y.row(3).transpose(), 3});
    worker.post({m0.X.row(4).transpose(), m0.Y.row(4).transpose(), 4});
    auto reportFuture = firstReport.get_future();
    REQUIRE(reportFuture.wait_for(std::chrono::seconds(60)) == std::future_status::ready);
    const AdaptiveReport report = reportFuture.get();
    CHECK(report.result.accepted);
    CHECK(worker.pending() >= 1);  // the worker is still busy (held in its listener)
    // Meanwhile: take the latest version and solve; post another sample. None of this waits.
    const gp::ModelVersionPtr latest = worker.current();
    CHECK(latest->number == 1);
    LearnedIkSolver solver(latest);
    LearnedIkRequest req;
    req.start = latest->model->clip.frames[3];
    req.startX = latentStartForFrame(*latest, 3);
    FkState fk;
    forwardKinematics(latest->model->clip.skeleton, req.start, fk);
    req.constraints = {{Effector::kLHand,
                        effectorCm(latest->model->clip.skeleton, fk, Effector::kLHand) + Eigen::Vector3d(0, 5, 0),
                        false}};
    const LearnedIkResult res = solver.solve(req);
    CHECK(res.reached);
    worker.post({res.x, res.y, 3});
    releaseWorker.set_value();
    worker.waitIdle();
    CHECK(worker.current()->number == 3);
    CHECK(worker.current()->model->N() == 358 + 3);
}

TEST_CASE("a disabled worker keeps the static model") {
    const auto v0 = test::walkModel35();
    AdaptiveWorker worker(v0, 5);
    worker.setEnabled(false);
    worker.post({v0->model->X.row(0).transpose(), v0->model->Y.row(0).transpose(), 0});
    worker.waitIdle();
    CHECK(worker.current() == v0);
}

TEST_CASE(
    "an adaptively added row keeps its accepted pose through save and load, and a trained model's file is unchanged") {
    const auto v0 = test::walkModel35();
    const gp::GpModel& m0 = *v0->model;
    // The committed fixture re-saved is byte-identical: no edited rows are written for it.
    CHECK(gp::modelToJsonText(m0) == test::readText(test::walkModelPath()));
    // An accepted pose that differs from the captured pose of its frame (as every drag does).
    Eigen::VectorXd y = m0.Y.row(40).transpose();
    y[0] += 12.5;
    y[3] -= 7.25;
    const gp::AdaptiveUpdateResult r = gp::adaptiveUpdate(*v0, m0.X.row(40).transpose(), y, 40);
    REQUIRE(r.accepted);
    const gp::GpModel& m1 = *r.version->model;
    const std::string dir = test::scratchDir("adaptive_save");
    gp::saveModel(dir + "/m.model", m1);
    const gp::GpModel back = gp::loadModel(dir + "/m.model");
    REQUIRE(back.N() == m1.N());
    CHECK(back.Y == m1.Y);  // bit for bit, the edited row included
    CHECK(back.Y.row(m0.N()) == y.transpose());
    CHECK(back.Y.row(m0.N()) != back.Y.row(40));  // not the captured pose of frame 40
    CHECK(gp::modelToJsonText(back) == gp::modelToJsonText(m1));
    // A damaged edited row is a clear error.
    std::string text = test::readText(dir + "/m.model");
    const std::size_t at = text.find("\"row\": " + std::to_string(m0.N()));
    REQUIRE(at != std::string::npos);
    text.replace(at, 7 + std::to_string(m0.N()).size(), "\"row\": 99999");
    const std::string expected = "expected edited_rows row in 0.." + std::to_string(m0.N());
    CHECK_THROWS_WITH(gp::modelFromJsonText(text, "bad.model"), doctest::Contains(expected.c_str()));
}
