// Rotate joint (docs/maths-ik.md §7) and mirror pose on the document (docs/maths.md §21): held
// DOFs in the constrained solver (gradient against central differences), the prior's pose against
// the plain rotation, one undo step each.
#include <cmath>

#include <Eigen/Geometry>

#include "central_difference.h"
#include "document_helpers.h"
#include "edit/joint_rotation.h"
#include "edit/mirror_edit.h"
#include "ik/constrained_ik.h"
#include "ik/plain_ik.h"
#include "io/clip_loader.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_mirror.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

namespace {

// The index into z = (x, y) of pose DOF (joint, axis), −1 when it is not a kept column.
int zIndexOf(const gp::GpModel& m, int joint, int axis) {
    const PoseLayout layout(m.clip.skeleton);
    for (int dof = 0; dof < kAsfPoseDofs; ++dof)
        if (layout.joint(dof) == joint && layout.axis(dof) == axis)
            for (int k = 0; k < m.D(); ++k)
                if (m.keptColumns[k] == dof) return m.latentDim() + k;
    return -1;
}

// min over x of L_IK(x, y(pose)): every kept DOF held, only the latent point free.
double bestLik(const gp::ModelVersionPtr& v, const Pose& pose, const Eigen::VectorXd& startX) {
    const Skeleton& sk = v->model->clip.skeleton;
    ConstrainedIkRequest req;
    req.start = pose;
    req.startX = startX;
    for (int j = 0; j < sk.jointCount(); ++j)
        for (int a = 0; a < 3; ++a)
            if (sk.joints[j].dof[a]) req.held.push_back({j, a, pose.anglesDeg[j][a]});
    req.maxIterations = 200;
    ConstrainedIkSolver solver(v);
    const ConstrainedIkResult r = solver.solve(req);
    REQUIRE(r.stop != IkStop::kInvalidRequest);
    return r.lik;
}

}  // namespace

TEST_CASE("constrained IK with held DOFs: ∇F over the free unknowns matches central differences, held entries are 0") {
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    const Skeleton& sk = m.clip.skeleton;
    ConstrainedIkSolver solver(version);
    ConstrainedIkRequest req;
    req.start = m.clip.frames[100];
    req.startX = latentStartForFrame(*version, 100);
    const int humerus = sk.findBone("lhumerus"), tibia = sk.findBone("rtibia");
    req.held = {{humerus, 0, 20.0}, {humerus, 1, -10.0}, {humerus, 2, 35.0}, {tibia, 0, 40.0}};
    req.constraints = {
        {Effector::kRHand, effectorCm(sk, req.start, Effector::kRHand) + Eigen::Vector3d(-5, 2, 1), false, 0.9},
        {Effector::kLFoot, effectorCm(sk, req.start, Effector::kLFoot), true}};
    Eigen::VectorXd z = solver.startPoint(req);
    std::vector<int> held;
    for (const HeldDof& h : req.held) {
        const int i = zIndexOf(m, h.joint, h.axis);
        REQUIRE(i >= 0);
        CHECK(z[i] == h.valueDeg);  // the start point carries the held values
        held.push_back(i);
    }
    const int d = m.latentDim();
    z.head(d).array() += 0.05;
    for (int k = d; k < z.size(); ++k) z[k] += 0.3 * std::sin(k);
    Eigen::VectorXd g;
    const double F = solver.objective(req, z, &g);
    const Eigen::MatrixXd H = solver.hessianModel();
    // F is steep in x here (|dF/dx| = 5e5): the difference quotient's error on x is round-off
    // (0.4 to 0.6, build-dependent) at h = 1e-6 and truncation, h^2 |F'''|/6, 0.6 at h = 1e-4.
    // h = 1e-5 balances the two at about a tenth of the tolerance.
    const double h = 1e-5;
    double worst = 0.0;
    for (int i = 0; i < z.size(); ++i) {
        if (std::find(held.begin(), held.end(), i) != held.end()) {
            CHECK(g[i] == 0.0);
            CHECK(H(i, i) == 1.0);
            CHECK((H.row(i).cwiseAbs().sum() - 1.0) == 0.0);
            continue;
        }
        const double numeric = test::centralDifference(
            [&](const Eigen::VectorXd& v) { return solver.objective(req, v, nullptr); }, z, i, h);
        worst = std::max(worst, std::abs(numeric - g[i]));
    }
    MESSAGE("∇F with held DOFs: max abs error " << worst << " against |g|∞ " << g.cwiseAbs().maxCoeff() << ", F " << F);
    CHECK(worst < 1e-6 * g.cwiseAbs().maxCoeff());
    // A held DOF named twice or out of range is refused with a message.
    ConstrainedIkRequest bad = req;
    bad.held.push_back(bad.held.front());
    CHECK(solver.validate(bad).find("twice") != std::string::npos);
    bad.held = {{sk.jointCount(), 0, 1.0}};
    CHECK(solver.validate(bad).find("expected a held DOF") != std::string::npos);
}

