#pragma once
// Constrained learned IK: the most likely pose under the GPLVM prior that holds every pin exactly
// and meets every target as strongly as its strength asks (docs/maths-ik.md).
//
//   minimise over z = (x, y):  F(z) = L_IK(x, y) + ½ Σ_targets κ(s_t) ‖FK_t(y) − c_t‖²
//                                              + ½ k_root ‖y_root − r_ref‖² + ½ ℓ Σ_k w_k (y_k − y_ref,k)²
//                                              [+ the floor's and the balance's one-sided penalties]
//   subject to                 FK_p(y) = c_p  for every pin p                      (cm, degrees)
//
// Semantics (what an animator gets):
//   - Pins are hard equality constraints: met to 1e-5 cm whenever they are jointly feasible.
//   - A target of strength 1 ("exact") has κ = kExactTargetWeight: it is met (residual far below
//     0.05 cm) whenever it is reachable with the pins held; otherwise the pose is the least-squares
//     closest one (the prior only breaks ties) and the target reports reached = false.
//   - A target of strength s < 1 has κ = 2s/(1 − s): F is then (L_IK·(1 − s) + s‖FK − c‖²)/(1 − s),
//     the paper's penalty with λ = s. Lower s lets the prior keep the pose more natural.
//   - Balance (optional, `balance`): the whole-body centre of mass outside the pinned feet's support
//     costs ½ κ_b d², d its distance outside (docs/maths-ik.md §1): Gauss–Newton in H, the rest of
//     its Hessian (the centre of mass's curvature, the distance's own) in C in the Newton regime.
//   - Root orientation: y's three root rotations carry the stiff quadratic ½ k_root ‖Δ‖² (per
//     degree²) around r_ref (the drag's starting root rotation), so the whole body turns or tilts
//     only as much as the targets need once the limbs alone cost more than k_root·Δ.
//   - Locality (ℓ > 0, off by default): every DOF away from the targets' limbs costs its change
//     from y_ref (the start pose, or the drag's first), so the body follows a dragged limb only as
//     much as the target needs (localityWeights; docs/maths-ik.md §1).
//   - Floor (optional, floorCm): hands and feet stay on or above it. A target below the floor is
//     raised onto it before the solve and reports its miss from the asked position (reached =
//     false, belowFloor); a hand or foot on no target and no pin carries the one-sided penalty
//     ½ κ_exact min(0, p_y − floor)², so it rests on the floor rather than passing it (ends within
//     about 1e-4 cm of it; docs/maths-ik.md §1).
//   - The root translation, the model's constant columns and DOFs outside the pose vector stay at
//     the start pose's (constants: the model's) values.
//   - Held DOFs (rotate joint): each `held` entry fixes one joint angle at its value. It is
//     removed from the unknowns (its gradient entry is 0 and its Hessian row and column are those
//     of the identity, its Jacobian columns 0), so the step never moves it and it ends exactly at
//     its value, while the rest of the pose is the most likely one under the prior given it
//     (docs/maths-ik.md §7). A held DOF on a constant column or outside the pose vector is simply
//     set in the pose.
//
// Method: Levenberg–Marquardt with hard pins, on the exact gradient of F and the Hessian model
//   H = ∇²L_IK (exact: y–y and x–y blocks from ∂f/∂x and ∂σ²/∂x, the x–x block from the kernel's
//       second derivatives, ActiveSetPosterior::latentHessian; the ln σ² term included)
//     + Σ κ J_tᵀJ_t (Gauss–Newton for the targets) + k_root on the root diagonal,
//     + the constraints' curvature Σ κe_t·∇²FK_t + Σ ν_p·∇²FK_p (ν: least-squares multipliers)
//       once the iteration is in its Newton regime (the last step accepted with μ ≤ 1e-3);
//       before that it is indefinite and only slows the damping down.
// Marquardt damping μ·diag(H). The factorised matrix also carries ρAᵀA (ρ = κ) for the pins: it
// leaves the KKT step unchanged and makes the matrix positive definite wherever the Hessian is on
// the pins' tangent space. A model that is still indefinite gets a one-step shift τI. Each step
// solves the KKT system of the pins' linearisation (range-space form, A (H + μ diag H)⁻¹ Aᵀ), is
// shortened to at most half the RBF length scale in x and 20° in any angle, then a second-order
// correction (up to 5 projections in the same metric, stopped when one makes the residual larger)
// brings the trial point back onto the pins and onto the exact targets' linearised prediction:
// without it the κ-penalty charges the curved target manifold to every step along it and the
// iteration converges only linearly. Steps are
// accepted by the gain ratio (Nielsen's μ update) on F when both points are on the pins (to a
// tenth of the tolerance), else on the ℓ1 merit F + ν‖c‖₁; a trial may leave the pins by at most
// 1e-3 cm (the next step restores them), and a Gauss–Newton trial rejected only for leaving
// them, its F predicted, is retried shorter by the pins' second-order error, μ kept where the
// rejection put it. Before a trial point is scored, its latent point is
// re-optimised for its pose, from the sixth trial on (a drag event needs at most five, so drags
// keep their cost): up to three Newton steps on L_IK over x alone (y fixed; the exact x-gradient,
// the joint model's x–x block as Hessian with its eigenvalues taken in absolute value, the same
// latent bound, halving backtracking). F depends on x only through L_IK, so this is exact block
// elimination of x (variable projection): the outer step no longer has to drag x along behind y,
// which the indefinite x–x block made slow (docs/maths-ik.md §3). A solve still running after 20
// trial steps is crawling: from then on the shift is on the latent block only (τ on x, which always
// factorises a Gauss–Newton model; τI on every unknown froze the y DOFs whose prior curvature is
// below τ), 4× the smallest that factorises (bracketed), and the latent bound becomes a trust
// radius (up to 16×, and a step the grown radius made too long does not raise μ; down to 1/16
// after rejected steps it cut, outside the large-residual regime below), the 20° angle bound one too
// (halved, down to 0.5°, when a step it cut is rejected; set to half the largest angle change, at
// least 0.5°, of a full-length step rejected at a finite F with the pins held, unless it was a
// shortened retry), and μ falls 10× after a step the model
// predicted (gain within 1 ± 0.1) instead of at most 3×; earlier steps are untouched. A
// solve past 50 steps whose exact target is still out of tolerance (out of reach, or met only by a
// straight limb) uses the full Newton model after every accepted step: there Gauss–Newton
// converges only linearly. A crawling solve (past step 20) does so earlier, from its first step
// accepted after a rejection while that target sits at the end of a knee or elbow within 1 % of
// straight (limbExtension ≥ 0.99), for as long as it sits there: at the straight limb's
// rank-deficient Jacobian Gauss–Newton cannot see the end of the reach (docs/maths-ik.md §3).
// A crawling solve whose last Gauss–Newton trial had a gain ratio below 0.75 (it promised more
// decrease than it gave) keeps a Newton model that does not factorise, shifted by τI, instead of
// falling back to Gauss–Newton: the curvature Gauss–Newton omits is what limits its steps.
//
// Convergence (KKT): the pins' residual ‖c‖∞ ≤ pinToleranceCm (1e-5 cm) and the damped Newton
// decrement gᵀ(H + μ diag H)⁻¹g projected onto the pins' tangent space is at most
// stationarityAbsolute + stationarityRelative·|F| (1e-6 + 1e-10·|F|) with μ ≤ 1e-2 and no shift,
// i.e. no Newton step could lower F by more than that. `iterations` counts every linear solve/trial
// step (accepted or not); `evaluations` counts prior evaluations.
//
// The solver holds a preallocated workspace for one model version: warm starts come from the
// request (the previous event's (x, pose)). solve() never throws.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "gp/model_version.h"
#include "ik/balance_region.h"
#include "ik/ik_types.h"
#include "ik/locality.h"
#include "skeleton/centre_of_mass.h"
#include "skeleton/forward_kinematics.h"
#include "skeleton/pose_layout.h"

