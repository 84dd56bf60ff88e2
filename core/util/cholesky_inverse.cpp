#include "util/cholesky_inverse.h"

#include <Eigen/Dense>

namespace mgp {

namespace {

constexpr Eigen::Index kBaseBlock = 32;  // below this, plain dense work on a copy is cheapest

using BaseBlock = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kBaseBlock, kBaseBlock>;

// M = [A 0; B C], split at half its size, and T: a view of the scratch the size of B.
struct Halves {
    Eigen::Block<Eigen::Ref<Eigen::MatrixXd>> A, B, C;
    Eigen::Map<Eigen::MatrixXd> T;
};

Halves halvesOf(Eigen::Ref<Eigen::MatrixXd>& M, Eigen::MatrixXd& scratch) {
    const Eigen::Index h = M.rows() / 2, r = M.rows() - h;
    if (scratch.size() < r * h) scratch.resize(r * h, 1);
    return {M.topLeftCorner(h, h), M.bottomLeftCorner(r, h), M.bottomRightCorner(r, r),
            Eigen::Map<Eigen::MatrixXd>(scratch.data(), r, h)};
}

}  // namespace

void invertLowerTriangularInPlace(Eigen::Ref<Eigen::MatrixXd> L, Eigen::MatrixXd& scratch) {
    const Eigen::Index n = L.rows();
    if (n <= kBaseBlock) {
        BaseBlock X = BaseBlock::Identity(n, n);
        L.triangularView<Eigen::Lower>().solveInPlace(X);
        L.triangularView<Eigen::Lower>() = X;
        return;
    }
    // [A 0; B C]⁻¹ = [A⁻¹ 0; −C⁻¹ B A⁻¹  C⁻¹].
    Halves q = halvesOf(L, scratch);
    invertLowerTriangularInPlace(q.A, scratch);
    q.T.noalias() = q.B * q.A.triangularView<Eigen::Lower>();  // B A⁻¹
    q.C.triangularView<Eigen::Lower>().solveInPlace(q.T);      // C⁻¹ B A⁻¹, C not yet inverted
    q.B = -q.T;
    invertLowerTriangularInPlace(q.C, scratch);
}

void lowerTransposeTimesSelfInPlace(Eigen::Ref<Eigen::MatrixXd> V, Eigen::MatrixXd& scratch) {
    const Eigen::Index n = V.rows();
    if (n <= kBaseBlock) {
        const BaseBlock T = V.triangularView<Eigen::Lower>();
        V.triangularView<Eigen::Lower>() = T.transpose() * T;
        return;
    }
    // V = [A 0; B C]: VᵀV = [AᵀA + BᵀB, (CᵀB)ᵀ; CᵀB, CᵀC].
    Halves q = halvesOf(V, scratch);
    lowerTransposeTimesSelfInPlace(q.A, scratch);
    q.A.selfadjointView<Eigen::Lower>().rankUpdate(q.B.transpose());       // + BᵀB, B still V's
    q.T.noalias() = q.C.transpose().triangularView<Eigen::Upper>() * q.B;  // CᵀB, C still V's
    q.B = q.T;
    lowerTransposeTimesSelfInPlace(q.C, scratch);
}

void choleskyInverseInPlace(Eigen::Ref<Eigen::MatrixXd> L, Eigen::MatrixXd& scratch) {
    invertLowerTriangularInPlace(L, scratch);
    lowerTransposeTimesSelfInPlace(L, scratch);
}

}  // namespace mgp
