// docs/maths.md §21: mirror pose by conjugation with the sagittal reflection.
#include <cmath>
#include <random>

#include "io/clip_loader.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_mirror.h"
#include "skeleton/rotation.h"
#include "skeleton/synthetic_clip.h"
#include "test_support.h"

using namespace mgp;

namespace {

// Largest |a − b| over every angle, each difference taken modulo 360°.
double angleDistanceMod360(const Pose& a, const Pose& b) {
    double worst = 0.0;
    for (std::size_t j = 0; j < a.anglesDeg.size(); ++j)
        for (int k = 0; k < 3; ++k) {
            const double d = a.anglesDeg[j][k] - b.anglesDeg[j][k];
            worst = std::max(worst, std::abs(wrap180(d)));
        }
    return worst;
}

// Largest distance between the mirrored pose's joint positions and bone ends and the reflections,
// through the original's sagittal plane, of their partners' (cm).
double reflectionResidual(const Skeleton& sk, const PoseMirror& m, const Pose& pose, const Pose& mirrored) {
    FkState fk, fkm;
    forwardKinematics(sk, pose, fk);
    forwardKinematics(sk, mirrored, fkm);
    const Eigen::Matrix3d w = m.worldReflection(fk.global[0]);
    const Eigen::Vector3d root = fk.jointCm[0];
    double worst = 0.0;
    for (int j = 0; j < sk.jointCount(); ++j) {
        const int p = m.partner(j);
        worst = std::max(worst, (fkm.jointCm[j] - (root + w * (fk.jointCm[p] - root))).norm());
        worst = std::max(worst, (boneEndCm(sk, fkm, j) - (root + w * (boneEndCm(sk, fk, p) - root))).norm());
    }
    return worst;
}

// A random pose: every animated DOF in ±70°, the root turned by any heading.
Pose randomPose(const Skeleton& sk, std::mt19937& rng) {
    std::uniform_real_distribution<double> angle(-70.0, 70.0), heading(-400.0, 400.0), pos(-100.0, 100.0);
    Pose p;
    p.rootCm = {pos(rng), 90.0 + 0.1 * pos(rng), pos(rng)};
    p.anglesDeg.assign(sk.jointCount(), Eigen::Vector3d::Zero());
    for (int j = 0; j < sk.jointCount(); ++j)
        for (int a = 0; a < 3; ++a)
            if (sk.joints[j].dof[a]) p.anglesDeg[j][a] = angle(rng);
    p.anglesDeg[0][kAxisY] = heading(rng);
    return p;
}

PoseMirror mirrorOf(const Skeleton& sk) {
    std::string err;
    std::optional<PoseMirror> m = PoseMirror::make(sk, err);
    REQUIRE_MESSAGE(m.has_value(), err);
    return *m;
}

}  // namespace

TEST_CASE("eulerFromMatrix inverts eulerMatrix for all six orders, and eulerAlternative is the same rotation") {
    const RotationOrder orders[] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-179.0, 179.0), mid(-89.0, 89.0);
    for (const RotationOrder& o : orders) {
        for (int s = 0; s < 200; ++s) {
            Eigen::Vector3d a(u(rng), u(rng), u(rng));
            a[o[1]] = mid(rng);
            const Eigen::Matrix3d r = eulerMatrix(a, o);
            const Eigen::Vector3d back = eulerFromMatrix(r, o);
            CHECK((back - a).cwiseAbs().maxCoeff() < 1e-9);
            CHECK((eulerMatrix(eulerAlternative(back, o), o) - r).cwiseAbs().maxCoeff() < 1e-12);
        }
        // Gimbal lock: the middle angle at 90°, the innermost angle folded into the outermost.
        Eigen::Vector3d g = Eigen::Vector3d::Zero();
        g[o[0]] = 30.0;
        g[o[1]] = 90.0;
        g[o[2]] = 20.0;
        const Eigen::Matrix3d r = eulerMatrix(g, o);
        const Eigen::Vector3d back = eulerFromMatrix(r, o);
        CHECK(back[o[2]] == 0.0);
        CHECK((eulerMatrix(back, o) - r).cwiseAbs().maxCoeff() < 1e-9);
    }
    // The ZYX special case agrees with the general one.
    const Eigen::Vector3d a(12.0, -33.0, 140.0);
    CHECK(
        (eulerFromMatrix(eulerMatrix(a, kOrderZYX), kOrderZYX) - eulerZYXFromMatrix(eulerMatrix(a, kOrderZYX))).norm() <
        1e-12);
}