TEST_CASE("rotate joint with the learned prior on 35_01: held DOFs exact, pins hold, L_IK below the plain rotation's") {
    const auto version = test::walkModel35();
    EditorDocument doc;
    doc.setModel(version, true);
    doc.setFrame(60);
    doc.setPinned(Effector::kLFoot, true);
    doc.setPinned(Effector::kRFoot, true);
    const Skeleton& sk = doc.clip().skeleton;
    const Pose before = doc.currentPose();
    struct Case {
        const char* bone;
        Eigen::Vector3d delta;
    };
    for (const Case& c : {Case{"lhumerus", {30.0, -20.0, 15.0}}, Case{"lowerback", {15.0, 0.0, 0.0}},
                          Case{"rfemur", {-25.0, 0.0, 0.0}}}) {
        CAPTURE(c.bone);
        const int j = sk.findBone(c.bone);
        REQUIRE(j >= 0);
        JointRotation rot;
        rot.joint = j;
        rot.anglesDeg = before.anglesDeg[j] + c.delta;
        const JointRotationResult plain = solveJointRotation(doc, rot);
        REQUIRE(plain.error.empty());
        rot.followPrior = true;
        const JointRotationResult prior = solveJointRotation(doc, rot);
        REQUIRE(prior.error.empty());
        CHECK(prior.learned);
        double heldErr = 0.0;
        for (int a = 0; a < 3; ++a)
            if (sk.joints[j].dof[a])
                heldErr = std::max(heldErr, std::abs(prior.pose.anglesDeg[j][a] - rot.anglesDeg[a]));
        double pinErr = 0.0;
        for (const IkConstraintResult& cr : prior.ik.constraints) pinErr = std::max(pinErr, cr.residualCm);
        const Eigen::VectorXd x0 = doc.currentLatent();
        const double likPlain = bestLik(version, plain.pose, x0);
        double plainPinMove = 0.0;
        for (Effector foot : {Effector::kLFoot, Effector::kRFoot})
            plainPinMove =
                std::max(plainPinMove, (effectorCm(sk, plain.pose, foot) - effectorCm(sk, before, foot)).norm());
        MESSAGE(std::string(c.bone) << " +" << c.delta.transpose() << ": held DOFs " << heldErr << " deg, pins "
                                    << pinErr << " cm, L_IK prior " << prior.ik.lik << " vs plain (best x) " << likPlain
                                    << ", " << prior.ik.iterations << " iterations, " << ikStopName(prior.ik.stop)
                                    << "; the plain rotation moves a pinned foot by " << plainPinMove << " cm");
        CHECK(heldErr <= 1e-6);
        CHECK(prior.ik.constraints.size() == 2);
        CHECK(pinErr <= 0.05);
        // The plain rotation keeps the pins too: untouched (the arm, the back) or settled (the
        // femur moves a pinned foot; the legs and the root bring it back). The prior's solve starts
        // from that pose and keeps its root, so the plain pose is a candidate of the prior's
        // problem and the prior's pose must be at least as likely.
        CHECK(plainPinMove <= kSettledHoldCm);
        CHECK(plain.settled == (std::string(c.bone) == "rfemur"));
        CHECK(prior.settled == plain.settled);
        CHECK(prior.ik.lik < likPlain);
        CHECK(prior.pose.rootCm == plain.pose.rootCm);
        if (plain.settled) CHECK((plain.pose.rootCm - before.rootCm).norm() > 0.1);
    }
    CHECK(posesIdentical(doc.currentPose(), before));  // solving changes nothing in the document
}

