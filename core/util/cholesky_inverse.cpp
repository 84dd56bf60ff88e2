#include "util/cholesky_inverse.h"

#include <Eigen/Dense>

namespace mgp {

namespace {

constexpr Eigen::Index kBaseBlock = 32;  // below this, plain dense work on a copy is cheapest

// A (rows×cols) view of the scratch's first rows·cols doubles.
Eigen::Map<Eigen::MatrixXd> scratchBlock(Eigen::MatrixXd& scratch, Eigen::Index rows, Eigen::Index cols) {
    if (scratch.size() < rows * cols) scratch.resize(rows * cols, 1);
    return Eigen::Map<Eigen::MatrixXd>(scratch.data(), rows, cols);
}

}  // namespace

void invertLowerTriangularInPlace(Eigen::Ref<Eigen::MatrixXd> L, Eigen::MatrixXd& scratch) {
    const Eigen::Index n = L.rows();
    if (n <= kBaseBlock) {
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kBaseBlock, kBaseBlock> X(n, n);
        X.setIdentity();
        L.triangularView<Eigen::Lower>().solveInPlace(X);
        L.triangularView<Eigen::Lower>() = X;
        return;
    }
    // [A 0; B C]⁻¹ = [A⁻¹ 0; −C⁻¹ B A⁻¹  C⁻¹].
    const Eigen::Index h = n / 2, r = n - h;
    auto A = L.topLeftCorner(h, h);
    auto B = L.bottomLeftCorner(r, h);
    auto C = L.bottomRightCorner(r, r);
    invertLowerTriangularInPlace(A, scratch);
    {
        Eigen::Map<Eigen::MatrixXd> T = scratchBlock(scratch, r, h);
        T.noalias() = B * A.triangularView<Eigen::Lower>();  // B A⁻¹
        C.triangularView<Eigen::Lower>().solveInPlace(T);    // C⁻¹ B A⁻¹, C not yet inverted
        B = -T;
    }
    invertLowerTriangularInPlace(C, scratch);
}

void lowerTransposeTimesSelfInPlace(Eigen::Ref<Eigen::MatrixXd> V, Eigen::MatrixXd& scratch) {
    const Eigen::Index n = V.rows();
    if (n <= kBaseBlock) {
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kBaseBlock, kBaseBlock> T(n, n);
        T = V.triangularView<Eigen::Lower>();
        V.triangularView<Eigen::Lower>() = T.transpose() * T;
        return;
    }
    // V = [A 0; B C]: VᵀV = [AᵀA + BᵀB, (CᵀB)ᵀ; CᵀB, CᵀC].
    const Eigen::Index h = n / 2, r = n - h;
    auto A = V.topLeftCorner(h, h);
    auto B = V.bottomLeftCorner(r, h);
    auto C = V.bottomRightCorner(r, r);
    lowerTransposeTimesSelfInPlace(A, scratch);
    A.selfadjointView<Eigen::Lower>().rankUpdate(B.transpose());  // + BᵀB, B still V's
    {
        Eigen::Map<Eigen::MatrixXd> T = scratchBlock(scratch, r, h);
        T.noalias() = C.transpose().triangularView<Eigen::Upper>() * B;  // CᵀB, C still V's
        B = T;
    }
    lowerTransposeTimesSelfInPlace(C, scratch);
}

void choleskyInverseInPlace(Eigen::Ref<Eigen::MatrixXd> L, Eigen::MatrixXd& scratch) {
    invertLowerTriangularInPlace(L, scratch);
    lowerTransposeTimesSelfInPlace(L, scratch);
}

}  // namespace mgp
