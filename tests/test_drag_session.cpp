// DragSession (core/edit/drag_session.h): one drag without a document — what it holds, how it
// solves (learned with a model, plain IK without), the compare ghost and the latent mode.
#include <doctest/doctest.h>

#include "edit/drag_session.h"
#include "ik/learned_ik.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/synthetic_clip.h"
#include "trained_model_fixture.h"

using namespace mgp;

namespace {
double distance(const Skeleton& sk, const Pose& p, const IkConstraint& c) {
    return (effectorCm(sk, p, c.effector) - c.targetCm).norm();
}
}  // namespace

TEST_CASE("drag session: the constraints are the target, the pins, then feet in contact, each held once") {
    const Clip clip = makeSyntheticWalk();
    const Pose& start = clip.frames[40];
    const Eigen::Vector3d lfoot = effectorCm(clip.skeleton, start, Effector::kLFoot);
    const Eigen::Vector3d rfoot = effectorCm(clip.skeleton, start, Effector::kRFoot);
    const Eigen::Vector3d lhand = effectorCm(clip.skeleton, start, Effector::kLHand);
    DragSession drag;
    // The right hand is dragged; the left foot is both pinned and in contact; the dragged hand's own pin is ignored.
    drag.begin(clip.skeleton, Effector::kRHand, start, nullptr, {},
               {{Effector::kLFoot, lfoot, true}, {Effector::kRHand, Eigen::Vector3d::Zero(), true}},
               {{Effector::kLFoot, lfoot, true}, {Effector::kRFoot, rfoot, true}});
    const std::vector<IkConstraint> cs = drag.constraints();
    REQUIRE(cs.size() == 3);
    CHECK(cs[0].effector == Effector::kRHand);
    CHECK_FALSE(cs[0].pin);
    CHECK(cs[0].targetCm.isApprox(effectorCm(clip.skeleton, start, Effector::kRHand)));
    CHECK((cs[1].effector == Effector::kLFoot && cs[1].pin));
    CHECK((cs[2].effector == Effector::kRFoot && cs[2].pin));
    // Pins changed mid-drag are held from the next solve on.
    drag.setPins({{Effector::kLHand, lhand, true}});
    const std::vector<IkConstraint> later = drag.constraints();
    REQUIRE(later.size() == 4);
    CHECK(later[1].effector == Effector::kLHand);
    CHECK(later[2].effector == Effector::kLFoot);  // now held as a contact, no longer by a pin
}

TEST_CASE("drag session: without a model a drag is plain IK that holds the pins") {
    const Clip clip = makeSyntheticWalk();
    const Pose& start = clip.frames[10];
    const IkConstraint pin{Effector::kLFoot, effectorCm(clip.skeleton, start, Effector::kLFoot), true};
    DragSession drag;
    drag.begin(clip.skeleton, Effector::kRHand, start, nullptr, {}, {pin}, {});
    CHECK(drag.active());
    CHECK_FALSE(drag.learned());
    const Eigen::Vector3d target = effectorCm(clip.skeleton, start, Effector::kRHand) + Eigen::Vector3d(0, 8, 5);
    drag.dragTo(target, 50);
    const SolveReadout& r = drag.readout();
    REQUIRE(r.valid);
    CHECK_FALSE(r.learned);
    CHECK(r.reached);
    CHECK(r.diagnostic.rfind("plain IK (no model)", 0) == 0);
    CHECK((effectorCm(clip.skeleton, drag.pose(), Effector::kRHand) - target).norm() <= kReachedToleranceCm);
    CHECK(distance(clip.skeleton, drag.pose(), pin) <= kReachedToleranceCm);
    CHECK(drag.x().size() == 0);
    CHECK(r.nearest.row == -1);    // no model: no captured data to compare with
    CHECK_FALSE(drag.refine(50));  // nothing to refine for plain IK
    drag.finish();
    CHECK_FALSE(drag.active());
    CHECK_FALSE(drag.comparePose());
}

