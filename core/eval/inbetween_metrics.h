#pragma once
// The in-betweening benchmark's measures (docs/maths-inbetween.md §3), after LaFAN1's
// `benchmarks.py` (Harvey et al. 2020), on one skeleton's windows.
//
// A window is the frames a..b of a clip: key a, the transition a+1..b−1, key b. Before anything is
// compared, every window is moved into the frame of its key a: the root of frame a at the origin of
// the ground plane (x = z = 0, the height kept) and its heading (the root's forward axis projected
// on the ground) turned onto +z. Global joint positions (cm) and global joint rotations (unit
// quaternions, the sign of each joint's first one chosen with w ≥ 0 and every later one kept on
// the side of the one before) are then taken on the transition frames only.
//   L2P  = mean over transition frames of ‖(p − p̂) / σ‖, p the 3J global positions, σ the
//          per-coordinate standard deviation of the training windows' positions (LaFAN1 also
//          subtracts their mean, which cancels in the difference);
//   L2Q  = mean over transition frames of ‖q − q̂‖ over the 4J quaternion components;
//   NPSS = Σ_c w_c·EMD_c / Σ_c w_c over the channels c (4J quaternion components) of every window:
//          per channel the real part of the DFT over time, squared and normalised to sum 1, its
//          cumulative sum, and EMD_c the L1 distance of those of truth and prediction; w_c the
//          truth's total power. Channels whose truth has no power carry no weight.
#include <Eigen/Core>
#include <vector>

#include "skeleton/pose_layout.h"
#include "skeleton/skeleton.h"

namespace mgp {

// One window in its key's frame: row t is frame a+1+t of the transition.
struct WindowGlobals {
    Eigen::MatrixXd positions;    // T × 3J (cm)
    Eigen::MatrixXd quaternions;  // T × 4J (w, x, y, z per joint)
};

// `frames` holds a window a..b (at least 3 frames): key, transition, key.
WindowGlobals windowGlobals(const Skeleton& skeleton, const std::vector<Pose>& frames);

// Per-coordinate standard deviation of the positions of every transition frame of `windows`
// (population sd; a coordinate that never varies gets 1 so that it counts in cm).
Eigen::VectorXd positionSpread(const std::vector<WindowGlobals>& windows);

// The three measures of a prediction against the truth, summed over windows so that several
// windows (of one transition length) average as LaFAN1 averages a batch.
class InbetweenScore {
public:
    // Both of the same shape (windowGlobals of the same window's truth and prediction);
    // positionSd: positionSpread of the training windows the prediction's model learned from.
    void add(const WindowGlobals& truth, const WindowGlobals& prediction, const Eigen::VectorXd& positionSd);
    int frames() const { return frames_; }
    double l2p() const;
    double l2q() const;
    double npss() const;

private:
    int frames_ = 0;
    double l2pSum_ = 0.0, l2qSum_ = 0.0;
    double npssWeighted_ = 0.0, npssWeight_ = 0.0;
};

// NPSS of one window's channels alone (T × C each): Σ_c w_c EMD_c / Σ_c w_c and its weight Σ_c w_c.
struct NpssTerms {
    double weightedEmd = 0.0, weight = 0.0;
};
NpssTerms npssTerms(const Eigen::MatrixXd& truth, const Eigen::MatrixXd& prediction);

}  // namespace mgp