namespace mgp {

// Penalty per cm² (in ½κ‖e‖²) of an exact target: a 1e-3 cm miss costs 0.5, about what one
// degree of an unlikely joint angle costs under the prior, so reachable targets end ≪ 0.05 cm.
constexpr double kExactTargetWeight = 1e6;
// Root orientation stiffness per degree² (in ½k‖Δ‖²).
constexpr double kDefaultRootStiffness = 0.5;
// Balance weight κ_b per cm² (in ½κ_b d²): the centre of mass 1 cm outside its support costs 5·10⁴,
// far more than the prior's range over natural poses and a tenth of an exact target's weight, so the
// body leans back rather than tip where it can, and a reachable target is still met (≤ 0.011 cm off
// in the measured cases, docs/maths-ik.md §1).
constexpr double kBalanceWeight = 1e5;

enum class IkStop {
    kConverged,       // the KKT test above holds
    kIterationCap,    // maxIterations trial steps without meeting it
    kStalled,         // the damping grew past 1e12: no step lowers the merit (round-off level)
    kInvalidRequest,  // validate() failed; the start pose is returned
    kNonFinite,       // the start point has no finite objective; the start pose is returned
};
const char* ikStopName(IkStop stop);  // "converged", "iteration_cap", "stalled", "invalid_request", "non_finite"

// Target weight κ for a strength in (0, 1].
double targetWeight(double strength);

// One joint angle held at a value (degrees): pose.anglesDeg[joint][axis] = valueDeg.
struct HeldDof {
    int joint = -1;
    int axis = 0;  // 0, 1, 2 = x, y, z
    double valueDeg = 0.0;
};

struct ConstrainedIkRequest {
    Pose start;              // warm start pose (root translation is kept)
    Eigen::VectorXd startX;  // warm start latent point (d)
    std::vector<IkConstraint> constraints;
    std::vector<HeldDof> held;  // joint angles fixed at their values (none: every angle is free)
    int maxIterations = 50;
    double rootStiffness = kDefaultRootStiffness;
    std::optional<Eigen::Vector3d> rootReferenceDeg;  // r_ref; default: the start's root rotation
    // Locality ℓ per degree² (docs/maths-ik.md §1): ½ ℓ Σ_k w_k (y_k − y_ref,k)², w_k by the DOF's
    // distance along the skeleton from the targets' effectors (localityWeights). 0: off.
    double locality = kDefaultLocality;     // 0: off
    std::optional<Pose> localityReference;  // y_ref; default: the start pose
    std::optional<double> floorCm;          // world Y (cm) that hands and feet may not pass; none: no floor
    // Balance (docs/maths-ik.md §1): where the whole-body centre of mass may fall on the ground, the
    // pinned planted feet's support grown by half a sole (motion/support_polygon.h, balanceRegion);
    // the centre of mass outside it costs ½ κ_b d², d its distance outside (cm). None: not asked.
    std::optional<BalanceRegion> balance;
    double balanceWeight = kBalanceWeight;  // κ_b per cm²
    double pinToleranceCm = 1e-5;
    double stationarityAbsolute = 1e-6;
    double stationarityRelative = 1e-10;
    double reachedToleranceCm = 0.05;  // a constraint is reached within this
};

struct ConstrainedIkResult {
    Pose pose;
    Eigen::VectorXd x, y;                         // latent point (d), kept pose columns (D, degrees)
    double sigma2 = 0.0;                          // σ²(x)
    double lik = 0.0;                             // L_IK(x, y)
    double objective = 0.0;                       // F (without the pins, which hold)
    double decrement = 0.0;                       // the last stationarity measure (see above)
    std::vector<IkConstraintResult> constraints;  // in request order
    bool reached = false;                         // every target and pin within reachedToleranceCm
    bool converged = false;                       // stop == kConverged
    IkStop stop = IkStop::kInvalidRequest;
    int iterations = 0;
    int evaluations = 0;
    std::string diagnostic;  // human-readable; the validation error for kInvalidRequest
};

class ConstrainedIkSolver {
public:
    explicit ConstrainedIkSolver(gp::ModelVersionPtr version);
    const gp::ModelVersionPtr& version() const { return version_; }

