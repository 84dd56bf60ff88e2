#pragma once
// A temporal prior on the latent points of a clip (docs/maths.md §19): the second-difference
// smoothness penalty
//
//   L_smooth(X) = (λ/2) Σ_t ‖a_t x_{t−1} + b_t x_t + c_t x_{t+1}‖²
//
// over every three time-consecutive training rows of one segment. With equal frame gaps
// (a, b, c) = (1, −2, 1); with unequal gaps h₁, h₂ (in units of the median gap) it is the
// divided second difference a = 2/(h₁(h₁+h₂)), c = 2/(h₂(h₁+h₂)), b = −(a + c), which still
// annihilates constant and linear motion. A segment breaks where the gap to the next row (in clip
// frames, rows sorted by frame) is 0 or more than 3 median gaps, so separate takes or frame
// ranges are never tied together. With several source clips (core/gp/model.h) rows are ordered
// by (clip, frame) and a segment also breaks wherever the clip changes: rows of different clips
// are never joined, whatever their frame numbers. The prior only adds to the objectives of Steps 6 and 8
// (core/gp/train/trainer.h); with LatentPrior::kNone nothing changes (the paper's model).
//
// kPaced (docs/maths.md §19) keeps the same segments but measures the gaps h₁, h₂ in pose distance
// ‖y_t − y_{t−1}‖ (in units of the median step, clamped to [kMinPaceGap, kMaxPaceGap]) instead of
// frames: a latent path whose speed follows the pose's speed costs nothing, so a jump's takeoff
// may move fast in latent space while a still stretch is held together.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace mgp::gp {

enum class LatentPrior { kNone, kSmooth, kPaced };
const char* latentPriorName(LatentPrior p);  // "none" / "smooth" / "paced"
bool parseLatentPrior(const std::string& s, LatentPrior& out);

// Pose-distance gaps of kPaced, in units of the median step: a still stretch (h → 0) would make
// the coefficients ~1/h² explode and SCG stiff; a very fast step (h large) would leave it free.
constexpr double kMinPaceGap = 0.25;
constexpr double kMaxPaceGap = 4.0;

class TemporalPrior {
public:
    struct Triple {
        int row[3];      // training rows, in time order
        double coef[3];  // a, b, c
    };

    TemporalPrior() = default;
    // frames: clip frame of each training row (any order); weight λ ≥ 0; clips: each row's clip
    // index (empty: all one clip).
    static TemporalPrior secondDifference(const std::vector<int>& frames, double weight,
                                          const std::vector<int>& clips = {});
    // kPaced: the same segments, with the gap between time-consecutive rows measured as the pose
    // distance ‖Y.row(b) − Y.row(a)‖ over its median across the joined pairs, clamped to
    // [kMinPaceGap, kMaxPaceGap]. Y has one row per frame entry.
    static TemporalPrior posePaced(const std::vector<int>& frames, const Eigen::MatrixXd& Y, double weight,
                                   const std::vector<int>& clips = {});

    bool empty() const { return triples_.empty() || weight_ == 0.0; }
    double weight() const { return weight_; }
    const std::vector<Triple>& triples() const { return triples_; }
    // Rows in time order (the order the Step-8 colouring uses), and each row's position in it.
    const std::vector<int>& timeOrder() const { return order_; }

    // L_smooth(X); if grad is non-null it is resized to X's shape and set to ∂L_smooth/∂X.
    double value(const Eigen::MatrixXd& X, Eigen::MatrixXd* grad = nullptr) const;
    // The part of L_smooth that involves row `row`, with X.row(row) replaced by x (the other rows
    // as in X), and its gradient in x (sized by the callee) when grad is non-null.
    double pointValue(const Eigen::MatrixXd& X, int row, const Eigen::VectorXd& x, Eigen::VectorXd* grad) const;

private:
    // Segments by frame gap; gap(a, b) gives the (positive) spacing of joined rows a → b.
    template <class Gap>
    static TemporalPrior build(const std::vector<int>& frames, const std::vector<int>& clips, double weight, Gap gap);

    double weight_ = 0.0;
    std::vector<Triple> triples_;
    std::vector<std::vector<int>> byRow_;  // triples touching each row
    std::vector<int> order_;
};

}  // namespace mgp::gp
