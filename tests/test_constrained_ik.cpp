// Constrained learned IK (core/ik/constrained_ik.h) on real clips: hard pins, exact targets, the
// 50-iteration budget, unreachable targets, and the admission rule for adaptive updates
// (core/gp/training_range.h). Tuned on 35_01; 10_03 (kick) and 16_01 (jump) are held out.
#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include "eval/admission.h"
#include "gp/train/trainer.h"
#include "gp/training_range.h"
#include "ik/constrained_ik.h"
#include "io/clip_loader.h"
#include "motion/captured_pose_request.h"
#include "motion/foot_contacts.h"
#include "skeleton/limb_extension.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

namespace {
// Same settings as the 35_01 fixture (M = 100, T = 3), on a held-out clip.
gp::ModelVersionPtr heldOutModel(const std::string& file) {
    static std::mutex mutex;
    static std::map<std::string, gp::ModelVersionPtr> cache;
    std::lock_guard<std::mutex> lock(mutex);
    auto& v = cache[file];
    if (!v) {
        gp::TrainOptions options;
        options.activeSize = 100;
        options.outerIterations = 3;
        v = gp::ModelVersion::make(gp::trainOnClip(loadClip(test::mocap("asf_amc/" + file)), options).model);
    }
    return v;
}

ConstrainedIkRequest captured(const gp::ModelVersion& v, int frame, int iterations = 50) {
    ConstrainedIkRequest r;
    r.start = v.model->clip.frames[frame];
    r.startX = latentStartForFrame(v, frame);
    r.maxIterations = iterations;
    return r;
}

struct Move {
    Effector effector;
    Eigen::Vector3d offset;
};

// One move of a committed fixture's captured frame (a 0-based frame index).
struct FixtureMove {
    gp::ModelVersionPtr version;
    int frame;
    Move move;
};

// What `motiongp pose` solves: from the captured frame, `effector` moved by `move` (an exact
// target), the feet in ground contact there held as pins where they stand.
ConstrainedIkRequest poseMove(const gp::ModelVersion& v, int frame, Effector effector, const Eigen::Vector3d& move) {
    const Clip& clip = v.model->clip;
    const Eigen::Vector3d target = effectorCm(clip.skeleton, clip.frames[frame], effector) + move;
    return capturedPoseRequest(v, frame, {{effector, target, false}}, detectFootContacts(clip), 50);
}

// The request without the defaults' locality, floor and balance: the solver mechanisms below were found
// and measured on the prior-only problem (the walk's frame 30 target lies below the floor), and stay
// tested there; `bench --only ik` measures convergence with the defaults.
ConstrainedIkRequest priorOnly(ConstrainedIkRequest req) {
    req.locality = 0.0;
    req.floorCm.reset();
    req.balance.reset();
    return req;
}

// The request at its 50-step cap converges, meets every pin and target, and ends at the minimum
// the same solve finds with 500 steps.
void checkConvergesWithin50AtTheLongSolvesMinimum(ConstrainedIkSolver& solver, ConstrainedIkRequest req) {
    REQUIRE(req.maxIterations == 50);
    const ConstrainedIkResult at50 = solver.solve(req);
    req.maxIterations = 500;
    const ConstrainedIkResult full = solver.solve(req);
    MESSAGE("at 50: " << std::string(ikStopName(at50.stop)) << " in " << at50.iterations << ", F " << at50.objective
                      << "; at 500: " << std::string(ikStopName(full.stop)) << " in " << full.iterations << ", F "
                      << full.objective);
    CHECK(at50.converged);
    CHECK(at50.iterations <= 50);
    CHECK(at50.reached);
    for (const auto& c : at50.constraints) CHECK(c.residualCm <= (c.pin ? 1e-5 : 0.05));
    REQUIRE(full.converged);
    CHECK(at50.objective == doctest::Approx(full.objective).epsilon(1e-6));
}
}  // namespace

