// In-betweening (motion/inbetween.h): the gaps' contract, the interpolation baseline, keys and
// everything outside the gaps kept bit for bit, the gap's own frames never read, planted feet held.
#include <doctest/doctest.h>

#include <cmath>

#include "io/clip_loader.h"
#include "motion/foot_contacts.h"
#include "motion/inbetween.h"
#include "motion/span_solver.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"
#include "skeleton/synthetic_clip.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("gaps: inside the clip, at least one frame between the keys, increasing, not overlapping") {
    CHECK(validateGaps({{0, 2}, {2, 9}}, 10) == "");
    CHECK(validateGaps({}, 10).find("at least one gap") != std::string::npos);
    CHECK(validateGaps({{3, 4}}, 10) ==
          "expected at least one frame between the keys of a gap A:B (A + 1 < B), found 4:5");
    CHECK(validateGaps({{3, 10}}, 10) == "expected gaps inside the clip's frames 1..10, found 4:11");
    CHECK(validateGaps({{-1, 3}}, 10).find("inside the clip") != std::string::npos);
    CHECK(validateGaps({{4, 8}, {2, 6}}, 10) ==
          "expected gaps in increasing order that do not overlap, found 3:7 after 5:9");
}

TEST_CASE("the interpolation baseline: the keys at both ends, every joint's rotation slerped between") {
    const Clip clip = makeSyntheticWalk(60);
    const Skeleton& sk = clip.skeleton;
    const Pose& a = clip.frames[5];
    const Pose& b = clip.frames[35];
    FkState fa, fb, f0, f1, fm;
    forwardKinematics(sk, a, fa);
    forwardKinematics(sk, b, fb);
    forwardKinematics(sk, interpolatedPose(sk, a, b, 0.0), f0);
    forwardKinematics(sk, interpolatedPose(sk, a, b, 1.0), f1);
    const Pose mid = interpolatedPose(sk, a, b, 0.5);
    forwardKinematics(sk, mid, fm);
    CHECK((mid.rootCm - 0.5 * (a.rootCm + b.rootCm)).norm() < 1e-12);
    for (int j = 0; j < sk.jointCount(); ++j) {
        CHECK((f0.global[j] - fa.global[j]).cwiseAbs().maxCoeff() < 1e-9);
        CHECK((f1.global[j] - fb.global[j]).cwiseAbs().maxCoeff() < 1e-9);
        // Halfway: the local rotation is the slerp midpoint, so it is as far (in angle) from
        // either key's local rotation.
        const Joint& jt = sk.joints[static_cast<std::size_t>(j)];
        const Eigen::Quaterniond qa(eulerMatrix(a.anglesDeg[j], jt.order)), qb(eulerMatrix(b.anglesDeg[j], jt.order)),
            qm(eulerMatrix(mid.anglesDeg[j], jt.order));
        CHECK(qm.angularDistance(qa) == doctest::Approx(qm.angularDistance(qb)).epsilon(1e-9));
        CHECK(qm.angularDistance(qa) == doctest::Approx(0.5 * qa.angularDistance(qb)).epsilon(1e-9));
    }
}

namespace {
InbetweenJob kickJob(const Clip& clip, InbetweenMethod method, std::vector<InbetweenGap> gaps) {
    InbetweenJob job;
    job.version = test::kickModel1003();
    job.clip = clip;
    job.gaps = std::move(gaps);
    job.method = method;
    return job;
}
}  // namespace

TEST_CASE("every method keeps the keys and every frame outside the gaps bit for bit, on a clip the model never saw") {
    // The model learned 10_03; the gaps are on 10_02, another take.
    const Clip clip = loadClip(test::mocap("asf_amc/10_02.amc"));
    const std::vector<InbetweenGap> gaps = {{40, 101}, {200, 321}};
    for (InbetweenMethod method :
         {InbetweenMethod::kHold, InbetweenMethod::kInterpolate, InbetweenMethod::kRetrieve, InbetweenMethod::kPrior}) {
        CAPTURE(std::string(inbetweenMethodName(method)));
        InbetweenJob job = kickJob(clip, method, gaps);
        REQUIRE(job.validate() == "");
        job.run();
        REQUIRE(job.frames.size() == clip.frames.size());
        REQUIRE(job.reports.size() == 2);
        int changed = 0;
        for (int t = 0; t < clip.frameCount(); ++t) {
            const bool inner = (t > 40 && t < 101) || (t > 200 && t < 321);
            if (!inner)
                CHECK(
                    posesIdentical(job.frames[static_cast<std::size_t>(t)], clip.frames[static_cast<std::size_t>(t)]));
            else
                changed +=
                    posesIdentical(job.frames[static_cast<std::size_t>(t)], clip.frames[static_cast<std::size_t>(t)])
                        ? 0
                        : 1;
            CHECK(allFinite(job.frames[static_cast<std::size_t>(t)]));
        }
        CHECK(changed == 60 + 120);
        for (const InbetweenJob::GapReport& r : job.reports) {
            if (method == InbetweenMethod::kRetrieve || method == InbetweenMethod::kPrior) {
                CHECK(r.sourceClip == "10_03");
                CHECK(r.sourceFirst >= 0);
                CHECK(r.timeScale >= 0.8 - 1e-9);
                CHECK(r.timeScale <= 1.25 + 1e-9);
                CHECK(r.meanVariance > 0.0);
                CHECK(r.maxVariance >= r.meanVariance);
            }
        }
    }
}

