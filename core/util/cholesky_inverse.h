#pragma once
// K⁻¹ from K's Cholesky factor L (K = LLᵀ) in (1/3 + 1/3) m³ flops, as LAPACK's trtri and
// lauum do it (docs/maths.md §4.4): a triangular inverse L⁻¹, then the lower triangle of L⁻ᵀL⁻¹.
// Solving LX = I and multiplying L⁻ᵀ by the dense L⁻¹ cost m³ flops each, since neither knows that
// half of its right-hand side is zero. Both steps recurse on halves down to 32×32 blocks, so every
// flop is in Eigen's blocked triangular products and rank updates.
//
// Each function reads and writes the lower triangle only; the strict upper triangle is left as it
// was. `scratch` is storage only (resized, never read before written), reused across calls.
#include <Eigen/Core>

namespace mgp {

// L (lower triangle, non-zero diagonal) ← L⁻¹.
void invertLowerTriangularInPlace(Eigen::Ref<Eigen::MatrixXd> L, Eigen::MatrixXd& scratch);

// V (lower triangle) ← the lower triangle of VᵀV.
void lowerTransposeTimesSelfInPlace(Eigen::Ref<Eigen::MatrixXd> V, Eigen::MatrixXd& scratch);

// L (lower triangle of a Cholesky factor) ← the lower triangle of (LLᵀ)⁻¹ = L⁻ᵀL⁻¹.
void choleskyInverseInPlace(Eigen::Ref<Eigen::MatrixXd> L, Eigen::MatrixXd& scratch);

}  // namespace mgp