TEST_CASE(
    "constrained IK: 20–50 cm hand and foot moves from the captured pose: pins always hold, targets met to 0.05 cm") {
    // Right-handed world, Y up. Moves an animator makes: reach up/forward/out, lift and step a foot.
    const std::vector<Move> moves = {{Effector::kRHand, {0, 20, 0}},   {Effector::kRHand, {0, 0, 30}},
                                     {Effector::kLHand, {-25, 15, 0}}, {Effector::kRHand, {10, 35, 20}},
                                     {Effector::kRFoot, {0, 20, 0}},   {Effector::kLFoot, {0, 25, 25}},
                                     {Effector::kRFoot, {0, 30, 40}}};
    int solves = 0, convergedAt50 = 0, reachedAt50 = 0, converged300 = 0, reached300 = 0;
    for (const std::string file : {"35_01.amc", "10_03.amc", "16_01.amc"}) {
        const auto version = file == "35_01.amc" ? test::walkModel35() : heldOutModel(file);
        const Skeleton& sk = version->model->clip.skeleton;
        ConstrainedIkSolver solver(version);
        for (int frame : {40, 120}) {
            for (const Move& mv : moves) {
                CAPTURE(file);
                CAPTURE(frame);
                CAPTURE(std::string(effectorName(mv.effector)));
                CAPTURE(mv.offset.transpose());
                ConstrainedIkRequest req = captured(*version, frame);
                FkState fk;
                forwardKinematics(sk, req.start, fk);
                req.constraints = {{mv.effector, effectorCm(sk, fk, mv.effector) + mv.offset, false}};
                // Both feet pinned for a hand move; the other foot for a foot move.
                for (Effector f : {Effector::kLFoot, Effector::kRFoot})
                    if (f != mv.effector) req.constraints.push_back({f, effectorCm(sk, fk, f), true});
                // The editor's budget (50 iterations): pins always hold; count what else holds.
                const ConstrainedIkResult at50 = solver.solve(req);
                ++solves;
                convergedAt50 += at50.converged;
                reachedAt50 += at50.reached;
                CHECK(at50.iterations <= 50);
                for (const auto& c : at50.constraints)
                    if (c.pin) CHECK(c.residualCm <= 0.05);
                CHECK(at50.pose.rootCm == req.start.rootCm);
                // Given 300 iterations.
                req.maxIterations = 300;
                const ConstrainedIkResult res = solver.solve(req);
                MESSAGE(file << " frame " << frame + 1 << " " << std::string(effectorName(mv.effector)) << " "
                             << mv.offset.transpose() << ": at 50 " << std::string(ikStopName(at50.stop)) << ", target "
                             << at50.constraints[0].residualCm << " cm; " << std::string(ikStopName(res.stop)) << " in "
                             << res.iterations << ", target " << res.constraints[0].residualCm << " cm, L_IK "
                             << res.lik);
                converged300 += res.converged;
                reached300 += res.reached;
                for (const auto& c : res.constraints)
                    if (c.pin) CHECK(c.residualCm <= 0.05);
            }
        }
    }
    // The goal is every move converged at 50 iterations; measured (42 moves, committed 35_01
    // fixture): 8 converged and 41 reached at 50, 40 converged and 41 reached at 300 (16_01 frame
    // 41, lhand −25,15,0 stays 0.13 cm short). These floors catch regressions; they are not the goal.
    MESSAGE("at 50 iterations: " << convergedAt50 << "/" << solves << " converged, " << reachedAt50 << "/" << solves
                                 << " reached to 0.05 cm; at 300: " << converged300 << " converged, " << reached300
                                 << " reached");
    CHECK(reachedAt50 >= solves - 1);
    CHECK(converged300 >= solves - 3);
    CHECK(reached300 >= solves - 1);
}

TEST_CASE(
    "constrained IK: a cold start that crawls converges within 50 iterations, at the minimum a 500-iteration solve "
    "finds") {
    // 35_01 fixture, frame 150, left hand moved (−30, 0, 30) cm, the feet in ground contact held
    // as pins (what `motiongp pose` does). Without the crawl rules of docs/maths-ik.md §3 (the
    // shift bracketed, the latent trust radius) this move stops at the cap with F 2473.72 and
    // converges only after 51 trial steps; with them it converged in 47, and with the latent
    // refinement of step 7 as well in 34, at the same F.
    const auto version = test::walkModel35();
    const ConstrainedIkRequest req = poseMove(*version, 149, Effector::kLHand, {-30, 0, 30});
    REQUIRE(req.constraints.size() >= 2);  // at least one foot is pinned
    ConstrainedIkSolver solver(version);
    // The same minimum as the long solve: the rules make the crawl faster, not go elsewhere.
    checkConvergesWithin50AtTheLongSolvesMinimum(solver, req);
}