TEST_CASE(
    "rotate joint: the plain rotation changes exactly that joint's DOFs unless it moves a planted foot (the legs and "
    "the root bring it back) and is one undo step") {
    EditorDocument doc;
    doc.setModel(test::walkModel35(), true);
    doc.setFrame(12);
    const Pose before = doc.currentPose();
    const Skeleton& sk = doc.clip().skeleton;
    const int j = sk.findBone("ltibia");
    REQUIRE(doc.inContact(Effector::kLFoot));
    JointRotation rot;
    rot.joint = j;
    rot.anglesDeg = Eigen::Vector3d(75.0, 5.0, 5.0);  // the tibia animates x only: y and z are ignored
    // With the left foot's contact released nothing held is below the knee: plain forward kinematics.
    doc.setContactReleased(Effector::kLFoot, true);
    const JointRotationResult free = solveJointRotation(doc, rot);
    REQUIRE(free.error.empty());
    CHECK_FALSE(free.settled);
    CHECK(free.pose.rootCm == before.rootCm);
    for (int k = 0; k < sk.jointCount(); ++k)
        for (int a = 0; a < 3; ++a) {
            if (k == j && a == 0)
                CHECK(free.pose.anglesDeg[k][a] == 75.0);
            else
                CHECK(free.pose.anglesDeg[k][a] == before.anglesDeg[k][a]);
        }
    // Planted, the foot stays: the knee's angle as asked, the root rotation and every joint off the
    // legs' chains as they were; the root translation and the legs move.
    doc.setContactReleased(Effector::kLFoot, false);
    REQUIRE(applyJointRotation(doc, rot) == "");
    const Pose& after = doc.currentPose();
    CHECK(after.anglesDeg[j][0] == 75.0);
    for (Effector foot : {Effector::kLFoot, Effector::kRFoot})
        if (doc.inContact(foot))
            CHECK((effectorCm(sk, after, foot) - effectorCm(sk, before, foot)).norm() <= kSettledHoldCm);
    CHECK((after.rootCm - before.rootCm).norm() > 1.0);
    const int leftFoot = sk.effectorSite(Effector::kLFoot).joint, rightFoot = sk.effectorSite(Effector::kRFoot).joint;
    for (int k = 0; k < sk.jointCount(); ++k) {
        const bool onLeg = k != 0 && (sk.isAncestorOrSelf(k, leftFoot) || sk.isAncestorOrSelf(k, rightFoot));
        if (!onLeg) CHECK(after.anglesDeg[k] == before.anglesDeg[k]);
    }
    CHECK(doc.undoLabel() == "rotate ltibia on frame 13");
    REQUIRE(doc.undo() == "");
    CHECK(posesIdentical(doc.currentPose(), before));
    CHECK_FALSE(doc.canUndo());
    // Without a model the prior option says why, and nothing changes.
    EditorDocument bare;
    bare.setClip(doc.clip());
    rot.followPrior = true;
    const std::string err = applyJointRotation(bare, rot);
    CHECK(err.find("needs a model") != std::string::npos);
    CHECK_FALSE(bare.canUndo());
    rot.joint = 999;
    CHECK(applyJointRotation(bare, rot).find("expected a joint") != std::string::npos);
}

