// The model-independent tests of docs/maths.md §14.1: PPCA density, joint ranges, nearest real pose, continuity,
// and the editing-range sweep's bookkeeping.
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <random>

#include "eval/editing_range.h"
#include "eval/naturalness.h"
#include "eval/ppca_density.h"
#include "io/clip_loader.h"
#include "motion/foot_contacts.h"
#include "skeleton/forward_kinematics.h"
#include "test_support.h"
#include "trained_model_fixture.h"

using namespace mgp;

TEST_CASE("PPCA log density equals the Gaussian density of its covariance") {
    std::mt19937 rng(7);
    std::normal_distribution<double> n01;
    Eigen::MatrixXd A(6, 6);
    for (int i = 0; i < 36; ++i) A.data()[i] = n01(rng);
    Eigen::MatrixXd X(400, 6);
    for (int r = 0; r < 400; ++r) {
        Eigen::VectorXd z(6);
        for (int i = 0; i < 6; ++i) z[i] = n01(rng);
        X.row(r) = (A * z).transpose() + Eigen::RowVectorXd::LinSpaced(6, 1, 6);
    }
    const PpcaDensity ppca(X, 3);
    // Build C = U Λ Uᵀ + σ²(I − U Uᵀ) independently from the sample covariance.
    const Eigen::VectorXd mu = X.colwise().mean().transpose();
    const Eigen::MatrixXd Xc = X.rowwise() - mu.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Xc.transpose() * Xc / 400.0);
    const Eigen::VectorXd ev = eig.eigenvalues();  // ascending
    const Eigen::MatrixXd U = eig.eigenvectors().rightCols(3);
    const double s2 = ev.head(3).mean();
    const Eigen::MatrixXd C =
        U * ev.tail(3).asDiagonal() * U.transpose() + s2 * (Eigen::MatrixXd::Identity(6, 6) - U * U.transpose());
    const Eigen::LLT<Eigen::MatrixXd> llt(C);
    for (int r = 0; r < 5; ++r) {
        const Eigen::VectorXd y = X.row(r * 37).transpose() + Eigen::VectorXd::Constant(6, 0.3 * r);
        const Eigen::VectorXd c = y - mu;
        const double quad = llt.matrixL().solve(c).squaredNorm();
        const double logDet = 2.0 * llt.matrixL().toDenseMatrix().diagonal().array().log().sum();
        const double want = -0.5 * (quad + logDet + 6 * std::log(2 * M_PI));
        CHECK(ppca.logDensity(y) == doctest::Approx(want).epsilon(1e-10));
    }
    // Held-out 1st percentile sits below the typical in-sample density.
    CHECK(heldOutLogDensityQuantile(X, 3, 5, 0.01) < ppca.logDensity(mu));
}

TEST_CASE("naturalness: real frames pass, a twisted pose fails ranges, density and nearest pose") {
    const Clip clip = loadClip(test::mocap("asf_amc/35_01.amc"));
    // Frame 201 and its neighbours are clean. (Frames 99-103 are not: the captured lfoot rx jumps
    // 21.8 → 3.8 → -19.6 → 3.3 degrees between consecutive frames, marker noise in the file.)
    std::vector<ReferenceFrame> ref;
    for (int t = 0; t < clip.frameCount(); ++t)
        if (std::abs(t - 200) > 10) ref.push_back({&clip, t, 0});
    const NaturalnessTests tests(ref, Effector::kRFoot);
    CHECK(tests.size() == 358 - 21);
    CHECK(tests.nnThreshold() > 0.0);
    const Eigen::MatrixXd y = poseMatrix(clip);
    // Frame 201 (left out of R) is a real walking pose: every test passes.
    const Eigen::VectorXd real = y.row(200).transpose(), prev = y.row(199).transpose();
    NaturalnessVerdict v = tests.judge(clip.skeleton, real, &prev);
    CHECK(v.ranges);
    CHECK(v.nearest);
    CHECK(v.density);
    CHECK(v.continuity);
    // Bend the left knee backwards by 90° and twist the spine: not a walking pose.
    Eigen::VectorXd bad = real;
    bad[6] -= 90.0;
    bad[16] += 60.0;
    v = tests.judge(clip.skeleton, bad, &real);
    CHECK_FALSE(v.ranges);
    CHECK(v.worstRangeDof == 6);
    CHECK_FALSE(v.nearest);
    CHECK_FALSE(v.density);
    CHECK_FALSE(v.continuity);
    CHECK(v.maxStepDof == 6);
    CHECK_FALSE(v.all());
    // The excluded effector's bone does not count in MPJPE: moving only the right foot bone's
    // own DOFs (rfoot rx) changes only the end of rfoot... and rtoes, which is not a model bone.
    Eigen::VectorXd foot = real;
    foot[13] += 25.0;
    CHECK(tests.nearestDistance(NaturalnessTests::bodyShape(clip.skeleton, foot)) ==
          doctest::Approx(tests.nearestDistance(NaturalnessTests::bodyShape(clip.skeleton, real))));
}