TEST_CASE("constrained IK: an unreachable hand target with both feet pinned keeps the feet, reached:false, refused") {
    for (const std::string file : {"35_01.amc", "10_03.amc"}) {
        CAPTURE(file);
        const auto version = file == "35_01.amc" ? test::walkModel35() : heldOutModel(file);
        const Skeleton& sk = version->model->clip.skeleton;
        ConstrainedIkSolver solver(version);
        ConstrainedIkRequest req = captured(*version, 60, 200);
        FkState fk;
        forwardKinematics(sk, req.start, fk);
        req.constraints = {
            {Effector::kRHand, effectorCm(sk, fk, Effector::kRHand) + Eigen::Vector3d(120, 120, 0), false},
            {Effector::kLFoot, effectorCm(sk, fk, Effector::kLFoot), true},
            {Effector::kRFoot, effectorCm(sk, fk, Effector::kRFoot), true}};
        const ConstrainedIkResult res = solver.solve(req);
        MESSAGE(file << ": " << std::string(ikStopName(res.stop)) << " after " << res.iterations << ", hand "
                     << res.constraints[0].residualCm << " cm, feet " << res.constraints[1].residualCm << ", "
                     << res.constraints[2].residualCm << " cm, L_IK " << res.lik << " (limit "
                     << version->range.likLimit << "), σ² " << res.sigma2 << " (limit " << version->range.sigma2Limit
                     << ")");
        CHECK_FALSE(res.reached);
        CHECK_FALSE(res.constraints[0].reached);
        CHECK(res.constraints[0].residualCm > 1.0);
        CHECK(res.constraints[1].residualCm <= 0.05);
        CHECK(res.constraints[2].residualCm <= 0.05);
        const AdmissionVerdict verdict =
            admitPose(*version, res.pose, movedEffectors(res.constraints), res.reached, false, res.sigma2, res.lik);
        CHECK_FALSE(verdict.admitted);
        CHECK(verdict.judgement == PoseJudgement::kOutOfReach);
        CHECK(verdict.reason == "a target or pin was not reached");
        // The least-squares answer: no pose that holds the feet gets the hand closer (checked
        // against the same solve run 10× longer).
        req.maxIterations = 2000;
        const ConstrainedIkResult deep = solver.solve(req);
        CHECK(res.constraints[0].residualCm <= deep.constraints[0].residualCm + 0.05);
        // Past 50 steps the out-of-reach target switches the model to full Newton (docs/maths-ik.md
        // docs/maths-ik.md §3 step 6): the least-squares solve becomes stationary (35_01 after 104 steps, 10_03
        // after 182; with Gauss–Newton alone both were still moving after 2000).
        MESSAGE("2000-step solve: " << std::string(ikStopName(deep.stop)) << " after " << deep.iterations << ", hand "
                                    << deep.constraints[0].residualCm << " cm");
        if (file == "35_01.amc") CHECK(res.converged);
        CHECK(deep.converged);
    }
}