TEST_CASE("the prior's held feet never jump at a key: each foot moves across a join about as much as the capture's") {
    // 10_02 with the model of 10_03: gaps whose keys have feet planted, and one where a foot
    // steps into key b (the cases where a foot held mid-contact used to jump 10-19 cm at a key).
    const Clip clip = loadClip(test::mocap("asf_amc/10_02.amc"));
    InbetweenJob job = kickJob(clip, InbetweenMethod::kPrior, {{136, 256}, {516, 576}});
    job.run();
    InbetweenJob second = kickJob(clip, InbetweenMethod::kPrior, {{198, 258}});  // overlaps the first
    second.run();
    auto worstJoinStep = [&](const std::vector<Pose>& frames, const std::vector<InbetweenGap>& gaps) {
        double worst = 0.0;
        for (const InbetweenGap& g : gaps)
            for (int t : {g.a + 1, g.b})
                for (Effector foot : {Effector::kLFoot, Effector::kRFoot})
                    worst = std::max(worst, (effectorCm(clip.skeleton, frames[static_cast<std::size_t>(t)], foot) -
                                             effectorCm(clip.skeleton, frames[static_cast<std::size_t>(t - 1)], foot))
                                                .norm());
        return worst;
    };
    const std::vector<InbetweenGap> all = {{136, 256}, {516, 576}, {198, 258}};
    const double captured = worstJoinStep(clip.frames, all);
    const double filled =
        std::max(worstJoinStep(job.frames, {{136, 256}, {516, 576}}), worstJoinStep(second.frames, {{198, 258}}));
    MESSAGE("worst foot step across a join: " << filled << " cm (the capture's " << captured << " cm)");
    CHECK(filled <= captured + 1.0);
}

TEST_CASE("retrieval never reads the gap it fills, and the prior holds the feet planted at the keys") {
    // The model's own clip: the best stretch for a gap would be the gap itself, which is left out.
    const gp::ModelVersionPtr version = test::kickModel1003();
    const Clip& clip = version->model->clip;
    // A 40-frame gap whose first key has both feet planted (the context says so).
    const ContactSet contacts = detectFootContacts(clip);
    int a = 10;
    while (a + 41 < clip.frameCount() && !(contacts.at(Effector::kLFoot, a) && contacts.at(Effector::kRFoot, a))) ++a;
    REQUIRE(a + 41 < clip.frameCount());
    const int b = a + 41;
    InbetweenJob job;
    job.version = version;
    job.clip = clip;
    job.gaps = {{a, b}};
    job.method = InbetweenMethod::kPrior;
    job.run();
    const InbetweenJob::GapReport& r = job.reports.front();
    CHECK(r.sourceClip == clip.name);
    CHECK((r.sourceLast < a || r.sourceFirst > b));
    CHECK(r.heldFootFrames > 0);
    CHECK(r.maxHeldResidualCm < 1.0);
    CHECK(r.stop == SpanStop::kConverged);
}

TEST_CASE("a job says what is wrong before it runs") {
    const Clip clip = loadClip(test::mocap("asf_amc/10_02.amc"));
    InbetweenJob job = kickJob(clip, InbetweenMethod::kPrior, {{10, 11}});
    CHECK(job.validate().find("at least one frame between") != std::string::npos);
    CHECK_THROWS_AS(job.run(), std::invalid_argument);
    InbetweenJob other = kickJob(loadClip(test::mocap("asf_amc/35_01.amc")), InbetweenMethod::kPrior, {{10, 40}});
    CHECK(other.validate().find("expected a clip of the model's skeleton") != std::string::npos);
}

TEST_CASE("a span over another clip's motion needs that motion's latent points") {
    const gp::ModelVersionPtr version = test::kickModel1003();
    EditBase base;
    const Clip clip = loadClip(test::mocap("asf_amc/10_02.amc"));  // 590 frames, the model's clip has 362
    base.frames = clip.frames;
    CHECK_THROWS_AS(SpanSolver(version, 40, 60, {}, &base), std::invalid_argument);
    base.x.assign(base.frames.size(), Eigen::VectorXd());
    for (int t = 41; t < 60; ++t) base.x[static_cast<std::size_t>(t)] = version->model->X.row(0).transpose();
    SpanSolver solver(version, 40, 60, {}, &base);
    const SpanResult r = solver.solve(5);
    REQUIRE(r.poses.size() == 19);
    // The root translation is the base's own, not the model clip's.
    CHECK(r.poses.front().rootCm == clip.frames[41].rootCm);
}