TEST_CASE("editing-range sweep: per-test ranges are prefix ranges and the combined one is their minimum") {
    const auto version = test::walkModel35();
    const Clip& clip = version->model->clip;
    std::vector<ReferenceFrame> ref;
    for (int t = 0; t < clip.frameCount(); ++t)
        if (std::abs(t - 100) > 10) ref.push_back({&clip, t, 0});
    const NaturalnessTests tests(ref, Effector::kRFoot);
    EditingRangeJob job;
    job.version = version;
    job.frame = 100;
    job.effector = Effector::kRFoot;
    job.tests = &tests;
    job.maxDeltaCm = 12;
    job.adaptive = true;
    const EditingRange r = job.run();
    REQUIRE(!r.steps.empty());
    CHECK(r.steps[0].deltaCm == 0);
    // δ = 0 is the captured frame itself (left out of R by ±10): a range of −1 would make the
    // prefix checks below vacuous.
    CHECK(r.combined >= 0);
    const int perTest[5] = {r.reach, r.ranges, r.nearest, r.density, r.continuity};
    CHECK(r.combined == *std::min_element(perTest, perTest + 5));
    // Prefix semantics: every step up to the combined range was accepted, and the next was not.
    for (int d = 0; d <= r.combined; ++d) CHECK(r.steps[d].accepted);
    if (r.combined + 1 < static_cast<int>(r.steps.size())) CHECK_FALSE(r.steps[r.combined + 1].accepted);
    // Adaptive updates happen only after accepted steps.
    int updates = 0;
    for (const auto& s : r.steps) {
        if (s.updatedModel) CHECK(s.accepted);
        updates += s.updatedModel;
    }
    CHECK(updates == r.adaptiveUpdates);
    // δ = 0 re-solves the captured frame: not an edit, nothing learned.
    CHECK_FALSE(r.steps[0].updatedModel);
    // The binding tests are the ones the step after the range failed.
    const std::vector<std::string> binding = r.binding();
    if (r.combined + 1 < static_cast<int>(r.steps.size())) {
        const EditingStep& next = r.steps[r.combined + 1];
        CHECK(binding.size() == static_cast<std::size_t>(!next.reach + !next.verdict.ranges + !next.verdict.nearest +
                                                         !next.verdict.density + !next.verdict.continuity));
        CHECK_FALSE(binding.empty());
    } else {
        CHECK(binding.empty());
    }
    MESSAGE("35_01 f101 raise rfoot (T=3, M=100, FAS adaptive): combined "
            << r.combined << " cm; reach " << r.reach << ", ranges " << r.ranges << ", NN " << r.nearest << ", density "
            << r.density << ", continuity " << r.continuity);
}

TEST_CASE("editing-range sweep, editor drag: the feet planted on the frame stay where they stand") {
    const auto version = test::walkModel35();
    const Clip& clip = version->model->clip;
    const int frame = 100;
    std::vector<ReferenceFrame> ref;
    for (int t = 0; t < clip.frameCount(); ++t)
        if (std::abs(t - frame) > 10) ref.push_back({&clip, t, 0});
    const NaturalnessTests tests(ref, Effector::kLHand);
    EditingRangeJob job;
    job.version = version;
    job.frame = frame;
    job.effector = Effector::kLHand;
    job.tests = &tests;
    job.maxDeltaCm = 6;
    job.editorDrag = true;
    const EditingRange r = job.run();
    REQUIRE(r.steps.size() >= 2);
    const ContactSet contacts = detectFootContacts(clip);
    const Pose& captured = clip.frames[frame];
    int planted = 0;
    for (Effector foot : {Effector::kLFoot, Effector::kRFoot}) {
        if (!contacts.at(foot, frame)) continue;
        ++planted;
        for (const EditingStep& s : r.steps) {
            Pose pose = captured;
            PoseLayout(clip.skeleton).apply(s.poseDeg.data(), pose);
            const double moved =
                (effectorCm(clip.skeleton, pose, foot) - effectorCm(clip.skeleton, captured, foot)).norm();
            INFO(effectorName(foot) << " at δ = " << s.deltaCm);
            if (s.reach) CHECK(moved <= 0.5);
        }
    }
    CHECK(planted > 0);  // the walk's frame 101 stands on a foot: the check above is not vacuous
    for (const EditingStep& s : r.steps)
        if (s.reach) CHECK(s.residualCm <= 0.5);
    CHECK(r.reach >= 1);
}