TEST_CASE(
    "constrained IK: the floor: a foot target 20 cm below it ends on it, reached:false, refused, and a free foot stays "
    "above it") {
    for (const std::string file : {"35_01.amc", "10_03.amc"}) {
        CAPTURE(file);
        const auto version = file == "35_01.amc" ? test::walkModel35() : heldOutModel(file);
        const Clip& clip = version->model->clip;
        const Skeleton& sk = clip.skeleton;
        const ContactSet contacts = detectFootContacts(clip);
        REQUIRE(contacts.floorCm);
        const double floor = *contacts.floorCm;
        // No captured frame has a foot below the floor (it is the lowest foot point).
        for (const Eigen::Vector3d& p : effectorTrajectory(clip, Effector::kLFoot)) CHECK(p.y() >= floor);
        ConstrainedIkSolver solver(version);
        // Frame 60: the left foot is pushed 20 cm into the ground, the right foot held by a pin.
        ConstrainedIkRequest req = captured(*version, 60, 200);
        req.floorCm = floor;
        const Eigen::Vector3d lfoot = effectorCm(sk, req.start, Effector::kLFoot);
        const Eigen::Vector3d asked(lfoot.x(), floor - 20.0, lfoot.z());
        req.constraints = {{Effector::kLFoot, asked, false},
                           {Effector::kRFoot, effectorCm(sk, req.start, Effector::kRFoot), true}};
        const ConstrainedIkResult res = solver.solve(req);
        const Eigen::Vector3d got = effectorCm(sk, res.pose, Effector::kLFoot);
        MESSAGE(file << ": floor " << floor << " cm, left foot ends " << got.y() - floor << " cm above it, "
                     << (got - asked).norm() << " cm from the target, " << std::string(ikStopName(res.stop)));
        CHECK(got.y() >= floor - 0.5);
        CHECK(got.y() <= floor + 0.05);  // on the floor: the raised target is met
        CHECK_FALSE(res.reached);
        CHECK(res.constraints[0].belowFloor);
        CHECK_FALSE(res.constraints[1].belowFloor);
        CHECK(res.constraints[0].residualCm == doctest::Approx((got - asked).norm()));
        CHECK(res.constraints[0].residualCm >= 19.5);
        CHECK(res.constraints[1].residualCm <= 0.05);
        const AdmissionVerdict verdict = admitPose(*version, res.pose, movedEffectors(res.constraints), res.reached,
                                                   anyBelowFloor(res.constraints), res.sigma2, res.lik);
        CHECK_FALSE(verdict.admitted);
        CHECK(verdict.judgement == PoseJudgement::kThroughFloor);
        CHECK(verdict.reason == "a target is below the floor: the effector was held on it");
        // Without a floor the same target is met below the ground.
        req.floorCm.reset();
        const ConstrainedIkResult sunk = solver.solve(req);
        CHECK(effectorCm(sk, sunk.pose, Effector::kLFoot).y() < floor - 10.0);

        // A free foot: the floor raised 3 cm above where the left foot stands, a hand target
        // and the right foot pinned. The left foot is on no constraint, so the one-sided penalty
        // lifts it onto the floor; without a floor it stays where it was.
        ConstrainedIkRequest lift = captured(*version, 60, 200);
        const double raised = effectorCm(sk, lift.start, Effector::kLFoot).y() + 3.0;
        lift.floorCm = raised;
        lift.constraints = {
            {Effector::kRHand, effectorCm(sk, lift.start, Effector::kRHand) + Eigen::Vector3d(0, 10, 0), false},
            {Effector::kRFoot, effectorCm(sk, lift.start, Effector::kRFoot), true}};
        const ConstrainedIkResult lifted = solver.solve(lift);
        const double freeFoot = effectorCm(sk, lifted.pose, Effector::kLFoot).y();
        MESSAGE(file << ": a free foot 3 cm below a raised floor ends " << freeFoot - raised << " cm from it");
        CHECK(lifted.reached);
        CHECK(freeFoot >= raised - 0.01);
    }
}

TEST_CASE("constrained IK: pins hold to 1e-4 cm through a 200-event hand drag, each event within 50 iterations") {
    const auto version = test::walkModel35();
    const Skeleton& sk = version->model->clip.skeleton;
    ConstrainedIkSolver solver(version);
    ConstrainedIkRequest req = captured(*version, 100);
    FkState fk;
    forwardKinematics(sk, req.start, fk);
    const Eigen::Vector3d hand = effectorCm(sk, fk, Effector::kRHand);
    req.constraints = {{Effector::kRHand, hand, false},
                       {Effector::kLFoot, effectorCm(sk, fk, Effector::kLFoot), true},
                       {Effector::kRFoot, effectorCm(sk, fk, Effector::kRFoot), true}};
    req.rootReferenceDeg = req.start.anglesDeg[0];
    ConstrainedIkResult res = solver.solve(req);
    int converged = 0;
    double worstPin = 0.0, worstStep = 0.0;
    for (int s = 1; s <= 200; ++s) {
        req.start = res.pose;
        req.startX = res.x;
        const Eigen::VectorXd yPrev = res.y;
        req.constraints[0].targetCm = hand + Eigen::Vector3d(0, 0.25 * s, 0.1 * s);
        solver.solve(req, res);
        converged += res.converged;
        worstPin = std::max({worstPin, res.constraints[1].residualCm, res.constraints[2].residualCm});
        worstStep = std::max(worstStep, (res.y - yPrev).cwiseAbs().maxCoeff());
    }
    MESSAGE("converged " << converged << "/200, worst pin " << worstPin << " cm, largest DOF step " << worstStep
                         << "°");
    CHECK(converged >= 190);
    CHECK(worstPin <= 1e-4);
    CHECK(worstStep < 5.0);  // no branch jump for a 0.27 cm step
}

