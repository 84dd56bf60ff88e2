#include "edit/deferred_teaching.h"

#include <cmath>
#include <map>

#include "edit/latent_refit.h"
#include "gp/point_objective.h"

namespace mgp {

std::vector<DeferredPose> latestPerFrame(const std::vector<DeferredPose>& poses) {
    std::map<int, const DeferredPose*> latest;
    for (const DeferredPose& p : poses) latest[p.frame] = &p;
    std::vector<DeferredPose> out;
    for (const auto& [frame, p] : latest) out.push_back(*p);
    return out;
}

std::optional<DeferredTeaching> teachingOnModel(const gp::ModelVersion& version, const DeferredPose& pose) {
    DeferredTeaching t;
    t.sample.x = refitLatent(version, pose.frame, pose.yKept);
    t.sample.yKept = pose.yKept;
    t.sample.clipFrame = pose.frame;
    if (!t.sample.x.allFinite()) return std::nullopt;
    gp::PointWorkspace ws;
    const double lik = version.posterior->evaluate(t.sample.x, pose.yKept, ws, nullptr, nullptr);
    if (!std::isfinite(lik)) return std::nullopt;
    t.verdict = admitPose(version, pose.edited, pose.moved, true, false, ws.variance, lik, pose.balance);
    return t;
}

}  // namespace mgp