TEST_CASE("mirror pose on the document is one undo step, and mirroring twice restores the pose") {
    EditorDocument doc;
    doc.setModel(test::walkModel35(), true);
    doc.setFrame(40);
    // Nothing kept in place (the planted foot released): the mirror exactly, not re-solved.
    doc.setContactReleased(Effector::kLFoot, true);
    doc.setContactReleased(Effector::kRFoot, true);
    const Pose before = doc.currentPose();
    REQUIRE(mirrorCurrentPose(doc) == "");
    CHECK(doc.undoLabel() == "mirror pose on frame 41");
    const Skeleton& sk = doc.clip().skeleton;
    // The left femur now has the right femur's flexion (x kept, y and z negated: mirror-symmetric axes).
    const int lf = sk.findBone("lfemur"), rf = sk.findBone("rfemur");
    CHECK(doc.currentPose().anglesDeg[lf][0] == before.anglesDeg[rf][0]);
    CHECK(doc.currentPose().anglesDeg[lf][1] == -before.anglesDeg[rf][1]);
    REQUIRE(mirrorCurrentPose(doc) == "");
    for (int k = 1; k < sk.jointCount(); ++k)
        CHECK((doc.currentPose().anglesDeg[k] - before.anglesDeg[k]).cwiseAbs().maxCoeff() < 1e-9);
    REQUIRE(doc.undo() == "");
    REQUIRE(doc.undo() == "");
    CHECK(posesIdentical(doc.currentPose(), before));
    EditorDocument empty;
    CHECK(mirrorCurrentPose(empty).find("no clip") != std::string::npos);
}

TEST_CASE(
    "mirror, paste and a rotation with the prior keep a planted foot where it was, on the frame and on its "
    "neighbours") {
    // On a walk frame with a planted foot, the mirrored (or pasted) pose is re-solved under the
    // prior so that the foot stays; a rotation with the prior solves with it held. The spread keeps
    // it on the neighbouring frames where it was planted (it used to follow the pose layer: tens of
    // cm off its footprint; for the rotation until the spread held its holds too).
    EditorDocument doc;
    doc.setModel(test::walkModel35(), true);
    doc.setAdaptiveEnabled(false);
    doc.setDragFalloff(20);
    const Skeleton& sk = doc.clip().skeleton;
    const int t = 40;
    doc.setFrame(t);
    std::vector<Effector> planted;
    for (Effector foot : {Effector::kLFoot, Effector::kRFoot})
        if (doc.inContact(foot)) planted.push_back(foot);
    REQUIRE_FALSE(planted.empty());
    auto footAt = [&](int s, Effector foot) { return effectorCm(sk, doc.poseAt(s), foot); };
    auto capturedAt = [&](int s, Effector foot) { return effectorCm(sk, doc.clip().frames[s], foot); };
    // The rotation bends the knee of a planted leg: the solve keeps the foot and moves the body.
    const int knee = sk.findBone(planted.front() == Effector::kLFoot ? "ltibia" : "rtibia");
    REQUIRE(knee >= 0);
    for (const char* op : {"mirror", "paste", "rotate with the prior"}) {
        INFO(std::string(op));
        doc.setFrame(t);
        std::string err;
        if (std::string(op) == "mirror") {
            err = mirrorCurrentPose(doc);
        } else if (std::string(op) == "paste") {
            err = doc.pastePose(doc.clip().frames[220]);
        } else {
            JointRotation r;
            r.joint = knee;
            r.anglesDeg = doc.currentPose().anglesDeg[knee] + Eigen::Vector3d(30, 0, 0);
            r.followPrior = true;
            err = applyJointRotation(doc, r);
        }
        REQUIRE(err == "");
        doc.waitIdle();
        CHECK(doc.pollRegenerate().find(": spread over frames") != std::string::npos);
        // The rotation's own frame is its solve's (a bent knee may not quite keep its foot): the
        // neighbours are what the spread decides. Mirror and paste re-solve their frame to keep it.
        const bool rotation = std::string(op) == "rotate with the prior";
        double worst = 0.0;
        for (Effector foot : planted)
            for (int s = t - 20; s <= t + 20; ++s)
                if ((s != t || !rotation) && doc.contacts().at(foot, s))
                    worst = std::max(worst, (footAt(s, foot) - capturedAt(s, foot)).norm());
        MESSAGE("planted foot, worst distance from its captured place over the spread: " << worst << " cm");
        CHECK(worst <= 1.0);
        // Mirror and paste keep the sole on their frame: the planted foot's ankle stays too, so the
        // foot does not tip onto its toe or put its heel through the floor.
        if (!rotation)
            for (Effector foot : planted) {
                const int ankle = sk.effectorSite(foot).joint;
                FkState now, captured;
                forwardKinematics(sk, doc.poseAt(t), now);
                forwardKinematics(sk, doc.clip().frames[t], captured);
                const double moved = (now.jointCm[ankle] - captured.jointCm[ankle]).norm();
                MESSAGE(std::string(effectorName(foot))
                        << "'s ankle on the frame: " << moved << " cm from its captured place");
                CHECK(moved <= kSettledHoldCm);
            }
        REQUIRE(doc.undo().empty());
    }
}