TEST_CASE("fitJointAngles: a representable rotation exactly, a missing axis by least squares") {
    const std::array<bool, 3> all{true, true, true}, xz{true, false, true};
    const Eigen::Vector3d a(25.0, 0.0, -40.0);
    const Eigen::Matrix3d q = eulerMatrix(a, kOrderZYX);
    CHECK((fitJointAngles(q, kOrderZYX, all, a) - a).cwiseAbs().maxCoeff() < 1e-9);
    CHECK((fitJointAngles(q, kOrderZYX, xz, Eigen::Vector3d::Zero()) - a).cwiseAbs().maxCoeff() < 1e-9);
    // Wrapped toward the reference.
    const Eigen::Vector3d ref(25.0 + 720.0, 0.0, -40.0 - 360.0);
    CHECK((fitJointAngles(q, kOrderZYX, all, ref) - ref).cwiseAbs().maxCoeff() < 1e-9);
    // One axis (x) for a rotation with y and z in it: no angle on a fine grid fits better.
    const Eigen::Matrix3d q2 = eulerMatrix(Eigen::Vector3d(50.0, 20.0, -15.0), kOrderZYX);
    const std::array<bool, 3> xOnly{true, false, false};
    const Eigen::Vector3d fit = fitJointAngles(q2, kOrderZYX, xOnly, Eigen::Vector3d::Zero());
    CHECK(fit[1] == 0.0);
    CHECK(fit[2] == 0.0);
    const double best = (q2.transpose() * eulerMatrix(fit, kOrderZYX)).trace();
    for (double t = -180.0; t < 180.0; t += 0.01)
        CHECK((q2.transpose() * eulerMatrix(Eigen::Vector3d(t, 0, 0), kOrderZYX)).trace() <= best + 1e-12);
}

TEST_CASE(
    "mirror pose on an exactly symmetric skeleton: partners' FK positions are reflections, mirror twice is identity") {
    const Clip clip = makeSyntheticWalk(40);
    const Skeleton& sk = clip.skeleton;
    const PoseMirror m = mirrorOf(sk);
    CHECK(m.pairCount() == 12);  // hipjoint femur tibia foot toes, clavicle humerus radius wrist hand fingers thumb
    CHECK((m.lateralAxis() - Eigen::Vector3d::UnitX()).norm() < 1e-12);
    CHECK(m.partner(sk.findBone("lhumerus")) == sk.findBone("rhumerus"));
    CHECK(m.partner(sk.findBone("head")) == sk.findBone("head"));
    CHECK(m.droppedAxes().empty());
    std::mt19937 rng(3);
    double worstFk = 0.0, worstTwice = 0.0;
    for (int s = 0; s < 200; ++s) {
        const Pose p = randomPose(sk, rng);
        const Pose mp = m.mirror(p);
        CHECK(mp.rootCm == p.rootCm);
        worstFk = std::max(worstFk, reflectionResidual(sk, m, p, mp));
        worstTwice = std::max(worstTwice, angleDistanceMod360(m.mirror(mp), p));
    }
    for (const Pose& p : clip.frames) {
        worstFk = std::max(worstFk, reflectionResidual(sk, m, p, m.mirror(p)));
        worstTwice = std::max(worstTwice, angleDistanceMod360(m.mirror(m.mirror(p)), p));
    }
    MESSAGE("symmetric skeleton: FK reflection residual " << worstFk << " cm, mirror twice " << worstTwice << " deg");
    CHECK(worstFk < 1e-6);
    CHECK(worstTwice < 1e-9);
}