    // "" if the request can be solved, else what is wrong (expected ..., found ...).
    std::string validate(const ConstrainedIkRequest& request) const;
    void solve(const ConstrainedIkRequest& request, ConstrainedIkResult& result);
    ConstrainedIkResult solve(const ConstrainedIkRequest& request);

    // F at z = (x, y) for `request` and, if `gradient` is given, its exact gradient (the tests
    // check it against central differences). Pins are not part of F. Held DOFs' entries of the
    // gradient are 0 (they are not unknowns).
    double objective(const ConstrainedIkRequest& request, const Eigen::VectorXd& z, Eigen::VectorXd* gradient);
    // The Hessian model H at z (after objective() at the same z with a gradient).
    const Eigen::MatrixXd& hessianModel() const { return H_; }
    // The start point z0 of a request (latent start and kept columns of the start pose).
    Eigen::VectorXd startPoint(const ConstrainedIkRequest& request);

private:
    void bind(const ConstrainedIkRequest& request);
    // F, and with `derivatives` also g_, H_, A_, c_ (pins) at z. Its parts, in order:
    double evaluate(const Eigen::VectorXd& z, bool derivatives);
    // g_ and H_ = L_IK's gradient and Hessian (y–y, x–y, x–x blocks); C_ = 0.
    void priorDerivatives();
    // F += ½κ‖FK_t − c_t‖² per target; Gauss–Newton terms, their curvature in C_, Aall_'s rows.
    void addTargetTerms(double& F, bool derivatives);
    // F += the root orientation's and the locality's quadratics (exact, diagonal).
    void addRootAndLocalityTerms(double& F, bool derivatives);
    // F += the one-sided floor penalty of the free hands and feet (Gauss–Newton on the vertical row).
    void addFloorTerms(double& F, bool derivatives);
    // F += the balance term ½ κ_b d² (Gauss–Newton on the centre of mass's ground Jacobian).
    void addBalanceTerm(double& F, bool derivatives);
    // c_, A_ and Aall_'s pin rows; held DOFs frozen; C_ += the pins' ν·∇²FK in the Newton regime.
    void pinDerivatives();
    // FK at z and the second-order correction's residual r = [pins' c; exact targets' e − ê]
    // (cm); returns the pins' ‖c‖∞.
    double correctionResidual(const Eigen::VectorXd& z, Eigen::VectorXd& r);
    void setPose(const Eigen::VectorXd& y);
    void fillResult(const ConstrainedIkRequest& request, ConstrainedIkResult& result);
    // Every constraint's residual and reached flag at the current FK, against `request`'s targets.
    void scoreConstraints(const ConstrainedIkRequest& request, ConstrainedIkResult& result) const;
    // solve() once the targets below the floor have been raised onto it: the start, then trial
    // steps until the KKT test holds, μ passes kMaxDamping or maxIterations trials are taken.
    void solveOnFloor(const ConstrainedIkRequest& request, ConstrainedIkResult& result);
    // The result of a request validate() refused (`problem`): the start pose, no numbers.
    void rejectRequest(const ConstrainedIkRequest& request, const std::string& problem,
                       ConstrainedIkResult& result) const;

