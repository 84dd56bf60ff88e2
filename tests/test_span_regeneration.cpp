// Span regeneration on real clips (motion/motion_edit.h, kSpan): keys met, smoothness within the
// capture's, planted feet and pins held. Small quick models (M = 100, T = 3).
#include <mutex>

#include "gp/train/trainer.h"
#include "io/clip_loader.h"
#include "motion/motion_edit.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

namespace {
MotionEditJob edit(gp::ModelVersionPtr v, Effector e, int firstKey1Based, const Eigen::Vector3d& offset) {
    MotionEditJob job;
    job.version = std::move(v);
    job.effector = e;
    const int k = firstKey1Based - 1;
    job.keyFrames = {k, k + 14, k + 28, k + 42};
    job.keyOffsetsCm = {Eigen::Vector3d::Zero(), offset, offset, Eigen::Vector3d::Zero()};
    return job;
}

// The done-when bar, checked on one regenerated span.
void checkKeepable(const MotionEditJob& job) {
    const SpanQuality& q = job.quality;
    MESSAGE("key " << q.worstKeyErrorCm << " cm, second difference p95 " << q.edited.p95Deg << "° (captured "
                   << q.captured.p95Deg << "°), max " << q.edited.maxDeg << "° (captured " << q.captured.maxDeg
                   << "°), stop " << std::string(spanStopName(job.spanStop)) << " after " << job.spanIterations
                   << " iterations");
    CHECK(job.spanStop == SpanStop::kConverged);
    CHECK(q.worstKeyErrorCm <= 0.5);
    CHECK(q.worstPathErrorCm <= 0.5);
    CHECK(q.edited.p95Deg <= 1.5 * q.captured.p95Deg + 2.0);
    CHECK(q.edited.maxDeg <= 1.5 * q.captured.maxDeg + 5.0);
    for (const ContactTravel& c : q.contacts) {
        MESSAGE(std::string(effectorName(c.foot)) << " contact " << c.first + 1 << ".." << c.last + 1 << ": travel "
                                                  << c.editedCm << " cm (captured " << c.capturedCm << " cm)");
        CHECK(std::abs(c.editedCm - c.capturedCm) <= 1.0);
    }
    // Frames outside the open span are the capture's, bit for bit.
    const Clip& clip = job.version->model->clip;
    for (int t = 0; t < clip.frameCount(); ++t) {
        if (t > job.keyFrames.front() && t < job.keyFrames.back()) continue;
        for (std::size_t j = 0; j < clip.frames[t].anglesDeg.size(); ++j)
            REQUIRE(job.frames[t].anglesDeg[j] == clip.frames[t].anglesDeg[j]);
    }
}
}  // namespace

TEST_CASE("span regeneration on 35_01: left foot raised 20 cm over 89..131, the planted right foot held") {
    MotionEditJob job = edit(test::walkModel35(), Effector::kLFoot, 89, Eigen::Vector3d(0, 20, 0));
    job.run();
    REQUIRE(job.held.size() == 1);  // the right foot's contact 100..157
    CHECK(job.held[0].foot == Effector::kRFoot);
    CHECK(job.maxHeldResidualCm < 0.1);
    checkKeepable(job);
    REQUIRE(job.quality.contacts.size() == 1);
}

TEST_CASE("span regeneration on a held-out kick (10_03, 189..231): raise and sideways, 10 and 40 cm") {
    for (const Eigen::Vector3d& offset :
         {Eigen::Vector3d(0, 10, 0), Eigen::Vector3d(0, 40, 0), Eigen::Vector3d(20, 0, 0)}) {
        CAPTURE(offset.transpose());
        MotionEditJob job = edit(test::kickModel1003(), Effector::kRFoot, 189, offset);
        job.run();
        CHECK_FALSE(job.held.empty());  // the left foot is planted from frame 224
        checkKeepable(job);
    }
}

TEST_CASE("per-frame regeneration (the paper's) pops where the span solver does not") {
    MotionEditJob perFrame = edit(test::kickModel1003(), Effector::kRFoot, 189, Eigen::Vector3d(0, 20, 0));
    perFrame.solver = EditSolver::kPerFrame;
    perFrame.holdContacts = false;
    perFrame.run();
    MotionEditJob span = edit(test::kickModel1003(), Effector::kRFoot, 189, Eigen::Vector3d(0, 20, 0));
    span.run();
    MESSAGE("per-frame p95 " << perFrame.quality.edited.p95Deg << "°, span p95 " << span.quality.edited.p95Deg
                             << "°, captured " << span.quality.captured.p95Deg << "°");
    CHECK(span.quality.edited.p95Deg < perFrame.quality.edited.p95Deg);
    CHECK(perFrame.quality.worstKeyErrorCm <= 0.5);  // both meet the keys
}

TEST_CASE("a user pin holds the left hand on every frame of the span, and cancel leaves the clip unedited") {
    MotionEditJob job = edit(test::walkModel35(), Effector::kLFoot, 89, Eigen::Vector3d(0, 20, 0));
    job.pins = {Effector::kLHand, Effector::kLFoot};  // a pin on the edited effector is ignored
    job.run();
    CHECK(job.maxHeldResidualCm < 0.1);
    for (const LearnedIkResult& r : job.results) {
        REQUIRE(r.constraints.size() >= 2);
        CHECK(r.constraints[1].effector == Effector::kLHand);
    }
    std::atomic<bool> cancel{true};
    MotionEditJob c = edit(test::walkModel35(), Effector::kLFoot, 89, Eigen::Vector3d(0, 20, 0));
    c.cancel = &cancel;
    c.run();
    CHECK(c.cancelled);
    CHECK(c.frames[110].anglesDeg[3] == c.version->model->clip.frames[110].anglesDeg[3]);
}

#include "edit/editor_document.h"

TEST_CASE("editor: Regenerate holds the clip's contacts unless the user switches one off") {
    EditorDocument doc;
    doc.setModel(test::walkModel35(), true);
    doc.setAdaptiveEnabled(false);
    const ContactSet& contacts = doc.contacts();
    std::size_t rightStance = contacts.contacts.size();
    for (std::size_t i = 0; i < contacts.contacts.size(); ++i)
        if (contacts.contacts[i].foot == Effector::kRFoot && contacts.contacts[i].contains(110)) rightStance = i;
    REQUIRE(rightStance < contacts.contacts.size());
    for (bool on : {true, false}) {
        CAPTURE(on);
        doc.setContactEnabled(rightStance, on);
        doc.setFrame(109);
        REQUIRE(doc.beginPathEdit(Effector::kLFoot) == "");
        REQUIRE(doc.paths().setKeyOffset(1, {0, 20, 0}) == "");
        REQUIRE(doc.paths().setKeyOffset(2, {0, 20, 0}) == "");
        REQUIRE(doc.startRegenerate() == "");
        doc.waitIdle();
        CHECK(doc.pollRegenerate().find(on ? "1 contact(s) held" : "0 contact(s) held") != std::string::npos);
        REQUIRE(doc.lastRegenerateQuality());
        CHECK(doc.lastRegenerateQuality()->contacts.size() == (on ? 1u : 0u));
        CHECK(doc.lastRegenerateQuality()->worstKeyErrorCm < 0.5);
        REQUIRE(doc.lastRegenerateKeys().size() == 2);  // the inner keys, for the Path panel's rows
        for (const MotionEditJob::KeyResult& k : doc.lastRegenerateKeys()) CHECK(k.reached);
        CHECK(doc.undo().empty());
        doc.paths().end();
    }
}
