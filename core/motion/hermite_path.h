#pragma once
// Cubic Hermite path of one effector through key frames (docs/maths.md §12).
// Time is the frame index itself (uniform knots, never chord length), positions in cm, tangents
// in cm per frame. Interior tangents are Catmull–Rom (central differences of the keys); the end
// tangents are given (the captured motion's own velocity), so the edited path joins the
// untouched motion C¹-continuously.
#include <Eigen/Core>
#include <vector>

namespace mgp {

struct HermiteKey {
    double frame = 0.0;
    Eigen::Vector3d positionCm = Eigen::Vector3d::Zero();
};

class HermitePath {
public:
    // keys: at least 2, strictly increasing frames. Throws std::invalid_argument otherwise.
    HermitePath(std::vector<HermiteKey> keys, const Eigen::Vector3d& startTangent, const Eigen::Vector3d& endTangent);

    // Position at frame t (clamped to the first/last key outside the range).
    Eigen::Vector3d position(double t) const;
    // d position / d frame at t.
    Eigen::Vector3d velocity(double t) const;

    const std::vector<HermiteKey>& keys() const { return keys_; }
    const std::vector<Eigen::Vector3d>& tangents() const { return tangents_; }

private:
    int segmentOf(double t) const;
    std::vector<HermiteKey> keys_;
    std::vector<Eigen::Vector3d> tangents_;
};

// The captured velocity at frame t of a sampled trajectory (central difference, cm/frame).
Eigen::Vector3d capturedVelocity(const std::vector<Eigen::Vector3d>& trajectory, int t);

}  // namespace mgp
