// Derivatives the constrained learned IK relies on, each against central differences: the GP
// mean's Jacobian ∂f/∂x, the variance gradient ∂σ²/∂x (ActiveSetPosterior::meanVarianceJacobians), the
// gradient of the solver's objective F over (x, y) (targets of several strengths, the root
// stiffness, the locality term and the floor's one-sided penalty), the prior's part of its Hessian model (exact), and
// the contracted second derivative of FK (core/skeleton/forward_kinematics.h). Also the locality weights and what the
// term does to a hand raise.
#include <algorithm>
#include <cmath>
#include <limits>

#include "central_difference.h"
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
    const gp::ActiveSetPosterior& pm = *version->posterior;
    const gp::GpModel& m = *version->model;
    const Eigen::VectorXd y = m.Y.row(17).transpose();
    for (const Eigen::VectorXd& x :
         {Eigen::VectorXd(m.X.row(17).transpose()), Eigen::VectorXd(m.X.row(3).transpose() * 1.7),
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

TEST_CASE("constrained IK: ∇F and the prior's Hessian match central differences") {
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    const Skeleton& sk = m.clip.skeleton;
    ConstrainedIkSolver solver(version);
    ConstrainedIkRequest req = requestAt(*version, 100);
    req.constraints = {
        {Effector::kRFoot, effectorCm(sk, req.start, Effector::kRFoot) + Eigen::Vector3d(3, 12, -4), false, 1.0},
        {Effector::kRHand, effectorCm(sk, req.start, Effector::kRHand) + Eigen::Vector3d(-5, 2, 1), false, 0.9},
        {Effector::kLFoot, effectorCm(sk, req.start, Effector::kLFoot), true}};
    req.rootReferenceDeg = Eigen::Vector3d(1.0, -2.0, 3.0);
    // The locality term, against a reference that is not the start (a drag's later events).
    req.locality = 0.3;
    req.localityReference = m.clip.frames[90];
    Eigen::VectorXd z = solver.startPoint(req);
    const int d = m.latentDim();
    z.head(d).array() += 0.05;
    for (int k = d; k < z.size(); ++k) z[k] += 0.3 * std::sin(k);
    // Gradient: the largest error against central differences of F, relative to |g|∞.
    Eigen::VectorXd g;
    const auto checkGradient = [&](const std::string& name, const ConstrainedIkRequest& request) {
        solver.objective(request, z, &g);
        double worst = 0.0;
        for (int i = 0; i < z.size(); ++i) {
            const double numeric = test::centralDifference(
                [&](const Eigen::VectorXd& v) { return solver.objective(request, v, nullptr); }, z, i);
            worst = std::max(worst, std::abs(numeric - g[i]));
        }
        MESSAGE(name << ": max abs error " << worst << " against |g|∞ " << g.cwiseAbs().maxCoeff());
        CHECK(worst < 1e-6 * g.cwiseAbs().maxCoeff());
    };
    checkGradient("∇F", req);  // |g|∞ is large: the exact target's κ
    // The prior's part of H is its exact Hessian (every block analytic, the x–x one from
    // ActiveSetPosterior::latentHessian); targets enter as Gauss–Newton, so check H on a request
    // with none (the root stiffness and the locality term are exact too). Without the exact
    // target's κ in |g|∞, the gradient check sees the prior, root and locality terms as well.
    ConstrainedIkRequest free = req;
    free.constraints.clear();
    checkGradient("∇F without targets", free);
    // The floor's one-sided penalty, active on the lower foot (1 cm above it at z), on a request
    // whose hands and feet carry no constraint.
    ConstrainedIkRequest floored = free;
    {
        Pose atZ = req.start;
        PoseLayout layout(sk);
        Eigen::VectorXd full = layout.extract(atZ);
        for (int k = 0; k < m.D(); ++k) full[m.keptColumns[k]] = z[d + k];
        layout.apply(full.data(), atZ);
        floored.floorCm =
            std::min(effectorCm(sk, atZ, Effector::kLFoot).y(), effectorCm(sk, atZ, Effector::kRFoot).y()) + 1.0;
    }
    REQUIRE(solver.objective(floored, z, nullptr) > solver.objective(free, z, nullptr) + 1e3);
    checkGradient("∇F with a foot below the floor", floored);
    solver.objective(free, z, &g);
    const Eigen::MatrixXd Hf = solver.hessianModel();
    const double scaleH = Hf.cwiseAbs().maxCoeff();
    Eigen::MatrixXd numericH(z.size(), z.size());
    for (int i = 0; i < z.size(); ++i) {
        const double h = 1e-5;
        Eigen::VectorXd zp = z, zm = z, gp_, gm;
        zp[i] += h;
        zm[i] -= h;
        solver.objective(free, zp, &gp_);
        solver.objective(free, zm, &gm);
        numericH.col(i) = (gp_ - gm) / (2 * h);
    }
    // Block by block, each against its own largest entry: the x–x block is orders of magnitude
    // larger than the y–y block, so one bound on the whole matrix would not see an error in y–y.
    const int D = static_cast<int>(z.size()) - d;
    const auto checkBlock = [&](const std::string& name, Eigen::Index r, Eigen::Index c, Eigen::Index rows,
                                Eigen::Index cols) {
        const double scale = Hf.block(r, c, rows, cols).cwiseAbs().maxCoeff();
        const double err = (numericH.block(r, c, rows, cols) - Hf.block(r, c, rows, cols)).cwiseAbs().maxCoeff();
        MESSAGE("∇²(L_IK + root + locality), " << name << " block: max abs error " << err << " against its max |H| "
                                               << scale);
        CHECK(scale > 0.0);
        CHECK(err < 1e-6 * scale);
    };
    checkBlock("x–x", 0, 0, d, d);
    checkBlock("y–x", d, 0, D, d);
    checkBlock("x–y", 0, d, d, D);
    checkBlock("y–y", d, d, D, D);
    CHECK((Hf - Hf.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * scaleH);
}

TEST_CASE("λ·∂²FK/∂y² matches central differences of λᵀ J for every effector") {
    const auto version = test::walkModel35();
    const Skeleton& sk = version->model->clip.skeleton;
    const PoseLayout layout(sk);
    Pose pose = version->model->clip.frames[77];
    const Eigen::VectorXd y0 = layout.extract(pose);
    const Eigen::Vector3d lambda(0.7, -1.3, 2.1);
    FkState fk;
    Eigen::Matrix<double, 3, Eigen::Dynamic> J(3, layout.size()), Jp(3, layout.size()), Jm(3, layout.size());
    Eigen::MatrixXd Hc(layout.size(), layout.size());
    for (int e = 0; e < kEffectorCount; ++e) {
        const auto eff = static_cast<Effector>(e);
        CAPTURE(std::string(effectorName(eff)));
        forwardKinematics(sk, pose, fk);
        effectorHessianContracted(sk, layout, fk, pose, eff, lambda, Hc);
        double worst = 0.0;
        for (int i = 0; i < layout.size(); ++i) {
            const double h = 1e-4;  // degrees
            Eigen::VectorXd yp = y0, ym = y0;
            yp[i] += h;
            ym[i] -= h;
            Pose pp = pose, pm = pose;
            layout.apply(yp.data(), pp);
            layout.apply(ym.data(), pm);
            forwardKinematics(sk, pp, fk);
            effectorJacobian(sk, layout, fk, pp, eff, Jp);
            forwardKinematics(sk, pm, fk);
            effectorJacobian(sk, layout, fk, pm, eff, Jm);
            const Eigen::VectorXd col = ((Jp - Jm).transpose() * lambda) / (2 * h);
            worst = std::max(worst, (col - Hc.col(i)).cwiseAbs().maxCoeff());
        }
        MESSAGE(effectorName(eff) << ": max abs error " << worst << " against max |H| " << Hc.cwiseAbs().maxCoeff());
        CHECK(Hc.cwiseAbs().maxCoeff() > 0.0);
        CHECK(worst < 1e-6 * Hc.cwiseAbs().maxCoeff());
        CHECK((Hc - Hc.transpose()).cwiseAbs().maxCoeff() == 0.0);
    }
}

TEST_CASE("∂²L_IK/∂x² matches central differences of the exact ∇ₓL_IK (FAS and SGPLVM kernels)") {
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    // The FAS model, and an SGPLVM posterior on the same active points (RBF part only).
    const Eigen::VectorXd rbfParams = m.kernel().logParams().head(gp::paramCount(gp::KernelKind::kSgplvm));
    const gp::ActiveSetPosterior sgplvm(gp::Kernel(gp::KernelKind::kSgplvm, rbfParams), m.activeX(), m.activeYhat(),
                                        m.mu, m.w);
    for (const gp::ActiveSetPosterior* pm : {version->posterior.get(), &sgplvm}) {
        const Eigen::VectorXd y = m.Y.row(17).transpose() + Eigen::VectorXd::Constant(m.D(), 2.0);
        for (const Eigen::VectorXd& x :
             {Eigen::VectorXd(m.X.row(17).transpose()), Eigen::VectorXd(m.X.row(3).transpose() * 1.7),
              Eigen::VectorXd(Eigen::Vector2d(2e-3, -1e-3))}) {
            CAPTURE(x.transpose());
            CAPTURE(pm->kernel().hasEta());
            gp::PointWorkspace ws;
            Eigen::VectorXd gx(m.latentDim()), gy(m.D()), dS2;
            Eigen::MatrixXd Jf, H;
            pm->evaluate(x, y, ws, &gx, &gy);
            pm->meanVarianceJacobians(x, ws, Jf, dS2);
            pm->latentHessian(x, ws, Jf, dS2, H);
            REQUIRE_FALSE(ws.clamped);
            double err = 0.0;
            for (int i = 0; i < x.size(); ++i) {
                // Near the origin the angular term's derivatives scale with 1/|x|: a step of
                // 1e-4·|x| there keeps the difference quotient's truncation error below round-off.
                const double h = std::clamp(1e-4 * x.norm(), 1e-7, 1e-6);
                Eigen::VectorXd a = x, b = x, ga, gb;
                a[i] += h;
                b[i] -= h;
                pm->evaluate(a, y, &ga, nullptr);
                pm->evaluate(b, y, &gb, nullptr);
                err = std::max(err, ((ga - gb) / (2 * h) - H.col(i)).cwiseAbs().maxCoeff());
            }
            MESSAGE("|∂²L/∂x²| max " << H.cwiseAbs().maxCoeff() << " err " << err);
            CHECK(err < 1e-6 * std::max(1.0, H.cwiseAbs().maxCoeff()));
            CHECK(H == H.transpose());
        }
    }
}

TEST_CASE("locality weights: a hand's limb is free, the clavicle half, the body and the other limbs whole") {
    const Skeleton& sk = test::walkModel35()->model->clip.skeleton;
    const PoseLayout layout(sk);
    const std::vector<double> w = localityWeights(sk, {Effector::kRHand});
    REQUIRE(static_cast<int>(w.size()) == layout.size());
    const auto weightOf = [&](const char* bone) {
        const int j = sk.findBone(bone);
        REQUIRE(j >= 0);
        double seen = -1.0;
        for (int dof = 0; dof < layout.size(); ++dof)
            if (layout.joint(dof) == j) {
                if (seen >= 0.0) CHECK(w[dof] == seen);  // every axis of a joint alike
                seen = w[dof];
            }
        REQUIRE(seen >= 0.0);
        return seen;
    };
    for (const char* bone : {"rwrist", "rradius", "rhumerus"}) CHECK(weightOf(bone) == 0.0);
    CHECK(weightOf("rclavicle") == 0.5);
    for (const char* bone : {"thorax", "upperback", "lowerback", "lhumerus", "lfemur", "rfemur", "head"})
        CHECK(weightOf(bone) == 1.0);
    for (int dof = 0; dof < 3; ++dof) CHECK(w[dof] == 1.0);  // the root's rotation
    // Two targets: each limb free; none: everything weighted.
    const std::vector<double> both = localityWeights(sk, {Effector::kRHand, Effector::kLFoot});
    for (int dof = 0; dof < layout.size(); ++dof)
        if (layout.joint(dof) == sk.findBone("ltibia")) CHECK(both[dof] == 0.0);
    for (double v : localityWeights(sk, {})) CHECK(v == 1.0);
}

TEST_CASE("locality: a hand target moves the head less the stiffer the body is") {
    const auto version = test::walkModel35();
    const gp::GpModel& m = *version->model;
    const Skeleton& sk = m.clip.skeleton;
    ConstrainedIkSolver solver(version);
    ConstrainedIkRequest req = requestAt(*version, 100);
    req.constraints = {
        {Effector::kRHand, effectorCm(sk, req.start, Effector::kRHand) + Eigen::Vector3d(0, 20, 0), false, 1.0},
        {Effector::kLFoot, effectorCm(sk, req.start, Effector::kLFoot), true},
        {Effector::kRFoot, effectorCm(sk, req.start, Effector::kRFoot), true}};
    req.maxIterations = 500;
    const Eigen::Vector3d head0 = effectorCm(sk, req.start, Effector::kHead);
    const Eigen::Vector3d lhand0 = effectorCm(sk, req.start, Effector::kLHand);
    double previousHead = std::numeric_limits<double>::infinity();
    double headOff = 0.0, headStiff = 0.0;
    for (double locality : {0.0, 10.0, 100.0}) {
        CAPTURE(locality);
        req.locality = locality;
        const ConstrainedIkResult r = solver.solve(req);
        REQUIRE(r.reached);
        const double head = (effectorCm(sk, r.pose, Effector::kHead) - head0).norm();
        const double lhand = (effectorCm(sk, r.pose, Effector::kLHand) - lhand0).norm();
        MESSAGE("locality " << locality << ": head moves " << head << " cm, left hand " << lhand << " cm, "
                            << r.iterations << " iterations");
        CHECK(head <= previousHead + 1e-6);
        previousHead = head;
        (locality == 0.0 ? headOff : headStiff) = head;
    }
    // Mid-stride (walk frame 100, both feet pinned) the head followed the 20 cm raise by 32 cm
    // without the term and by 3.2 cm at ℓ = 100: at least five times less.
    CHECK(headStiff <= 0.2 * headOff);
}