TEST_CASE("constrained IK: re-fitting each trial's latent point lets long cold starts converge within 50 iterations") {
    // Held-out kick fixture, frame 150, the right foot moved 30 cm (0, 0, −30) and the left hand
    // raised 50 cm, the other foot held where it is in contact. Without the latent refinement
    // (docs/maths-ik.md §3 step 7) both stopped at the 50-iteration cap, at F 81.73 and 124.85,
    // short of the minima a 500-iteration solve reaches (70.08 and 111.99); with it they
    // converge in 39 and 33.
    const auto version = test::kickModel1003();
    ConstrainedIkSolver solver(version);
    const Move moves[] = {{Effector::kRFoot, {0, 0, -30}}, {Effector::kLHand, {0, 50, 0}}};
    for (const Move& move : moves) {
        CAPTURE(std::string(effectorName(move.effector)));
        checkConvergesWithin50AtTheLongSolvesMinimum(solver, poseMove(*version, 149, move.effector, move.offset));
    }
}

TEST_CASE(
    "constrained IK: a crawling solve's trust radius on angles and its faster μ decrease keep a slow cold start within "
    "50") {
    // Held-out kick fixture, frame 150, left hand raised 40 cm and moved 10 cm, the feet in contact
    // held. Twice in this solve a long bounded step is rejected at μ ≈ 10⁻¹⁰ and Nielsen's ladder
    // needs several trials before μ shortens it, then lowers μ by ⅓ per step for as many again.
    // Without the angle trust radius and the 10× decrease after a well-predicted step (docs/maths-ik.md
    // docs/maths-ik.md §3 step 6) the solve stopped at the cap (F 69.1158, converged after 52); with them it
    // converges in 28 at the minimum the 500-step solve finds.
    const auto version = test::kickModel1003();
    ConstrainedIkSolver solver(version);
    checkConvergesWithin50AtTheLongSolvesMinimum(solver, poseMove(*version, 149, Effector::kLHand, {0, 40, 10}));
}

TEST_CASE("constrained IK: a foot target at the end of a straight leg switches a crawling solve to the Newton model") {
    // Both fixtures, the right foot moved 30 cm out and 30 cm back ((30, 0, −30) cm): the 35_01 walk
    // on frame 300 with the left foot pinned, the 10_03 kick on frame 120 with no foot in contact.
    // The leg ends straight, where Gauss–Newton cannot see the end of its reach. Without the
    // straight-limb rule (docs/maths-ik.md §3 step 6) both stop at the cap, converging after 70
    // and 59 steps; with it they converge in 35 and 33 steps. (The walk's frame 30, this test's
    // first case until the shortened retry of docs/maths-ik.md §3 step 5, now converges in 52 either way.)
    struct Case {
        gp::ModelVersionPtr version;
        int frame;
    };
    const Case cases[] = {{test::walkModel35(), 299}, {test::kickModel1003(), 119}};
    for (const Case& c : cases) {
        CAPTURE(c.version->model->clip.name);
        ConstrainedIkSolver solver(c.version);
        const ConstrainedIkRequest req = priorOnly(poseMove(*c.version, c.frame, Effector::kRFoot, {30, 0, -30}));
        checkConvergesWithin50AtTheLongSolvesMinimum(solver, req);
        FkState fk;
        forwardKinematics(c.version->model->clip.skeleton, solver.solve(req).pose, fk);
        CHECK(*limbExtension(c.version->model->clip.skeleton, fk, Effector::kRFoot) >= 0.99);
    }
}

