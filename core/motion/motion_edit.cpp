#include "motion/motion_edit.h"

#include <algorithm>
#include <stdexcept>
#include <thread>

namespace mgp {

std::string MotionEditJob::validate() const {
    if (!version) return "expected a model, found none";
    const int n = version->model->clip.frameCount();
    if (keyFrames.size() < 2) return "expected at least 2 key frames, found " + std::to_string(keyFrames.size());
    if (keyOffsetsCm.size() != keyFrames.size())
        return "expected one offset per key (" + std::to_string(keyFrames.size()) + "), found " + std::to_string(keyOffsetsCm.size());
    for (std::size_t i = 0; i < keyFrames.size(); ++i) {
        if (keyFrames[i] < 0 || keyFrames[i] >= n)
            return "expected key frames in 1.." + std::to_string(n) + ", found " + std::to_string(keyFrames[i] + 1);
        if (i > 0 && keyFrames[i] <= keyFrames[i - 1]) return "expected strictly increasing key frames";
        if (!keyOffsetsCm[i].allFinite()) return "expected finite key offsets, found NaN or Inf";
    }
    if (!version->model->clip.skeleton.hasEffector(effector))
        return std::string("expected an effector of this skeleton, found ") + effectorName(effector);
    return "";
}

std::vector<Eigen::Vector3d> MotionEditJob::capturedTrajectory() const {
    const Clip& clip = version->model->clip;
    std::vector<Eigen::Vector3d> out(clip.frameCount());
    FkState fk;
    for (int t = 0; t < clip.frameCount(); ++t) {
        forwardKinematics(clip.skeleton, clip.frames[t], fk);
        out[t] = effectorCm(clip.skeleton, fk, effector);
    }
    return out;
}

std::vector<Eigen::Vector3d> editTargetPath(const std::vector<Eigen::Vector3d>& captured,
                                            const std::vector<int>& keyFrames,
                                            const std::vector<Eigen::Vector3d>& keyOffsetsCm, PathMode mode) {
    const int first = keyFrames.front(), last = keyFrames.back();
    std::vector<HermiteKey> keys;
    for (std::size_t i = 0; i < keyFrames.size(); ++i) {
        const Eigen::Vector3d p = mode == PathMode::kDirect ? Eigen::Vector3d(captured[keyFrames[i]] + keyOffsetsCm[i])
                                                            : keyOffsetsCm[i];
        keys.push_back({double(keyFrames[i]), p});
    }
    const HermitePath path = mode == PathMode::kDirect
                                 ? HermitePath(keys, capturedVelocity(captured, first), capturedVelocity(captured, last))
                                 : HermitePath(keys, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    std::vector<Eigen::Vector3d> out;
    for (int t = first; t <= last; ++t) {
        const Eigen::Vector3d c = path.position(t);
        out.push_back(mode == PathMode::kDirect ? c : Eigen::Vector3d(captured[t] + c));
    }
    return out;
}

void MotionEditJob::run() {
    if (const std::string problem = validate(); !problem.empty()) throw std::invalid_argument(problem);
    const Clip& clip = version->model->clip;
    const std::vector<Eigen::Vector3d> target = editTargetPath(capturedTrajectory(), keyFrames, keyOffsetsCm, mode);
    const int first = keyFrames.front(), last = keyFrames.back();

    frames = clip.frames;
    cancelled = false;
    solvedFrames.clear();
    pathCm.clear();
    for (int t = first + 1; t < last; ++t) {
        solvedFrames.push_back(t);
        pathCm.push_back(target[t - first]);
    }
    results.assign(solvedFrames.size(), LearnedIkResult());
    const int count = static_cast<int>(solvedFrames.size());
    int workers = threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    workers = std::max(1, std::min(workers, count));
    auto work = [&](int worker) {
        LearnedIkSolver solver(version);
        LearnedIkRequest req;
        req.lambda = lambda;
        req.maxIterations = maxIterations;
        for (int i = worker; i < count; i += workers) {  // fixed assignment: deterministic
            if (cancel && cancel->load()) return;
            const int t = solvedFrames[i];
            req.start = clip.frames[t];
            req.startX = latentStartForFrame(*version, t);
            req.constraints = {{effector, pathCm[i], false}};
            solver.solve(req, results[i]);
            if (framesDone) ++*framesDone;
        }
    };
    std::vector<std::thread> pool;
    for (int w = 1; w < workers; ++w) pool.emplace_back(work, w);
    work(0);
    for (auto& th : pool) th.join();

    if (cancel && cancel->load()) {
        cancelled = true;
        frames = clip.frames;
        return;
    }
    maxResidualCm = 0.0;
    for (int i = 0; i < count; ++i) {
        frames[solvedFrames[i]] = results[i].pose;
        const double r = results[i].constraints.empty() ? std::numeric_limits<double>::infinity()
                                                        : results[i].constraints[0].residualCm;
        maxResidualCm = std::max(maxResidualCm, r);
    }
}

}  // namespace mgp