TEST_CASE("drag session: a learned drag reaches its target with the pins held and records its latent path") {
    const gp::ModelVersionPtr v = test::walkModel35();
    const Clip& clip = v->model->clip;
    const int frame = 60;
    const Pose& start = clip.frames[frame];
    const IkConstraint pin{Effector::kLFoot, effectorCm(clip.skeleton, start, Effector::kLFoot), true};
    DragSession drag;
    drag.setCompare(CompareMode::kPlainIk, nullptr, frame);
    drag.begin(clip.skeleton, Effector::kRHand, start, v, latentStartForFrame(*v, frame), {pin}, {});
    REQUIRE(drag.learned());
    CHECK(drag.latentPath().size() == 1);
    const Eigen::Vector3d origin = effectorCm(clip.skeleton, start, Effector::kRHand);
    Eigen::Vector3d target = origin;
    for (int step = 1; step <= 10; ++step) {
        target = origin + Eigen::Vector3d(0, step, 0.5 * step);
        drag.dragTo(target, 50);
    }
    for (int i = 0; i < 40 && drag.refine(50); ++i) {
    }
    drag.settle();
    const SolveReadout& r = drag.readout();
    REQUIRE(r.valid);
    CHECK(r.learned);
    CHECK(r.reached);
    CHECK((effectorCm(clip.skeleton, drag.pose(), Effector::kRHand) - target).norm() <= 0.05);
    CHECK(distance(clip.skeleton, drag.pose(), pin) <= 0.05);
    CHECK(drag.latentPath().size() >= 2);
    CHECK(drag.keptPose().size() == v->model->Y.cols());
    CHECK(drag.model() == v);
    // Where the pose is in the data: the nearest captured frame of the model's clip.
    CHECK(r.nearestClip == "35_01");
    const NearestPose expected = nearestPose(PoseLayout(clip.skeleton).extract(drag.pose()), poseMatrix(clip));
    CHECK(r.nearest.row == expected.row);
    CHECK(r.nearest.rmsDeg == expected.rmsDeg);
    CHECK(r.nearest.rmsDeg < 10.0);  // an 11 cm hand move stays close to captured poses (walk: any cycle)
    // The compare ghost: the same targets solved by plain IK from the start pose.
    REQUIRE(drag.comparePose());
    CHECK((effectorCm(clip.skeleton, *drag.comparePose(), Effector::kRHand) - target).norm() <= kReachedToleranceCm);
    drag.setCompare(CompareMode::kNone, nullptr, frame);
    CHECK_FALSE(drag.comparePose());
}

TEST_CASE("drag session: a latent drag poses from the model mean over the base pose") {
    const gp::ModelVersionPtr v = test::walkModel35();
    const Clip& clip = v->model->clip;
    const Pose& base = clip.frames[20];
    DragSession drag;
    CHECK_FALSE(drag.latentTo(Eigen::Vector2d(0, 0), base));  // not in a latent drag
    drag.beginLatent(clip.skeleton, v, latentStartForFrame(*v, 20), base);
    CHECK(drag.latentActive());
    CHECK_FALSE(drag.active());
    const Eigen::VectorXd x = v->model->X.row(v->model->active[3]).transpose();
    REQUIRE(drag.latentTo(x, base));
    Eigen::VectorXd mean;
    double variance = 0.0;
    v->posterior->predict(x, mean, variance);
    Pose expected = base;
    PoseLayout(clip.skeleton).apply(v->model->fullPose(mean).data(), expected);
    CHECK(drag.pose().rootCm == base.rootCm);
    for (std::size_t j = 0; j < expected.anglesDeg.size(); ++j)
        CHECK(drag.pose().anglesDeg[j] == expected.anglesDeg[j]);
    CHECK(drag.latentPath().size() == 2);
    CHECK_FALSE(drag.latentTo(Eigen::Vector3d(0, 0, 0), base));          // wrong latent dimension
    CHECK_FALSE(drag.latentTo(Eigen::Vector2d(std::nan(""), 0), base));  // not finite
    CHECK(drag.latentPath().size() == 2);
    drag.finish();
    CHECK_FALSE(drag.latentActive());
}