TEST_CASE("constrained IK: a trial rejected only for leaving the pins is retried shorter, not after a climb of μ") {
    // 35_01 walk, frame 80, left hand moved (−20, 20, −20) cm; 10_03 kick, frame 270, left foot
    // moved (25, 0, −25) cm; the other feet in contact pinned. Their long early steps lower F as the
    // model predicts (gain ratio 1.00) but leave a pin by more than the 0.001 cm slack. Raising μ
    // alone shortened such a step only after up to seven trials, again and again: both stopped at
    // the cap and converged after 60 and 58 steps. Retried at the length where the pin's
    // second-order error fits the slack (docs/maths-ik.md §3 step 5) they converge in 9 and 16,
    // at the same minimum.
    const FixtureMove cases[] = {{test::walkModel35(), 79, {Effector::kLHand, {-20, 20, -20}}},
                                 {test::kickModel1003(), 269, {Effector::kLFoot, {25, 0, -25}}}};
    for (const FixtureMove& c : cases) {
        CAPTURE(c.version->model->clip.name);
        ConstrainedIkSolver solver(c.version);
        const ConstrainedIkRequest req = poseMove(*c.version, c.frame, c.move.effector, c.move.offset);
        REQUIRE(req.constraints.size() >= 2);  // at least one foot is pinned
        checkConvergesWithin50AtTheLongSolvesMinimum(solver, req);
    }
}

TEST_CASE(
    "constrained IK: a crawling solve keeps an indefinite Newton model, shifted, once Gauss–Newton overpredicts") {
    // 35_01 walk, frame 30, left foot moved (−45, −5, 0) cm; 10_03 kick, frame 60, left foot moved
    // (−25, 0, −25) cm; the other foot free. Without the rule the indefinite Newton model fell
    // back to Gauss–Newton, whose steps lowered F by a quarter to a half of what it promised (on
    // the walk the angle radius shrank to 1.25° and stayed there): both stopped at the cap and
    // converged after 150 and 159 steps. With the Newton model shifted instead of dropped
    // (docs/maths-ik.md §3 step 6) they converge in 29 and 43, at the same minimum.
    const FixtureMove cases[] = {{test::walkModel35(), 29, {Effector::kLFoot, {-45, -5, 0}}},
                                 {test::kickModel1003(), 59, {Effector::kLFoot, {-25, 0, -25}}}};
    for (const FixtureMove& c : cases) {
        CAPTURE(c.version->model->clip.name);
        ConstrainedIkSolver solver(c.version);
        checkConvergesWithin50AtTheLongSolvesMinimum(
            solver, priorOnly(poseMove(*c.version, c.frame, c.move.effector, c.move.offset)));
    }
}

TEST_CASE(
    "constrained IK: a crawling solve's latent trust radius shrinks below the fixed bound when it cut a rejected "
    "step") {
    // 10_03 kick, frames 310 and 220, left foot moved (0, 0, −30) and (−30, 0, 0) cm, the right
    // foot pinned. Latent steps cut to the fixed bound (half the RBF length scale) were rejected
    // at negative gain ratios, and the identical retries failed until Nielsen's ladder had raised
    // μ from 10⁻¹²–10⁻⁹: they stopped at the cap and converged after 114 and 57 steps. With the
    // radius halved below the bound (docs/maths-ik.md §3 step 6) they converge in 38 and 40.
    const auto kick = test::kickModel1003();
    const FixtureMove cases[] = {{kick, 309, {Effector::kLFoot, {0, 0, -30}}},
                                 {kick, 219, {Effector::kLFoot, {-30, 0, 0}}}};
    ConstrainedIkSolver solver(kick);
    for (const FixtureMove& c : cases) {
        CAPTURE(c.frame);
        const ConstrainedIkRequest req = poseMove(*c.version, c.frame, c.move.effector, c.move.offset);
        REQUIRE(req.constraints.size() == 2);  // the right foot is pinned
        checkConvergesWithin50AtTheLongSolvesMinimum(solver, req);
    }
}

TEST_CASE(
    "constrained IK: a crawling solve's full-length step rejected on its merit sets the angle trust radius to half its "
    "length") {
    // 10_03 kick, frame 281, right foot moved (50, 0, 0) cm, and frame 356, left hand moved
    // (0, −35, 0) cm, the one foot in contact pinned. Full-length steps that neither bound had cut
    // were rejected, and the retries at μ ≈ 10⁻¹² were about the same step: the first move retried
    // it seven times while Nielsen's ladder raised μ to the model's curvature; the second, already
    // at its minimum's F, alternated such rejections with short accepted steps from step 23 on.
    // They stopped at the cap and converged after 53 and 59 steps. With the angle radius set to
    // half the rejected step's largest angle change (docs/maths-ik.md §3 step 6) they converge in
    // 40 and 41.
    const auto kick = test::kickModel1003();
    const FixtureMove cases[] = {{kick, 280, {Effector::kRFoot, {50, 0, 0}}},
                                 {kick, 355, {Effector::kLHand, {0, -35, 0}}}};
    ConstrainedIkSolver solver(kick);
    for (const FixtureMove& c : cases) {
        CAPTURE(c.frame);
        ConstrainedIkRequest req = poseMove(*c.version, c.frame, c.move.effector, c.move.offset);
        // These requests were found when a contact was the toe's flat phase alone; the left foot's
        // toe-off at frame 356, held since (docs/maths.md §13), was free then. It is released so the
        // request stays the one the mechanism was found on.
        req.balance.reset();  // the balance term came later; these solves were found without it
        if (c.frame == 355)
            req.constraints.erase(std::remove_if(req.constraints.begin(), req.constraints.end(),
                                                 [](const IkConstraint& k) { return k.effector == Effector::kLFoot; }),
                                  req.constraints.end());
        REQUIRE(req.constraints.size() == 2);  // the one foot in contact is pinned
        checkConvergesWithin50AtTheLongSolvesMinimum(solver, req);
    }
}

