#pragma once
// The model-independent naturalness tests of the editing-range protocol (docs/maths.md §14).
// The reference set R holds real frames only (never model outputs, never the edited frame):
// other CMU trials of the same subject and motion, or, as a fallback, the training clip with the
// edited frame ±10 frames removed. Poses are full 47-vectors in degrees (docs/maths.md §2.1 order).
//
//  2. joint ranges: y_k ∈ [q_min − m_k, q_max + m_k], m_k = max(5°, 0.1 (q_max − q_min));
//  3. d_NN(y) = min_r MPJPE(y, r): mean 3-D distance (cm) over the end points of the 22 model
//     bones, root at the origin, heading removed (R_y(−ψ), ψ = yaw of the root's forward axis),
//     the edited effector's bone excluded; threshold τ = 99th percentile of leave-one-clip-out
//     d_NN over R (single clip: leave out ±10 frames);
//  4. PPCA log density ≥ the 1st percentile of held-out real frames;
//  5. continuity: max_k |y_k(δ) − y_k(δ − 1)| ≤ 15°.
// Test 1 (reach ≤ 0.5 cm) comes from the IK result.
#include <Eigen/Core>
#include <memory>
#include <utility>
#include <vector>

#include "eval/ppca_density.h"
#include "skeleton/clip.h"

namespace mgp {

struct ReferenceFrame {
    const Clip* clip = nullptr;  // its skeleton is used for FK
    int frame = 0;
    int group = 0;  // clip id for leave-one-clip-out
};

struct NaturalnessVerdict {
    bool ranges = false, nearest = false, density = false, continuity = false;
    double dNN = 0.0, logDensity = 0.0, maxStepDeg = 0.0;
    int rangeViolations = 0;
    int worstRangeDof = -1;  // the DOF furthest outside its range (−1: none)
    double worstRangeExcessDeg = 0.0;
    int maxStepDof = -1;  // the DOF that moved most since δ − 1
    bool all() const { return ranges && nearest && density && continuity; }
};

class NaturalnessTests {
public:
    // `frames`: the reference set (clips must outlive this object). `excluded`: the edited
    // effector's bone, left out of MPJPE.
    NaturalnessTests(std::vector<ReferenceFrame> frames, Effector excluded);

    // pose: full 47-vector; skeleton/root: how to run FK for it; previous: the pose at δ − 1
    // (nullptr at δ = 0 skips the continuity test).
    NaturalnessVerdict judge(const Skeleton& skeleton, const Eigen::VectorXd& pose,
                             const Eigen::VectorXd* previous) const;

    double nnThreshold() const { return tauNN_; }
    // The interval test 2 allows DOF k (degrees): R's range widened by its margin.
    std::pair<double, double> rangeBounds(int dof) const;
    double densityThreshold() const { return densityThreshold_; }
    int size() const { return static_cast<int>(frames_.size()); }
    const Eigen::MatrixXd& referencePoses() const { return poses_; }  // |R| × 47, unwrapped per clip
    // Normalised bone-end positions (root at origin, heading removed), 22×3 flattened, cm.
    static Eigen::VectorXd bodyShape(const Skeleton& skeleton, const Eigen::VectorXd& poseDeg);
    double nearestDistance(const Eigen::VectorXd& shape, int skipGroup = -1, int skipFrom = 0, int skipTo = -1) const;

private:
    std::vector<ReferenceFrame> frames_;
    std::vector<bool> boneMask_;  // 22 entries, false for the excluded bone
    Eigen::MatrixXd shapes_;      // |R| × 66
    Eigen::MatrixXd poses_;       // |R| × 47
    Eigen::VectorXd qMin_, qMax_;
    std::vector<int> densityColumns_;  // non-constant columns used by the density
    std::unique_ptr<PpcaDensity> density_;
    double tauNN_ = 0.0, densityThreshold_ = 0.0;
};

}  // namespace mgp
