#pragma once
// Motion regeneration along an edited effector path (ALGORITHM.md §10).
//
// Keys are clip frames t_0 < … < t_n (0-based) with an offset (cm) each; the paper's example is
// 89, 103, 117, 131 with the two middle keys moved. Direct mode (the paper's): a cubic Hermite
// path through P_i = p_e(t_i) + offset_i with Catmull–Rom interior tangents and the captured
// velocity at both ends. Displacement mode (an option): d(t) through the offsets (0 and tangent 0
// at the ends, Catmull–Rom inside), target p_e(t) + d(t), which keeps the captured detail.
// Each frame strictly inside (t_0, t_n) is solved with the learned IK, warm-started from that
// frame's own (x_t, y_t) — never chained frame to frame. Frames t_0, t_n and everything outside
// keep their captured poses bit for bit. Solves run in parallel (one solver per thread) and the
// result does not depend on the thread count.
#include <atomic>
#include <vector>

#include "ik/learned_ik.h"
#include "motion/hermite_path.h"

namespace mgp {

enum class PathMode { kDirect, kDisplacement };

// The effector's target at every frame first..last (= keyFrames.front()..back()) of the edited
// path, from its captured trajectory (every clip frame) and the keys. Keys must be valid.
std::vector<Eigen::Vector3d> editTargetPath(const std::vector<Eigen::Vector3d>& captured,
                                            const std::vector<int>& keyFrames,
                                            const std::vector<Eigen::Vector3d>& keyOffsetsCm, PathMode mode);

struct MotionEditJob {
    // Inputs.
    gp::ModelVersionPtr version;
    Effector effector = Effector::kRFoot;
    std::vector<int> keyFrames;                  // clip frame indices, strictly increasing
    std::vector<Eigen::Vector3d> keyOffsetsCm;   // one per key
    PathMode mode = PathMode::kDirect;
    double lambda = 0.999;
    int maxIterations = 500;                     // per frame
    int threads = 0;                             // ≤ 0: hardware concurrency
    std::atomic<int>* framesDone = nullptr;      // optional: counts solved frames (progress bars)
    const std::atomic<bool>* cancel = nullptr;   // optional: stop early; run() then sets `cancelled`

    // Outputs.
    std::vector<Pose> frames;                    // the whole edited motion (every clip frame)
    std::vector<int> solvedFrames;               // frames that were re-solved
    std::vector<LearnedIkResult> results;        // one per solved frame
    std::vector<Eigen::Vector3d> pathCm;         // the target path at each solved frame
    double maxResidualCm = 0.0;
    bool cancelled = false;                      // `frames` is then the unedited clip

    std::string validate() const;  // "" or "expected …, found …"
    void run();                    // throws std::invalid_argument if validate() fails
    // The effector's captured position at every clip frame (needs validate() == "").
    std::vector<Eigen::Vector3d> capturedTrajectory() const;
};

}  // namespace mgp