    // The iteration's state from one trial step to the next (see the header comment's Method).
    struct Iteration {
        double F = 0.0;        // F at z_
        double mu = 1e-6;      // Marquardt damping μ
        double nuLm = 2.0;     // Nielsen's factor: μ *= nuLm after a rejection, then nuLm doubles
        double meritNu = 0.0;  // ν of the ℓ1 merit F + ν‖c‖₁ (never decreases)
        int it = 0;            // trial steps taken
        IkStop stop = IkStop::kIterationCap;
        bool lastAccepted = false;              // the last trial was accepted (a Newton model may follow)
        double latentRadius = 0.0;              // latent trust radius: grows only once the solve is crawling
        double angleRadius = 0.0;               // angle trust radius (°): shrinks only once the solve is crawling
        bool largeResidual = false;             // Newton model after every accepted step
        bool straightLimbNewton = false;        // Gauss–Newton failed at a straight limb
        bool rejectedSinceAccepted = false;     // a trial was rejected since the last accepted one
        bool gaussNewtonOverpredicted = false;  // the last Gauss–Newton trial's gain ratio was below 0.75
        // Step caps for the retry of a trial rejected only because it left the pins (planRetry).
        double retryAngleCap = std::numeric_limits<double>::infinity();
        double retryLatentCap = std::numeric_limits<double>::infinity();
    };
    // One step: its model, the KKT step at z_ and how it was bounded.
    struct Step {
        bool crawling = false;                     // past kCrawlIterations trials: the crawling rules apply
        bool shortenedRetry = false;               // this step retries one that left the pins, shortened
        bool newton = false;                       // Hm_ carries the constraints' curvature C_
        bool keepIndefiniteNewton = false;         // an indefinite Newton model is shifted, not dropped
        double shift = 0.0;                        // τ added to the model's diagonal (0: it factorised)
        double pinWorst = 0.0;                     // ‖c‖∞ at z_
        double modelDecrease = 0.0;                // the model's decrease of F along the full step
        double decrement = 0.0;                    // the stationarity measure (the damped Newton decrement)
        double latentBound = 0.0;                  // the latent step bound this step had
        double scale = 1.0;                        // the step's shortening (1: full length)
        bool latentCut = false, angleCut = false;  // the latent / angle bound set the length
        double stepDecrease = 0.0;                 // the model's decrease of F along the bounded step
        double c1 = 0.0;                           // ‖c‖₁ at z_
        double pred = 0.0;                         // the merit's predicted decrease
    };
    // How a trial point scored.
    struct Trial {
        double Ft = 0.0;            // F at the trial point
        double gain = 0.0;          // actual / predicted decrease
        double pinAllowance = 0.0;  // how far the trial may leave the pins (cm)
        bool pinsHeld = false, accepted = false;
        bool predictedWell = false;  // gain within 1 ± kAccurateGain
    };
    // One iteration of solveOnFloor, phase by phase:
    // 1. The model Hm_ (Gauss–Newton, or Newton with C_), damped and factorised as Hd_; false: an
    //    indefinite Newton model falls back to Gauss–Newton (the step is built again).
    bool buildModel(const Iteration& s, Step& step);
    // 2. A model that did not factorise is shifted by τ until it does; false: none does (stalled).
    bool shiftIndefiniteModel(Step& step);
    //    A crawling solve's τ: 4× the smallest that factorises, bracketed below `shift`.
    double bracketShift(double shift, bool latentOnly);
    //    Hd_'s diagonal += amount (the latent block only, or every unknown).
    void addShift(double amount, bool latentOnly);
    // 3. The KKT step delta_ (ν: nu_) of the pins' linearisation; its model decrease, the decrement.
    void kktStep(Step& step);
    // 4. The convergence test (pins met, decrement small, μ ≤ 1e-2, no shift).
    bool stationary(const Iteration& s, const Step& step) const;
    // 5. delta_ shortened to the step bounds (trust radii once crawling); the merit's prediction.
    void boundStep(Iteration& s, Step& step);
    // 6. zTrial_ = z_ + delta_, corrected onto the pins and the exact targets' prediction; ‖c‖₁ there.
    double correctTrial();
    // 7. The trial scored: x refitted to its pose (refineLatent, from trial 6), F, the gain ratio.
    Trial scoreTrial(const Iteration& s, const Step& step, double trialPinNorm);
    // 8. The caps of the shortened retry of a Gauss–Newton trial that left the pins.
    void planRetry(Iteration& s, const Step& step, const Trial& t);
    // 9. A crawling solve's latent and angle trust radii after the trial.
    void updateTrustRadii(Iteration& s, const Step& step, const Trial& t);
    // 10. Accepted: z_ = zTrial_, μ falls, the next model's regime, derivatives there; false: not finite.
    bool acceptTrial(Iteration& s, const Step& step, const Trial& t);
    //     Rejected: μ rises (Nielsen) unless a grown trust radius made the step too long; false: stalled.
    bool rejectTrial(Iteration& s, const Step& step);
    // Rows row..row+2 of `into` = the effector Jacobian jac_ on the kept columns y (x columns 0).
    void scatterJacobian(Eigen::MatrixXd& into, Eigen::Index row) const;
    // C_ += λ·∂²FK_e/∂y² (y–y block) at the current FK.
    void addConstraintCurvature(Effector e, const Eigen::Vector3d& lambda);
    // Lowers L_IK over the latent part of z with its pose fixed (the trial's variable projection).
    void refineLatent(Eigen::VectorXd& z);
    // At the pose of the last evaluate(): whether an exact target is farther than the reached
    // tolerance, and whether one such sits at the end of a straight limb (limbExtension ≥ 0.99).
    struct ExactTargetReach {
        bool outside = false;
        bool outsideAtStraightLimb = false;
    };
    ExactTargetReach exactTargetReach(double reachedToleranceCm) const;
    // g_ += w r ∂r, H_ += w ∂rᵀ∂r on the kept columns, ∂r = gaussNewtonRow_ (a one-sided penalty
    // ½ w r², the floor's and the balance's, in its Gauss–Newton form).
    void addGaussNewtonRow(double weight, double residual);
    // Removes the held DOFs from the unknowns in g_, H_, A_ and Aall_ (and C_ when `curvature`).
    void freezeHeld(bool curvature);

