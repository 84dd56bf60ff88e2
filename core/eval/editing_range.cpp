#include "eval/editing_range.h"

#include <limits>
#include <memory>
#include <optional>

#include "gp/train/adaptive_update.h"
#include "ik/constrained_ik.h"
#include "ik/learned_ik.h"
#include "motion/foot_contacts.h"

namespace mgp {

std::vector<std::string> EditingRange::binding() const {
    std::vector<std::string> out;
    const int at = combined + 1;
    if (at < 0 || at >= static_cast<int>(steps.size())) return out;
    const EditingStep& s = steps[at];
    if (!s.reach) out.push_back("reach");
    if (!s.verdict.ranges) out.push_back("joint ranges");
    if (!s.verdict.nearest) out.push_back("nearest real pose");
    if (!s.verdict.density) out.push_back("density");
    if (!s.verdict.continuity) out.push_back("continuity");
    return out;
}

namespace {

// One δ's solve, either the paper's learned IK or the editor's drag.
struct SweepSolve {
    Pose pose;
    Eigen::VectorXd x, y;
    double residualCm = std::numeric_limits<double>::infinity();
    double lik = 0.0;
    bool reached = false;
};

}  // namespace

EditingRange EditingRangeJob::run() const {
    EditingRange out;
    gp::ModelVersionPtr current = version;
    const gp::GpModel& m0 = *version->model;
    const Skeleton& sk = m0.clip.skeleton;
    const PoseLayout layout(sk);
    const Eigen::Vector3d origin = effectorCm(sk, m0.clip.frames[frame], effector);

    // The editor's drag holds the feet planted on the frame where they stand (unless one is the
    // edited effector) and keeps hands and feet above the clip's floor.
    std::vector<IkConstraint> pins;
    std::optional<double> floorCm;
    if (editorDrag) {
        const ContactSet contacts = detectFootContacts(m0.clip);
        FkState fk;
        forwardKinematics(sk, m0.clip.frames[frame], fk);
        pins = contactPinsAt(m0.clip, fk, contacts, frame, {{effector, origin, false}});
        floorCm = contacts.floorCm;
    }
    Pose startPose = m0.clip.frames[frame];
    Eigen::VectorXd startX = latentStartForFrame(*version, frame);
    bool passing[6] = {true, true, true, true, true, true};  // combined, reach, ranges, nearest, density, continuity
    int* ranges[6] = {&out.combined, &out.reach, &out.ranges, &out.nearest, &out.density, &out.continuity};
    Eigen::VectorXd previous;
    // Rebuilt only when an adaptive update changed the model.
    std::unique_ptr<LearnedIkSolver> learned;
    std::unique_ptr<ConstrainedIkSolver> drag;
    for (int delta = 0; delta <= maxDeltaCm; ++delta) {
        const IkConstraint target{effector, origin + delta * direction, false};
        SweepSolve res;
        if (editorDrag) {
            if (!drag || drag->version() != current) drag = std::make_unique<ConstrainedIkSolver>(current);
            ConstrainedIkRequest req;
            req.start = startPose;
            req.startX = startX;
            req.constraints = {target};
            req.constraints.insert(req.constraints.end(), pins.begin(), pins.end());
            req.maxIterations = ikIterations;
            req.floorCm = floorCm;
            req.localityReference = m0.clip.frames[frame];
            req.rootReferenceDeg = m0.clip.frames[frame].anglesDeg[0];
            req.reachedToleranceCm = 0.5;  // test 1, as the learned IK's `reached`
            const ConstrainedIkResult r = drag->solve(req);
            res = {r.pose, r.x,      r.y, r.constraints.empty() ? res.residualCm : r.constraints[0].residualCm,
                   r.lik,  r.reached};
            for (const IkConstraintResult& c : r.constraints) res.residualCm = std::max(res.residualCm, c.residualCm);
        } else {
            if (!learned || learned->version() != current) learned = std::make_unique<LearnedIkSolver>(current);
            LearnedIkRequest req;
            req.start = startPose;
            req.startX = startX;
            req.constraints = {target};
            req.maxIterations = ikIterations;
            const LearnedIkResult r = learned->solve(req);
            res = {r.pose, r.x,      r.y, r.constraints.empty() ? res.residualCm : r.constraints[0].residualCm,
                   r.lik,  r.reached};
        }
        EditingStep step;
        step.deltaCm = delta;
        step.residualCm = res.residualCm;
        step.lik = res.lik;
        step.reach = res.reached;
        const Eigen::VectorXd poseDeg = layout.extract(res.pose);
        step.verdict = tests->judge(sk, poseDeg, delta == 0 ? nullptr : &previous);
        step.accepted = step.reach && step.verdict.all();
        step.poseDeg = poseDeg;
        const bool pass[6] = {step.accepted,        step.reach,           step.verdict.ranges,
                              step.verdict.nearest, step.verdict.density, step.verdict.continuity};
        for (int k = 0; k < 6; ++k) {
            passing[k] = passing[k] && pass[k];
            if (passing[k]) *ranges[k] = delta;
        }
        // δ = 0 re-solves the captured frame: nothing was edited, so there is nothing to learn.
        if (adaptive && delta > 0 && passing[0] && res.x.allFinite()) {
            const gp::AdaptiveUpdateResult u = gp::adaptiveUpdate(*current, res.x, res.y, frame, adaptiveScgIterations);
            if (u.accepted) {
                current = u.version;
                step.updatedModel = true;
                ++out.adaptiveUpdates;
            }
        }
        out.steps.push_back(step);
        previous = poseDeg;
        startPose = res.pose;
        startX = res.x;
        bool anyPassing = false;
        for (int k = 1; k < 6; ++k) anyPassing = anyPassing || passing[k];
        if (!anyPassing) break;
    }
    return out;
}

}  // namespace mgp
