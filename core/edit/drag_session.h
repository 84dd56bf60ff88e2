#pragma once
// DragSession: one drag in the viewport, from press to release, with no document state
// (docs/architecture.md §6, "where a drag goes"). It holds the pose being solved, its latent
// point, the solver warm-started from the previous event, the readout and the compare ghost.
//
//   begin(e, start, model, startX, holds) -> dragTo(target)* / refine()* -> settle() -> finish()
//
// The document decides what the drag holds (pins, feet in contact), turns the finished pose into
// an undo step and decides whether the model may learn it. A latent drag (posing the frame from
// the model mean f(x)) is the other mode of the same session: beginLatent -> latentTo* -> finish.
// Without a model a drag is solved by plain IK (damped least squares) and the readout says so.
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "edit/compare_mode.h"
#include "eval/nearest_pose.h"
#include "gp/model_version.h"
#include "ik/constrained_ik.h"
#include "skeleton/pose_layout.h"
#include "skeleton/skeleton.h"

namespace mgp {

// Readout of the latest solve.
struct SolveReadout {
    bool valid = false;
    bool learned = false;  // false: plain IK (no model loaded)
    std::vector<IkConstraintResult> constraints;
    bool reached = false;
    double sigma2 = 0.0, lik = 0.0;
    int iterations = 0;  // total over the drag's last target (live solve + refinements)
    bool converged = false;
    IkStop stop = IkStop::kInvalidRequest;  // of the last solve (learned only)
    std::string diagnostic;
    // Where the pose is in the data (learned only): the captured frame of the model's clip
    // nearest to it, and how far (eval/nearest_pose.h; row -1 otherwise).
    std::string nearestClip;
    NearestPose nearest;
    // Horizontal move of the whole-body centre of mass from the drag's start pose (cm;
    // skeleton/centre_of_mass.h), or none for a skeleton without legs and trunk.
    std::optional<double> comShiftCm;
};

class DragSession {
public:
    DragSession();
    ~DragSession();
    DragSession(const DragSession&) = delete;
    DragSession& operator=(const DragSession&) = delete;

    // Starts dragging `e` from `start` (skeleton must outlive the drag). With a model the drag
    // is a learned solve from latent point `startX`; without, plain IK. `pins` are the user's
    // pins (effector held at a position), `contactPins` the feet in contact where they were
    // when the drag began: both are held unless they are the dragged effector, and a foot the
    // user pinned is held by its pin only.
    void begin(const Skeleton& skeleton, Effector e, const Pose& start, gp::ModelVersionPtr model,
               Eigen::VectorXd startX, std::vector<IkConstraint> pins, std::vector<IkConstraint> contactPins);
    // How the learned solves of the next drags hold the body (ConstrainedIkRequest): the floor
    // hands and feet stay above (none: no floor) and the locality ℓ, against the drag's start pose.
    void setFloor(std::optional<double> floorCm) { floorCm_ = floorCm; }
    // The balance term's region for the next drag (ConstrainedIkRequest::balance); none: not asked.
    void setBalance(std::optional<BalanceRegion> region) { balance_ = std::move(region); }
    void setLocality(double locality) { locality_ = locality; }
    // Pins changed while dragging: the next solve holds these.
    void setPins(std::vector<IkConstraint> pins) { pins_ = std::move(pins); }
    // Solves for a new target, warm-started from the previous solve (iteration cap per event).
    void dragTo(const Eigen::Vector3d& targetCm, int maxIterations);
    // More iterations on the same target while the user holds still; false if nothing to do
    // (converged, plain IK, not dragging, or the refinement budget is spent).
    bool refine(int maxIterations);
    // On release: a learned solve that has not converged gets a few hundred more iterations.
    void settle();
    // Ends either mode (the pose stays readable until the next begin).
    void finish();

    bool active() const { return active_; }
    bool learned() const { return solver_ != nullptr && model_ != nullptr; }
    Effector effector() const { return effector_; }
    Eigen::Vector3d target() const { return targetCm_; }
    const Pose& pose() const { return pose_; }
    const Eigen::VectorXd& x() const { return x_; }
    const SolveReadout& readout() const { return readout_; }
    // The model version the drag solves on (null for plain IK).
    const gp::ModelVersionPtr& model() const { return model_; }
    // The pose vector in the model's kept columns of the last learned solve (empty otherwise).
    const Eigen::VectorXd& keptPose() const { return result_.y; }
    // Every constraint of the current target: the target, then pins, then feet in contact.
    std::vector<IkConstraint> constraints() const;

    // The compare ghost (docs/architecture.md §6): the same targets solved by plain IK or by a
    // second model, from the drag's start pose. `frame` picks the second model's latent start.
    void setCompare(CompareMode mode, gp::ModelVersionPtr compareModel, int frame);
    const std::optional<Pose>& comparePose() const { return comparePose_; }

    // Latent drag: the pose is f(x) of `model` laid over `base` (root translation and the
    // DOFs the model does not cover kept from `base`).
    void beginLatent(const Skeleton& skeleton, gp::ModelVersionPtr model, Eigen::VectorXd x, const Pose& pose);
    // Moves the latent point; false if x is not usable (wrong size, non-finite pose).
    bool latentTo(const Eigen::VectorXd& x, const Pose& base);
    bool latentActive() const { return latent_; }

    // Latent points visited by the current drag (or the last one), in order.
    const std::vector<Eigen::VectorXd>& latentPath() const { return latentPath_; }
    // Forgets the path and the readout (a new clip).
    void clear();
    // Drops the solver and the latent path, which belong to a model that is going away.
    void forgetModel();

private:
    void solveLearned(int maxIterations);
    void solvePlain();
    void solveCompare();
    // The readout's centre-of-mass move, against the start's (computed once per drag).
    std::optional<double> comShiftFromStart() const;

    const Skeleton* skeleton_ = nullptr;
    std::optional<PoseLayout> layout_;  // of *skeleton_, bound once per drag, not once per event
    gp::ModelVersionPtr model_;
    bool active_ = false, latent_ = false;
    Effector effector_ = Effector::kRFoot;
    Eigen::Vector3d targetCm_ = Eigen::Vector3d::Zero();
    Pose startPose_, pose_;
    std::optional<Eigen::Vector3d> startCom_;  // whole-body centre of mass of startPose_
    Eigen::VectorXd x_;
    int refineBudget_ = 0;
    std::optional<double> floorCm_;
    std::optional<BalanceRegion> balance_;
    double locality_ = kDefaultLocality;
    bool converged_ = false;
    std::vector<IkConstraint> pins_, contactPins_;
    std::vector<Eigen::VectorXd> latentPath_;
    SolveReadout readout_;
    std::vector<Eigen::MatrixXd> capturedPoses_;  // poseMatrix of each model clip (the nearest-frame candidates)
    std::shared_ptr<const gp::GpModel> capturedPosesOf_;  // the model they were taken from

    std::unique_ptr<ConstrainedIkSolver> solver_, compareSolver_;
    ConstrainedIkRequest request_;
    ConstrainedIkResult result_;

    CompareMode compare_ = CompareMode::kNone;
    gp::ModelVersionPtr compareModel_;
    int compareFrame_ = 0;
    std::optional<Pose> comparePose_;
};

}  // namespace mgp