    gp::ModelVersionPtr version_;
    PoseLayout layout_;
    BodyMass bodyMass_;  // the centre of mass's segments on the model's skeleton, resolved once
    int d_ = 0, D_ = 0, n_ = 0;
    std::vector<int> yOfDof_;  // pose-vector index → index into y (−1 if constant)
    std::vector<int> heldY_;   // indices into y of the request's held DOFs
    int rootY_[3] = {-1, -1, -1};
    std::vector<Effector> floorGuarded_;       // hands and feet on no constraint, kept above the floor
    Eigen::VectorXd localityW_, localityRef_;  // ℓ·w_k and y_ref on the kept columns (held: 0)
    double latentStepBound_ = 0.0;             // longest latent step (half the RBF length scale)

    // Bound request.
    const ConstrainedIkRequest* request_ = nullptr;
    std::vector<int> pins_, targets_, exactTargets_;  // indices into request_->constraints
    std::vector<int> correctionRow_;                  // per target: its first row in Aall_, −1 if not exact
    Eigen::Vector3d rootRef_ = Eigen::Vector3d::Zero();

    // Workspace.
    Pose pose_;
    FkState fk_;
    Eigen::VectorXd full_, x_, y_, gx_, gy_, gyTmp_, dS2_;
    Eigen::VectorXd xR_, gR_, sR_, xRt_, gRt_, nuT_, deltaT_;  // latent refinement, tangent decrement
    Eigen::MatrixXd HR_, Hxx_;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigR_;
    Eigen::MatrixXd Jf_;
    gp::PointWorkspace ws_, wsRefine_;
    Eigen::Matrix<double, 3, Eigen::Dynamic> jac_;
    Eigen::RowVectorXd gaussNewtonRow_;  // ∂r/∂(pose DOFs) of a one-sided penalty's residual r
    Eigen::VectorXd g_, c_, cTrial_, z_, zTrial_, zSoc_, delta_, tmp_, nu_, rhs_;
    Eigen::MatrixXd H_, C_, Hm_, Hd_, A_, HinvAt_, S_, hc_;
    Eigen::LLT<Eigen::MatrixXd> llt_;
    Eigen::LDLT<Eigen::MatrixXd> sLdlt_, sAllLdlt_;
    // Second-order correction over pins and exact targets: Jacobian rows, predicted residuals ê.
    Eigen::MatrixXd Aall_, HinvAll_, Sall_;
    Eigen::VectorXd eAt_, eHat_, rAll_;
    double sigma2_ = 0.0, lik_ = 0.0;
    bool curvature_ = false;  // evaluate() also fills C_ (the constraints' curvature)
    // What the workspace holds, so a point is not evaluated twice (a trial that is accepted is
    // scored without derivatives, then evaluated with them): fk_ is FK at yPosed_, ws_ the prior's
    // value at zValued_; bind() clears both.
    Eigen::VectorXd yPosed_, zValued_;
    bool posed_ = false, valued_ = false;
    // Per effector: the pose-vector DOFs on its chain (effectorHessianContracted is 0 elsewhere).
    std::vector<int> chainDofs_[kEffectorCount];
    int evaluations_ = 0;
};

}  // namespace mgp