TEST_CASE("mirror pose keeps the root position and heading, and mirrors a turned and tilted root") {
    const Clip clip = makeSyntheticWalk(2);
    const PoseMirror m = mirrorOf(clip.skeleton);
    Pose p = clip.frames[0];
    p.anglesDeg[0] = Eigen::Vector3d(10.0, 130.0, 15.0);  // pitch, heading, roll (Rz·Ry·Rx)
    const Pose mp = m.mirror(p);
    const Eigen::Matrix3d r = eulerMatrix(p.anglesDeg[0], clip.skeleton.joints[0].order);
    const Eigen::Matrix3d rm = eulerMatrix(mp.anglesDeg[0], clip.skeleton.joints[0].order);
    // Forward (rest +z) keeps its horizontal direction; the lateral tilt changes sign.
    Eigen::Vector3d f = r * Eigen::Vector3d::UnitZ(), fm = rm * Eigen::Vector3d::UnitZ();
    f.y() = fm.y() = 0.0;
    CHECK((f.normalized() - fm.normalized()).norm() < 1e-12);
    CHECK(std::abs((r * Eigen::Vector3d::UnitZ()).y() - (rm * Eigen::Vector3d::UnitZ()).y()) < 1e-12);
    CHECK(std::abs((r * Eigen::Vector3d::UnitX()).y() + (rm * Eigen::Vector3d::UnitX()).y()) < 1e-12);
    CHECK(mp.rootCm == p.rootCm);
}

TEST_CASE(
    "mirror pose on real CMU clips: mirror twice is identity, and the reflection residual of the capture skeleton's "
    "asymmetry") {
    struct Case {
        const char* file;
        // The stated bound on the FK reflection residual (joints and bone ends, every frame):
        // measured 5.32 (35_01), 7.57 (10_02), 2.75 (49_04), 3.41 (131_01), 2.01 cm (02_03).
        double boundCm;
    };
    for (const Case c : {Case{"asf_amc/35_01.amc", 6.0}, Case{"asf_amc/10_02.amc", 8.0}, Case{"bvh/49_04.bvh", 3.0},
                         Case{"bvh/131_01.bvh", 4.0}, Case{"bvh/02_03.bvh", 2.5}}) {
        CAPTURE(std::string(c.file));
        const Clip clip = loadClip(test::mocap(c.file));
        const PoseMirror m = mirrorOf(clip.skeleton);
        // The skeleton's own asymmetry: rest joint positions against their partners' reflections.
        Pose rest;
        rest.anglesDeg.assign(clip.skeleton.jointCount(), Eigen::Vector3d::Zero());
        FkState fk;
        forwardKinematics(clip.skeleton, rest, fk);
        double restAsym = 0.0;
        for (int j = 0; j < clip.skeleton.jointCount(); ++j)
            restAsym = std::max(
                restAsym,
                (fk.jointCm[j] - fk.jointCm[0] - m.reflection() * (fk.jointCm[m.partner(j)] - fk.jointCm[0])).norm());
        // Rotations are mirrored exactly, so joint j misses its partner's reflection by at most the
        // bones' own asymmetry along its chain: Σ_k ‖offset_k − S offset_π(k)‖ (triangle inequality).
        const Skeleton& sk = clip.skeleton;
        std::vector<double> chain(sk.jointCount(), 0.0);
        for (int j = 1; j < sk.jointCount(); ++j)
            chain[j] = chain[sk.joints[j].parent] +
                       (sk.joints[j].offsetCm - m.reflection() * sk.joints[m.partner(j)].offsetCm).norm();
        double worstFk = 0.0, worstTwice = 0.0, meanFk = 0.0, worstOverBound = -1e300;
        FkState fa, fb;
        for (const Pose& p : clip.frames) {
            const Pose mp = m.mirror(p);
            forwardKinematics(sk, p, fa);
            forwardKinematics(sk, mp, fb);
            const Eigen::Matrix3d w = m.worldReflection(fa.global[0]);
            for (int j = 0; j < sk.jointCount(); ++j) {
                const Eigen::Vector3d want = fa.jointCm[0] + w * (fa.jointCm[m.partner(j)] - fa.jointCm[0]);
                worstOverBound = std::max(worstOverBound, (fb.jointCm[j] - want).norm() - chain[j]);
            }
            const double r = reflectionResidual(clip.skeleton, m, p, mp);
            worstFk = std::max(worstFk, r);
            meanFk += r / clip.frameCount();
            worstTwice = std::max(worstTwice, angleDistanceMod360(m.mirror(mp), p));
        }
        MESSAGE(c.file << ": rest asymmetry " << restAsym << " cm, " << m.pairCount() << " pairs, lateral axis "
                       << m.lateralAxis().transpose() << ", mirror twice " << worstTwice
                       << " deg, FK reflection residual max " << worstFk << " cm (mean of per-frame max " << meanFk
                       << " cm), largest chain asymmetry " << *std::max_element(chain.begin(), chain.end()) << " cm, "
                       << m.droppedAxes().size() << " dropped axes");
        CHECK(worstOverBound <= 1e-9);
        CHECK(worstTwice < 1e-9);
        CHECK(worstFk < c.boundCm);
    }
}

