// The constrained IK's balance term (docs/maths-ik.md §1, §2): the distance outside a grown support
// polygon with its gradient and curvature, the centre of mass's Jacobian and contracted Hessian, ∇F
// with the term active, each against central differences; then what the term does to a hand pulled
// far out on the walk.
#include <algorithm>
#include <cmath>

#include "central_difference.h"
#include "ik/balance_region.h"
#include "ik/constrained_ik.h"
#include "motion/captured_pose_request.h"
#include "motion/support_polygon.h"
#include "skeleton/centre_of_mass.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("balance region: distance outside a grown polygon, its direction and curvature") {
    const BalanceRegion square{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, 5.0};
    Eigen::Vector2d n;
    double k = -1.0;
    CHECK(square.outsideCm({5, 5}, &n, &k) == 0.0);  // inside
    CHECK(n.isZero());
    CHECK(k == 0.0);
    CHECK(square.outsideCm({13, 5}) == 0.0);                           // within the grown margin
    CHECK(square.outsideCm({20, 5}, &n, &k) == doctest::Approx(5.0));  // beside an edge: flat
    CHECK(n.isApprox(Eigen::Vector2d(1, 0)));
    CHECK(k == 0.0);
    CHECK(square.outsideCm({20, 20}, &n, &k) == doctest::Approx(std::sqrt(200.0) - 5.0));  // off a corner: round
    CHECK(n.isApprox(Eigen::Vector2d(1, 1).normalized()));
    CHECK(k == doctest::Approx(1.0 / std::sqrt(200.0)));
    const BalanceRegion point{{{1, 2}}, 5.0};
    CHECK(point.outsideCm({1, 10}) == doctest::Approx(3.0));
    CHECK(BalanceRegion{}.outsideCm({0, 0}) == INFINITY);
    // The gradient and the Hessian k(I − nnᵀ) against central differences, at a corner and an edge.
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(17.0, 23.0), Eigen::Vector2d(4.0, -9.0)}) {
        CAPTURE(p.transpose());
        square.outsideCm(p, &n, &k);
        const auto dist = [&](const Eigen::VectorXd& q) { return square.outsideCm(Eigen::Vector2d(q[0], q[1])); };
        const auto dirAt = [&](const Eigen::VectorXd& q, int c) {
            Eigen::Vector2d m;
            square.outsideCm(Eigen::Vector2d(q[0], q[1]), &m);
            return m[c];
        };
        const Eigen::VectorXd z = p;
        const Eigen::Matrix2d hess = k * (Eigen::Matrix2d::Identity() - n * n.transpose());
        for (int i = 0; i < 2; ++i) {
            CHECK(test::centralDifference(dist, z, i) == doctest::Approx(n[i]).epsilon(1e-6));
            for (int c = 0; c < 2; ++c)
                CHECK(test::centralDifference([&](const Eigen::VectorXd& q) { return dirAt(q, c); }, z, i) ==
                      doctest::Approx(hess(c, i)).epsilon(1e-5).scale(1e-3));
        }
    }
}

