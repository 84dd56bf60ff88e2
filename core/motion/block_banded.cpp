#include "motion/block_banded.h"

#include <Eigen/Cholesky>
#include <stdexcept>

namespace mgp {

BlockBandedMatrix::BlockBandedMatrix(int blocks, int blockSize, int bandwidth)
    : n_(blocks), b_(blockSize), w_(bandwidth) {
    if (blocks < 0 || blockSize < 1 || bandwidth < 0)
        throw std::invalid_argument("expected a non-empty block-banded shape");
    blocks_.assign(static_cast<std::size_t>(n_) * (w_ + 1), Eigen::MatrixXd::Zero(b_, b_));
}

void BlockBandedMatrix::setZero() {
    for (auto& m : blocks_) m.setZero();
}

Eigen::Ref<Eigen::MatrixXd> BlockBandedMatrix::block(int i, int j) { return blocks_[index(i, j)]; }
const Eigen::MatrixXd& BlockBandedMatrix::block(int i, int j) const { return blocks_[index(i, j)]; }

Eigen::MatrixXd BlockBandedMatrix::dense() const {
    Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n_ * b_, n_ * b_);
    for (int i = 0; i < n_; ++i)
        for (int j = std::max(0, i - w_); j <= i; ++j) {
            d.block(i * b_, j * b_, b_, b_) = block(i, j);
            if (j != i) d.block(j * b_, i * b_, b_, b_) = block(i, j).transpose();
        }
    // The diagonal blocks are stored whole; keep them symmetric in the dense view.
    return d;
}

bool BlockBandedMatrix::factor(const BlockBandedMatrix& a, double shift, double floor) {
    if (n_ != a.n_ || b_ != a.b_ || w_ != a.w_) {
        n_ = a.n_;
        b_ = a.b_;
        w_ = a.w_;
        blocks_.assign(a.blocks_.size(), Eigen::MatrixXd::Zero(b_, b_));
    }
    s_.resize(b_, b_);
    st_.resize(b_, b_);
    for (int i = 0; i < n_; ++i) {
        for (int j = std::max(0, i - w_); j <= i; ++j) {
            s_ = a.block(i, j);
            if (j == i) s_.diagonal().array() += shift * (s_.diagonal().array().abs() + floor);
            for (int k = std::max(0, i - w_); k < j; ++k) s_.noalias() -= block(i, k) * block(j, k).transpose();
            if (j < i) {
                // L(i,j) = S·L(j,j)⁻ᵀ, i.e. L(j,j)·L(i,j)ᵀ = Sᵀ.
                st_ = s_.transpose();
                block(j, j).triangularView<Eigen::Lower>().solveInPlace(st_);
                block(i, j) = st_.transpose();
            } else {
                llt_.compute(s_);  // reads the lower triangle only
                if (llt_.info() != Eigen::Success) return false;
                block(i, i) = llt_.matrixL();
            }
        }
    }
    return true;
}

Eigen::VectorXd BlockBandedMatrix::solve(const Eigen::VectorXd& rhs) const {
    Eigen::VectorXd x = rhs;
    // Forward: L y = rhs.
    for (int i = 0; i < n_; ++i) {
        auto xi = x.segment(i * b_, b_);
        for (int k = std::max(0, i - w_); k < i; ++k) xi.noalias() -= block(i, k) * x.segment(k * b_, b_);
        block(i, i).triangularView<Eigen::Lower>().solveInPlace(xi);
    }
    // Backward: Lᵀ x = y.
    for (int i = n_ - 1; i >= 0; --i) {
        auto xi = x.segment(i * b_, b_);
        for (int k = i + 1; k <= std::min(n_ - 1, i + w_); ++k)
            xi.noalias() -= block(k, i).transpose() * x.segment(k * b_, b_);
        block(i, i).transpose().triangularView<Eigen::Upper>().solveInPlace(xi);
    }
    return x;
}

}  // namespace mgp
