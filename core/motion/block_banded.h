#pragma once
// A symmetric positive definite matrix of n×n square blocks (each b×b) with block bandwidth w:
// block (i, j) is zero when |i − j| > w. The span solver's Gauss–Newton matrix has this shape
// (one block per frame, second differences couple frames up to two apart), and its Cholesky
// factor keeps it: L(i, j) is zero for i − j > w, so the factorisation costs O(n·w²·b³), not
// O((n·b)³).
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <vector>

namespace mgp {

class BlockBandedMatrix {
public:
    BlockBandedMatrix() = default;
    BlockBandedMatrix(int blocks, int blockSize, int bandwidth);
    void setZero();
    int blocks() const { return n_; }
    int blockSize() const { return b_; }
    int bandwidth() const { return w_; }
    // Block (i, j) of the lower triangle: 0 ≤ i − j ≤ w.
    Eigen::Ref<Eigen::MatrixXd> block(int i, int j);
    const Eigen::MatrixXd& block(int i, int j) const;
    // The dense matrix (tests).
    Eigen::MatrixXd dense() const;

    // In-place block Cholesky A = L Lᵀ with `shift` added to the diagonal first (scaled by the
    // diagonal's own magnitude: A_kk += shift·(A_kk + floor)). Returns false when A is not
    // positive definite (the factor is then unusable).
    bool factor(const BlockBandedMatrix& a, double shift, double floor);
    // Solves (L Lᵀ) x = rhs after a successful factor().
    Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;

private:
    int index(int i, int j) const { return i * (w_ + 1) + (i - j); }
    int n_ = 0, b_ = 0, w_ = 0;
    std::vector<Eigen::MatrixXd> blocks_;  // lower band, row-major by block row
    Eigen::MatrixXd s_, st_;               // factor() scratch
    Eigen::LLT<Eigen::MatrixXd> llt_;
};

}  // namespace mgp
