#include "util/cholesky_inverse.h"

#include <Eigen/Dense>

namespace mgp {

namespace {

constexpr Eigen::Index kBaseBlock = 32;  // below this, plain dense work on a copy is cheapest

using BaseBlock = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kBaseBlock, kBaseBlock>;

// M = [A 0; B C], split at half its size, and T: B's size of the work space (the top level's B is
// the largest, so one allocation before the recursion serves every level).
struct Halves {
    Eigen::Block<Eigen::Ref<Eigen::MatrixXd>> A, B, C;
    Eigen::Map<Eigen::MatrixXd> T;
};

Eigen::Index workSize(Eigen::Index n) { return (n - n / 2) * (n / 2); }

Halves halvesOf(Eigen::Ref<Eigen::MatrixXd>& M, double* work) {
    const Eigen::Index h = M.rows() / 2, r = M.rows() - h;
    return {M.topLeftCorner(h, h), M.bottomLeftCorner(r, h), M.bottomRightCorner(r, r),
            Eigen::Map<Eigen::MatrixXd>(work, r, h)};
}

void invertLower(Eigen::Ref<Eigen::MatrixXd> L, double* work) {
    const Eigen::Index n = L.rows();
    if (n <= kBaseBlock) {
        BaseBlock X = BaseBlock::Identity(n, n);
        L.triangularView<Eigen::Lower>().solveInPlace(X);
        L.triangularView<Eigen::Lower>() = X;
        return;
    }
    // [A 0; B C]⁻¹ = [A⁻¹ 0; −C⁻¹ B A⁻¹  C⁻¹].
    Halves q = halvesOf(L, work);
    invertLower(q.A, work);
    q.T.noalias() = q.B * q.A.triangularView<Eigen::Lower>();  // B A⁻¹
    q.C.triangularView<Eigen::Lower>().solveInPlace(q.T);      // C⁻¹ B A⁻¹, C not yet inverted
    q.B = -q.T;
    invertLower(q.C, work);
}

void lowerGram(Eigen::Ref<Eigen::MatrixXd> V, double* work) {
    const Eigen::Index n = V.rows();
    if (n <= kBaseBlock) {
        const BaseBlock T = V.triangularView<Eigen::Lower>();
        V.triangularView<Eigen::Lower>() = T.transpose() * T;
        return;
    }
    // V = [A 0; B C]: VᵀV = [AᵀA + BᵀB, (CᵀB)ᵀ; CᵀB, CᵀC].
    Halves q = halvesOf(V, work);
    lowerGram(q.A, work);
    q.A.selfadjointView<Eigen::Lower>().rankUpdate(q.B.transpose());       // + BᵀB, B still V's
    q.T.noalias() = q.C.transpose().triangularView<Eigen::Upper>() * q.B;  // CᵀB, C still V's
    q.B = q.T;
    lowerGram(q.C, work);
}

double* workFor(Eigen::Index n, Eigen::MatrixXd& scratch) {
    if (scratch.size() < workSize(n)) scratch.resize(workSize(n), 1);
    return scratch.data();
}

}  // namespace

void invertLowerTriangularInPlace(Eigen::Ref<Eigen::MatrixXd> L, Eigen::MatrixXd& scratch) {
    invertLower(L, workFor(L.rows(), scratch));
}

void lowerTransposeTimesSelfInPlace(Eigen::Ref<Eigen::MatrixXd> V, Eigen::MatrixXd& scratch) {
    lowerGram(V, workFor(V.rows(), scratch));
}

void choleskyInverseInPlace(Eigen::Ref<Eigen::MatrixXd> L, Eigen::MatrixXd& scratch) {
    invertLowerTriangularInPlace(L, scratch);
    lowerTransposeTimesSelfInPlace(L, scratch);
}

}  // namespace mgp