TEST_CASE("rotate joint about a world axis (the gizmo's view ring): the joint's frame turns by exactly that rotation") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    const Skeleton& sk = clip.skeleton;
    const int femur = sk.findBone("rfemur"), tibia = sk.findBone("rtibia");
    REQUIRE(femur >= 0);
    REQUIRE(tibia >= 0);
    const Pose& pose = clip.frames[60];
    FkState before, after;
    forwardKinematics(sk, pose, before);
    const Eigen::Vector3d axis = Eigen::Vector3d(0.3, 0.8, -0.5).normalized();
    for (const double degrees : {2.0, 25.0, -70.0}) {
        CAPTURE(degrees);
        const std::optional<Eigen::Vector3d> angles = anglesTurnedAboutWorldAxis(sk, pose, femur, axis, degrees);
        REQUIRE(angles.has_value());
        forwardKinematics(sk, rotateJoint(sk, pose, femur, *angles), after);
        const Eigen::Matrix3d R = Eigen::AngleAxisd(degrees * kDegToRad, axis).toRotationMatrix();
        CHECK((after.global[femur] - R * before.global[femur]).cwiseAbs().maxCoeff() < 1e-9);
        // The subtree turns about the hip with it; the rest of the body stays.
        const Eigen::Vector3d hip = before.jointCm[femur];
        CHECK((after.jointCm[tibia] - (hip + R * (before.jointCm[tibia] - hip))).norm() < 1e-9);
        CHECK((after.jointCm[0] - before.jointCm[0]).norm() == 0.0);
        // The Euler triple nearest the old one: a small turn changes each angle a little.
        if (degrees == 2.0) CHECK((*angles - pose.anglesDeg[femur]).cwiseAbs().maxCoeff() < 5.0);
    }
    // A knee animates one axis only: a turn about an arbitrary axis is not one of its poses.
    CHECK_FALSE(anglesTurnedAboutWorldAxis(sk, pose, tibia, axis, 10.0).has_value());
}

TEST_CASE(
    "rotate joint with the prior: a knee bent over its planted foot lowers the hips instead of tipping the foot") {
    // Before, the prior's solve (which keeps the root translation) held the ball by tipping the foot
    // onto its toe (the ankle 5 cm up, the hips where they were, "stalled").
    EditorDocument doc;
    doc.setModel(test::walkModel35(), true);
    doc.setFrame(145);
    const Skeleton& sk = doc.clip().skeleton;
    REQUIRE(doc.inContact(Effector::kLFoot));
    REQUIRE(doc.inContact(Effector::kRFoot));
    const Pose before = doc.currentPose();
    const int knee = sk.findBone("rtibia"), ankle = sk.findBone("rfoot");
    JointRotation rot;
    rot.joint = knee;
    rot.anglesDeg = before.anglesDeg[knee] + Eigen::Vector3d(30, 0, 0);
    rot.followPrior = true;
    const JointRotationResult r = solveJointRotation(doc, rot);
    REQUIRE(r.error.empty());
    REQUIRE(r.learned);
    FkState a, b;
    forwardKinematics(sk, before, b);
    forwardKinematics(sk, r.pose, a);
    const double heelRise = a.jointCm[ankle].y() - b.jointCm[ankle].y();
    MESSAGE("hips " << r.pose.rootCm.y() - before.rootCm.y() << " cm, right ankle " << heelRise << " cm, feet within "
                    << r.holdMissCm << " cm, L_IK " << r.ik.lik << " (" << ikStopName(r.ik.stop) << ")");
    CHECK(r.holdMissCm <= kSettledHoldCm);
    CHECK(r.pose.anglesDeg[knee].x() == rot.anglesDeg.x());
    CHECK(r.pose.rootCm.y() < before.rootCm.y() - 1.0);  // the hips came down
    CHECK(std::abs(heelRise) <= kSettledHoldCm);         // the foot stays on its sole (its ankle held)
}
