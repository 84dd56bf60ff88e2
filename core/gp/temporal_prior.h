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
// ranges are never tied together. The prior only adds to the objectives of Steps 6 and 8
// (core/gp/trainer.h); with LatentPrior::kNone nothing changes (the paper's model).
#include <Eigen/Core>
#include <string>
#include <vector>

namespace mgp::gp {

enum class LatentPrior { kNone, kSmooth };
const char* latentPriorName(LatentPrior p);  // "none" / "smooth"
bool parseLatentPrior(const std::string& s, LatentPrior& out);

class TemporalPrior {
public:
    struct Triple {
        int row[3];      // training rows, in time order
        double coef[3];  // a, b, c
    };

    TemporalPrior() = default;
    // frames: clip frame of each training row (any order); weight λ ≥ 0.
    static TemporalPrior secondDifference(const std::vector<int>& frames, double weight);

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
    double weight_ = 0.0;
    std::vector<Triple> triples_;
    std::vector<std::vector<int>> byRow_;  // triples touching each row
    std::vector<int> order_;
};

}  // namespace mgp::gp
