#include "eval/editing_range.h"

#include <memory>

#include "gp/adaptive_update.h"
#include "ik/learned_ik.h"

namespace mgp {

EditingRange EditingRangeJob::run() const {
    EditingRange out;
    gp::ModelVersionPtr current = version;
    const gp::GpModel& m0 = *version->model;
    const Skeleton& sk = m0.clip.skeleton;
    const PoseLayout layout(sk);
    const Eigen::Vector3d origin = effectorCm(sk, m0.clip.frames[frame], effector);

    LearnedIkRequest req;
    req.start = m0.clip.frames[frame];
    req.startX = latentStartForFrame(*version, frame);
    req.maxIterations = ikIterations;
    bool passing[6] = {true, true, true, true, true, true};  // combined, reach, ranges, nearest, density, continuity
    int* ranges[6] = {&out.combined, &out.reach, &out.ranges, &out.nearest, &out.density, &out.continuity};
    Eigen::VectorXd previous;
    std::unique_ptr<LearnedIkSolver> solver;  // rebuilt only when an adaptive update changed the model
    for (int delta = 0; delta <= maxDeltaCm; ++delta) {
        if (!solver || solver->version() != current) solver = std::make_unique<LearnedIkSolver>(current);
        req.constraints = {{effector, origin + delta * direction, false}};
        const LearnedIkResult res = solver->solve(req);
        EditingStep step;
        step.deltaCm = delta;
        step.residualCm = res.constraints.empty() ? std::numeric_limits<double>::infinity() : res.constraints[0].residualCm;
        step.lik = res.lik;
        step.reach = res.reached;
        const Eigen::VectorXd poseDeg = layout.extract(res.pose);
        step.verdict = tests->judge(sk, poseDeg, delta == 0 ? nullptr : &previous);
        step.accepted = step.reach && step.verdict.all();
        step.poseDeg = poseDeg;
        const bool pass[6] = {step.accepted, step.reach, step.verdict.ranges, step.verdict.nearest, step.verdict.density,
                              step.verdict.continuity};
        for (int k = 0; k < 6; ++k) {
            passing[k] = passing[k] && pass[k];
            if (passing[k]) *ranges[k] = delta;
        }
        if (adaptive && passing[0] && res.x.allFinite()) {
            const gp::AdaptiveUpdateResult u = gp::adaptiveUpdate(*current, res.x, res.y, frame, adaptiveScgIterations);
            if (u.accepted) {
                current = u.version;
                step.updatedModel = true;
                ++out.adaptiveUpdates;
            }
        }
        out.steps.push_back(step);
        previous = poseDeg;
        req.start = res.pose;
        req.startX = res.x;
        bool anyPassing = false;
        for (int k = 1; k < 6; ++k) anyPassing = anyPassing || passing[k];
        if (!anyPassing) break;
    }
    return out;
}

}  // namespace mgp
