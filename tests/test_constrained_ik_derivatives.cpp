// Derivatives the constrained learned IK relies on, each against central differences: the GP
// mean's Jacobian ∂f/∂x, the variance gradient ∂σ²/∂x (PointModel::meanVarianceJacobians), the
// gradient of the solver's objective F over (x, y) (targets of several strengths and the root
// stiffness), and its Hessian model's exact blocks (y–y, x–y, x–x).
#include <cmath>

#include "ik/constrained_ik.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

namespace {
ConstrainedIkRequest requestAt(const gp::ModelVersion& v, int frame) {
    ConstrainedIkRequest r;
    r.start = v.model->clip.frames[frame];
    r.startX = latentStartForFrame(v, frame);
    return r;
}
}  // namespace

TEST_CASE("∂f/∂x and ∂σ²/∂x match central differences (training point, far point, near the origin)") {
    const auto version = test::walkModel35();
    const gp::PointModel& pm = *version->point;
    const gp::GpModel& m = *version->model;
    const Eigen::VectorXd y = m.Y.row(17).transpose();
    for (const Eigen::VectorXd& x : {Eigen::VectorXd(m.X.row(17).transpose()), Eigen::VectorXd(m.X.row(3).transpose() * 1.7),
                                     Eigen::VectorXd(Eigen::Vector2d(2e-3, -1e-3))}) {
        CAPTURE(x.transpose());
        gp::PointWorkspace ws;
        pm.evaluate(x, y, ws, nullptr, nullptr);
        Eigen::MatrixXd Jf;
        Eigen::VectorXd dS2;
        pm.meanVarianceJacobians(x, ws, Jf, dS2);
        REQUIRE(Jf.rows() == m.D());
        REQUIRE(Jf.cols() == m.latentDim());
        const double h = 1e-6;
        double errF = 0.0, errS = 0.0;
        for (int i = 0; i < x.size(); ++i) {
            Eigen::VectorXd a = x, b = x, fa, fb;
            a[i] += h;
            b[i] -= h;
            double sa = 0.0, sb = 0.0;
            pm.predict(a, fa, sa);
            pm.predict(b, fb, sb);
            errF = std::max(errF, ((fa - fb) / (2 * h) - Jf.col(i)).cwiseAbs().maxCoeff());
            errS = std::max(errS, std::abs((sa - sb) / (2 * h) - dS2[i]));
        }
        MESSAGE("|∂f/∂x| max " << Jf.cwiseAbs().maxCoeff() << " err " << errF << "; |∂σ²/∂x| max "
                               << dS2.cwiseAbs().maxCoeff() << " err " << errS);
        CHECK(errF < 1e-6 * std::max(1.0, Jf.cwiseAbs().maxCoeff()));
        CHECK(errS < 1e-6 * std::max(1.0, dS2.cwiseAbs().maxCoeff()));
        // The workspace's σ² is the one predict() gives.
        Eigen::VectorXd f;
        double s2 = 0.0;
        pm.predict(x, f, s2);
        CHECK(ws.variance == doctest::Approx(s2).epsilon(1e-12));
    }
}

TEST_CASE("constrained IK: ∇F and the Hessian model's exact blocks match central differences") {
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    const Skeleton& sk = m.clip.skeleton;
    ConstrainedIkSolver solver(version);
    ConstrainedIkRequest req = requestAt(*version, 100);
    req.constraints = {{Effector::kRFoot, effectorCm(sk, req.start, Effector::kRFoot) + Eigen::Vector3d(3, 12, -4), false, 1.0},
                       {Effector::kRHand, effectorCm(sk, req.start, Effector::kRHand) + Eigen::Vector3d(-5, 2, 1), false, 0.9},
                       {Effector::kLFoot, effectorCm(sk, req.start, Effector::kLFoot), true}};
    req.rootReferenceDeg = Eigen::Vector3d(1.0, -2.0, 3.0);
    Eigen::VectorXd z = solver.startPoint(req);
    const int d = m.latentDim();
    z.head(d).array() += 0.05;
    for (int k = d; k < z.size(); ++k) z[k] += 0.3 * std::sin(k);
    Eigen::VectorXd g;
    solver.objective(req, z, &g);
    const Eigen::MatrixXd H = solver.hessianModel();
    // Gradient: relative to |g|∞ (the exact target's κ makes it large).
    double worst = 0.0;
    for (int i = 0; i < z.size(); ++i) {
        const double h = 1e-6;
        Eigen::VectorXd zp = z, zm = z;
        zp[i] += h;
        zm[i] -= h;
        const double numeric = (solver.objective(req, zp, nullptr) - solver.objective(req, zm, nullptr)) / (2 * h);
        worst = std::max(worst, std::abs(numeric - g[i]));
    }
    MESSAGE("∇F: max abs error " << worst << " against |g|∞ " << g.cwiseAbs().maxCoeff());
    CHECK(worst < 1e-6 * g.cwiseAbs().maxCoeff());
    // Hessian blocks that are exact: the prior's (targets are Gauss–Newton), so check them on a
    // request without targets (a pin does not enter F).
    ConstrainedIkRequest prior = req;
    prior.constraints = {req.constraints[2]};
    prior.rootStiffness = 0.0;
    solver.objective(prior, z, &g);
    const Eigen::MatrixXd Hp = solver.hessianModel();
    double worstH = 0.0, scaleH = Hp.cwiseAbs().maxCoeff();
    for (int i = 0; i < z.size(); ++i) {
        const double h = 1e-5;
        Eigen::VectorXd zp = z, zm = z, gp_, gm;
        zp[i] += h;
        zm[i] -= h;
        solver.objective(prior, zp, &gp_);
        solver.objective(prior, zm, &gm);
        const Eigen::VectorXd col = (gp_ - gm) / (2 * h);
        worstH = std::max(worstH, (col - Hp.col(i)).cwiseAbs().maxCoeff());
    }
    MESSAGE("∇²L_IK model: max abs error " << worstH << " against max |H| " << scaleH);
    CHECK(worstH < 1e-5 * scaleH);
    CHECK((Hp - Hp.transpose()).cwiseAbs().maxCoeff() == 0.0);
    (void)H;
}