TEST_CASE("centre of mass: its Jacobian and contracted Hessian match central differences") {
    const auto version = test::walkModel35();
    const Skeleton& sk = version->model->clip.skeleton;
    const PoseLayout layout(sk);
    const BodyMass body(sk);
    const Pose pose = version->model->clip.frames[77];
    const Eigen::VectorXd y0 = layout.extract(pose);
    FkState fk;
    forwardKinematics(sk, pose, fk);
    Eigen::Matrix<double, 3, Eigen::Dynamic> J(3, layout.size()), Jp(3, layout.size()), Jm(3, layout.size());
    REQUIRE(centreOfMassJacobian(sk, body, layout, fk, pose, J));
    const Eigen::Vector3d lambda(0.7, -1.3, 2.1);
    Eigen::MatrixXd Hc(layout.size(), layout.size());
    centreOfMassHessianContracted(sk, body, layout, fk, pose, lambda, Hc);
    const auto poseAt = [&](const Eigen::VectorXd& y) {
        Pose p = pose;
        layout.apply(y.data(), p);
        return p;
    };
    double worstJ = 0.0, worstH = 0.0;
    for (int i = 0; i < layout.size(); ++i) {
        const double h = 1e-4;  // degrees
        Eigen::VectorXd yp = y0, ym = y0;
        yp[i] += h;
        ym[i] -= h;
        const Eigen::Vector3d numeric = (*centreOfMass(sk, poseAt(yp)) - *centreOfMass(sk, poseAt(ym))) / (2 * h);
        worstJ = std::max(worstJ, (numeric - J.col(i)).cwiseAbs().maxCoeff());
        FkState fp, fm;
        forwardKinematics(sk, poseAt(yp), fp);
        forwardKinematics(sk, poseAt(ym), fm);
        centreOfMassJacobian(sk, body, layout, fp, poseAt(yp), Jp);
        centreOfMassJacobian(sk, body, layout, fm, poseAt(ym), Jm);
        const Eigen::RowVectorXd dLambdaJ = lambda.transpose() * (Jp - Jm) / (2 * h);
        worstH = std::max(worstH, (dLambdaJ.transpose() - Hc.col(i)).cwiseAbs().maxCoeff());
    }
    MESSAGE("∂c/∂y: max |J| " << J.cwiseAbs().maxCoeff() << ", error " << worstJ << "; λ·∂²c/∂y²: max "
                              << Hc.cwiseAbs().maxCoeff() << ", error " << worstH);
    CHECK(J.cwiseAbs().maxCoeff() > 0.1);
    CHECK(worstJ < 1e-7 * J.cwiseAbs().maxCoeff());
    CHECK(worstH < 1e-6 * Hc.cwiseAbs().maxCoeff());
    CHECK((Hc - Hc.transpose()).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("constrained IK: ∇F with the balance term active matches central differences") {
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    const Skeleton& sk = m.clip.skeleton;
    ConstrainedIkSolver solver(version);
    ConstrainedIkRequest req;
    req.start = m.clip.frames[100];
    req.startX = latentStartForFrame(*version, 100);
    const Eigen::Vector3d c = *centreOfMass(sk, req.start);
    // A support 12 cm beside the centre of mass, around a corner and along an edge.
    for (const BalanceRegion& region :
         {BalanceRegion{{{c.x() + 12.0, c.z() + 9.0}}, 5.0},
          BalanceRegion{{{c.x() + 12.0, c.z() - 20.0}, {c.x() + 12.0, c.z() + 20.0}}, 5.0}}) {
        req.balance = region;
        Eigen::VectorXd z = solver.startPoint(req);
        const int d = m.latentDim();
        z.head(d).array() += 0.05;
        for (int k = d; k < z.size(); ++k) z[k] += 0.3 * std::sin(k);
        ConstrainedIkRequest off = req;
        off.balance.reset();
        REQUIRE(solver.objective(req, z, nullptr) > solver.objective(off, z, nullptr) + 1e4);  // active: d > 1 cm
        Eigen::VectorXd g;
        solver.objective(req, z, &g);
        double worst = 0.0;
        for (int i = 0; i < z.size(); ++i) {
            const double numeric = test::centralDifference(
                [&](const Eigen::VectorXd& v) { return solver.objective(req, v, nullptr); }, z, i);
            worst = std::max(worst, std::abs(numeric - g[i]));
        }
        MESSAGE("∇F with the balance term (" << region.hull.size() << "-point support): max abs error " << worst
                                             << " against |g|∞ " << g.cwiseAbs().maxCoeff());
        CHECK(worst < 1e-6 * g.cwiseAbs().maxCoeff());
    }
}

TEST_CASE("constrained IK: a hand pulled far forward keeps the centre of mass over the planted feet") {
    // The walk's frame 200 (1-based) stands balanced on its planted foot; the right hand pulled 60 cm
    // forward, or 40 cm forward and down, tips the centre of mass out of the support without the term.
    const auto version = test::walkModel35();
    const Clip& clip = version->model->clip;
    const ContactSet contacts = detectFootContacts(clip);
    const int frame = 199;
    ConstrainedIkSolver solver(version);
    for (const Eigen::Vector3d& move : {Eigen::Vector3d(0, 0, 60), Eigen::Vector3d(0, -40, 40)}) {
        CAPTURE(move.transpose());
        const Eigen::Vector3d target = effectorCm(clip.skeleton, clip.frames[frame], Effector::kRHand) + move;
        ConstrainedIkRequest req =
            capturedPoseRequest(*version, frame, {{Effector::kRHand, target, false}}, contacts, 500);
        REQUIRE(req.balance);
        ConstrainedIkRequest free = req;
        free.balance.reset();
        const ConstrainedIkResult with = solver.solve(req), without = solver.solve(free);
        const Balance b = judgeBalance(clip.skeleton, clip.frames[frame], with.pose, contacts, frame);
        const Balance b0 = judgeBalance(clip.skeleton, clip.frames[frame], without.pose, contacts, frame);
        MESSAGE("centre of mass outside the support: " << b0.outsideCm << " cm without the term, " << b.outsideCm
                                                       << " cm with it (" << with.iterations << " steps, "
                                                       << std::string(ikStopName(with.stop)) << ")");
        REQUIRE(b.judged);
        CHECK(with.reached);
        CHECK(without.reached);
        CHECK(b0.offBalance);
        CHECK(b.outsideCm < 0.4 * b0.outsideCm);
    }
}