TEST_CASE("constrained IK: strength runs from natural to exact, and the root turns only as much as needed") {
    const auto version = test::walkModel35();
    const Skeleton& sk = version->model->clip.skeleton;
    ConstrainedIkSolver solver(version);
    ConstrainedIkRequest req = captured(*version, 100, 200);
    const Eigen::Vector3d hand = effectorCm(sk, req.start, Effector::kRHand) + Eigen::Vector3d(0, 25, 15);
    double prevResidual = 1e9;
    for (double s : {0.5, 0.9, 0.999, 1.0}) {
        CAPTURE(s);
        req.constraints = {{Effector::kRHand, hand, false, s}};
        const ConstrainedIkResult res = solver.solve(req);
        MESSAGE("strength " << s << ": residual " << res.constraints[0].residualCm << " cm, L_IK " << res.lik << ", "
                            << std::string(ikStopName(res.stop)));
        CHECK(res.converged);
        CHECK(res.constraints[0].strength == s);
        CHECK(res.constraints[0].residualCm <= prevResidual + 1e-9);  // stronger: closer
        prevResidual = res.constraints[0].residualCm;
    }
    CHECK(prevResidual <= 0.05);
    // A stiffer root moves the root less for the same (reached) target.
    req.constraints = {{Effector::kRHand, hand, false}};
    req.rootStiffness = 0.0;
    const ConstrainedIkResult loose = solver.solve(req);
    req.rootStiffness = 50.0;
    const ConstrainedIkResult stiff = solver.solve(req);
    const double looseTurn = (loose.pose.anglesDeg[0] - req.start.anglesDeg[0]).cwiseAbs().maxCoeff();
    const double stiffTurn = (stiff.pose.anglesDeg[0] - req.start.anglesDeg[0]).cwiseAbs().maxCoeff();
    MESSAGE("root change: " << looseTurn << "° free, " << stiffTurn << "° at k_root = 50");
    CHECK(stiffTurn <= looseTurn + 1e-9);
    CHECK(stiff.constraints[0].residualCm <= 0.05);
}

TEST_CASE("constrained IK: bad requests give one clear diagnostic and the start pose") {
    const auto version = test::walkModel35();
    ConstrainedIkSolver solver(version);
    ConstrainedIkRequest req = captured(*version, 10);
    req.constraints = {{Effector::kHead, Eigen::Vector3d(0, NAN, 0), false}};
    ConstrainedIkResult res = solver.solve(req);
    CHECK(res.stop == IkStop::kInvalidRequest);
    CHECK(res.diagnostic == "expected a finite target for head, found NaN or Inf");
    CHECK_FALSE(res.reached);
    req.constraints = {{Effector::kHead, Eigen::Vector3d::Zero(), false, 1.5}};
    res = solver.solve(req);
    CHECK(res.diagnostic == "expected a strength in (0, 1] for head, found 1.500000");
    req.constraints.clear();
    req.startX = Eigen::VectorXd::Zero(3);
    res = solver.solve(req);
    CHECK(res.diagnostic == "expected a 2-D latent start, found 3");
}