TEST_CASE("mirror pose: a DOF the partner lacks is fitted away by least squares, the rest stays exact") {
    Clip clip = makeSyntheticWalk(2);
    Skeleton& sk = clip.skeleton;
    const int lw = sk.findBone("lwrist"), rw = sk.findBone("rwrist");
    sk.joints[lw].dof = {false, true, true};  // the left wrist also turns about z; the right one only about y
    const PoseMirror m = mirrorOf(sk);
    REQUIRE(m.droppedAxes().size() == 1);
    CHECK(m.droppedAxes()[0].joint == rw);
    CHECK(m.droppedAxes()[0].axis == kAxisZ);
    Pose p = clip.frames[0];
    p.anglesDeg[lw] = Eigen::Vector3d(0.0, 30.0, 20.0);
    const Pose mp = m.mirror(p);
    CHECK(mp.anglesDeg[rw][kAxisZ] == 0.0);
    CHECK(mp.anglesDeg[rw][kAxisX] == 0.0);
    // The right wrist's y is the least-squares fit to the reflected left rotation.
    const Eigen::Matrix3d target = m.reflection() * eulerMatrix(p.anglesDeg[lw], sk.joints[lw].order) * m.reflection();
    const double best = (target.transpose() * eulerMatrix(mp.anglesDeg[rw], sk.joints[rw].order)).trace();
    for (double t = -180.0; t < 180.0; t += 0.01)
        CHECK((target.transpose() * eulerMatrix(Eigen::Vector3d(0, t, 0), sk.joints[rw].order)).trace() <=
              best + 1e-12);
    // Joints that do not hang from the right wrist still mirror exactly.
    FkState fk, fkm;
    forwardKinematics(sk, p, fk);
    forwardKinematics(sk, mp, fkm);
    const Eigen::Matrix3d w = m.worldReflection(fk.global[0]);
    for (int j = 0; j < sk.jointCount(); ++j) {
        if (sk.isAncestorOrSelf(rw, j)) continue;
        CHECK((fkm.jointCm[j] - (fk.jointCm[0] + w * (fk.jointCm[m.partner(j)] - fk.jointCm[0]))).norm() < 1e-6);
    }
    // The other way round the mirror is exact: the left wrist can take the right one's rotation.
    const Pose back = m.mirror(mp);
    CHECK(std::abs(back.anglesDeg[lw][kAxisZ]) < 1e-9);
}

TEST_CASE("mirror pose: a skeleton without left/right names or with mismatched parents says why") {
    Skeleton sk;
    Joint root;
    root.name = "root";
    sk.joints.push_back(root);
    for (const char* name : {"spine", "arm_a", "arm_b"}) {
        Joint j;
        j.name = name;
        j.parent = 0;
        j.tailCm = Eigen::Vector3d(1.0, 0.0, 0.0);
        sk.joints.push_back(j);
    }
    std::string err;
    CHECK_FALSE(PoseMirror::make(sk, err).has_value());
    CHECK(err.find("no symmetry") != std::string::npos);
    CHECK(err.find("found none") != std::string::npos);
    // Pairs whose parents are not partners.
    sk.joints[2].name = "larm";
    sk.joints[3].name = "rarm";
    sk.joints[3].parent = 1;
    err.clear();
    CHECK_FALSE(PoseMirror::make(sk, err).has_value());
    CHECK(err.find("larm") != std::string::npos);
    CHECK(err.find("hang from mirror bones") != std::string::npos);
}