TEST_CASE("training range: the 99th percentiles of the captured frames scored as new poses") {
    const auto version = test::walkModel35();
    const gp::TrainingRange& r = version->range;
    CHECK(r.rows == version->model->N());
    CHECK(r.percentile == 99.0);
    CHECK(r.sigma2Limit >= r.sigma2Median);
    CHECK(r.likLimit >= r.likMedian);
    // By construction about 1 % of the held-out scores lie above each percentile.
    std::vector<double> s2, lik;
    gp::heldOutMomentScores(*version->model, *version->posterior, gp::kHeldOutWindowFrames, s2, lik);
    REQUIRE(static_cast<int>(lik.size()) == version->model->N());
    int above = 0, aboveS2 = 0;
    for (std::size_t i = 0; i < lik.size(); ++i) {
        above += lik[i] > r.likLimit;
        aboveS2 += s2[i] > r.sigma2Percentile;
    }
    CHECK(above <= version->model->N() / 100 + 1);
    CHECK(aboveS2 <= version->model->N() / 100 + 1);
    // Hiding a row's moment is what makes it a new pose: in-sample, rows score below the
    // held-out median for most rows (σ² ≈ 1/β at an active row; measured 319 of 358).
    gp::PointWorkspace ws;
    int inSampleBelowMedian = 0;
    for (int i = 0; i < version->model->N(); ++i)
        inSampleBelowMedian +=
            version->posterior->evaluate(version->model->X.row(i).transpose(), version->model->Y.row(i).transpose(), ws,
                                         nullptr, nullptr) < r.likMedian;
    CHECK(inSampleBelowMedian >= version->model->N() * 8 / 10);
    // A window of 0 frames hides only the row itself, so the scores fall as the window shrinks.
    std::vector<double> s2Own, likOwn;
    gp::heldOutMomentScores(*version->model, *version->posterior, 0, s2Own, likOwn);
    double sumOwn = 0.0, sumWindow = 0.0;
    for (std::size_t i = 0; i < lik.size(); ++i) sumOwn += likOwn[i], sumWindow += lik[i];
    CHECK(sumOwn < sumWindow);
}

TEST_CASE("point model: predicting while holding out active points equals a model built without them") {
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    const Eigen::MatrixXd XI = m.activeX(), Yhat = m.activeYhat();
    const gp::Kernel kernel = version->posterior->kernel();
    const std::vector<int> heldOut = {3, 4, 5, 17, 90};
    std::vector<int> kept;
    for (int j = 0; j < XI.rows(); ++j)
        if (std::find(heldOut.begin(), heldOut.end(), j) == heldOut.end()) kept.push_back(j);
    Eigen::MatrixXd XK(static_cast<Eigen::Index>(kept.size()), XI.cols()),
        YK(static_cast<Eigen::Index>(kept.size()), Yhat.cols());
    for (std::size_t r = 0; r < kept.size(); ++r) {
        XK.row(static_cast<Eigen::Index>(r)) = XI.row(kept[r]);
        YK.row(static_cast<Eigen::Index>(r)) = Yhat.row(kept[r]);
    }
    const gp::ActiveSetPosterior reduced(kernel, XK, YK, m.mu, m.w);
    REQUIRE(version->posterior->jitter() == 0.0);
    REQUIRE(reduced.jitter() == 0.0);
    for (const int row : {4, 60, 200}) {
        CAPTURE(row);
        // At a held-out point itself, at a training row, and between two rows.
        const Eigen::VectorXd x = row == 4 ? Eigen::VectorXd(XI.row(4).transpose())
                                           : Eigen::VectorXd(0.5 * (m.X.row(row) + m.X.row(row + 1)).transpose());
        Eigen::VectorXd meanHeld, meanReduced;
        double varHeld = 0.0, varReduced = 0.0;
        version->posterior->predictHoldingOut(x, heldOut, meanHeld, varHeld);
        reduced.predict(x, meanReduced, varReduced);
        CHECK((meanHeld - meanReduced).cwiseAbs().maxCoeff() <= 1e-7 * (1.0 + meanReduced.cwiseAbs().maxCoeff()));
        CHECK(std::abs(varHeld - varReduced) <= 1e-9 * (1.0 + varReduced));
        // Holding out nothing is the plain prediction.
        Eigen::VectorXd meanAll, meanNone;
        double varAll = 0.0, varNone = 0.0;
        version->posterior->predict(x, meanAll, varAll);
        version->posterior->predictHoldingOut(x, {}, meanNone, varNone);
        CHECK(meanNone == meanAll);
        CHECK(varNone == varAll);
    }
}
