#pragma once
// Kernels of the GPLVM (docs/maths.md §3). Both models share this one interface:
//
//   FAS    k(x_i, x_j) = α·exp(−(γ/2)‖x_i − x_j‖²) + η·exp(φ(x_i)·φ(x_j)) + δ_ij/β
//   SGPLVM k(x_i, x_j) = α·exp(−(γ/2)‖x_i − x_j‖²)                        + δ_ij/β
//
// with the safe direction φ(x) = x / sqrt(‖x‖² + ε²), ε = 1e-3 (docs/maths.md §3). δ_ij is
// identity of data indices: the white term is only on the diagonal of gram(); cross() and diagF()
// are the noise-free k_f. Parameters are held as log-parameters ψ = ln θ, in the order
//   FAS: (ln α, ln γ, ln β, ln η)     SGPLVM: (ln α, ln γ, ln β)
// and are clamped to [−36, 36] before exp() (docs/maths.md §3). All code is generic in the
// latent dimension d = X.cols().
#include <Eigen/Core>
#include <string>

namespace mgp::gp {

enum class KernelKind { kFas, kSgplvm };
const char* kernelKindName(KernelKind k);  // "fas" / "sgplvm"
bool parseKernelKind(const std::string& s, KernelKind& out);

constexpr double kAngularEps = 1e-3;  // ε of φ(x)
constexpr double kLogParamBound = 36.0;

enum ParamIndex : int { kAlpha = 0, kGamma = 1, kBeta = 2, kEta = 3 };
int paramCount(KernelKind k);  // 4 (FAS) or 3 (SGPLVM)

// Pairwise quantities over one point set, computed once per objective evaluation
// (docs/maths.md §3):
// r² (M×M), R = exp(−γ r²/2), C = φ_i·φ_j, E = exp(C), φ (M×d), n (M).
struct GramParts {
    Eigen::MatrixXd r2, R, C, E, phi;
    Eigen::VectorXd n;
};

// Scratch storage of gradX (G∘R and G∘E, M×M); only storage is reused, never values.
struct GradXScratch {
    Eigen::MatrixXd H, Q;
};

class Kernel {
public:
    Kernel(KernelKind kind, const Eigen::VectorXd& logParams);

    KernelKind kind() const { return kind_; }
    int paramCount() const { return gp::paramCount(kind_); }
    bool hasEta() const { return kind_ == KernelKind::kFas; }
    const Eigen::VectorXd& logParams() const { return psi_; }  // clamped
    double alpha() const { return alpha_; }
    double gamma() const { return gamma_; }
    double beta() const { return beta_; }
    double eta() const { return eta_; }  // 0 for SGPLVM

    // K over the rows of X (M×M), white noise included.
    Eigen::MatrixXd gram(const Eigen::MatrixXd& X) const;
    // k(x) ∈ R^M, k(x)_j = k_f(x, X_j): no noise term.
    Eigen::VectorXd cross(const Eigen::MatrixXd& X, const Eigen::VectorXd& x) const;
    // k_f(x, x) = α + η·exp(‖φ(x)‖²) (no noise).
    double diagF(const Eigen::VectorXd& x) const;
    Eigen::VectorXd diagFRows(const Eigen::MatrixXd& X) const;

    GramParts parts(const Eigen::MatrixXd& X) const;
    void parts(const Eigen::MatrixXd& X, GramParts& out) const;  // reuses out's storage
    Eigen::MatrixXd gram(const GramParts& p) const;
    Eigen::VectorXd gradLogParams(const GramParts& p, const Eigen::MatrixXd& G) const;
    Eigen::MatrixXd gradX(const Eigen::MatrixXd& X, const GramParts& p, const Eigen::MatrixXd& G) const;
    Eigen::MatrixXd gradX(const Eigen::MatrixXd& X, const GramParts& p, const Eigen::MatrixXd& G,
                          GradXScratch& scratch) const;

    // Σ_ij G_ij ∂K_ij/∂ψ_p for every log-parameter p (G any M×M matrix).
    Eigen::VectorXd gradLogParams(const Eigen::MatrixXd& X, const Eigen::MatrixXd& G) const;
    // ∂/∂X of Σ_ij G_ij K_ij(X) for a SYMMETRIC G (M×d): 2 Σ_j G_ij ∂k(x_i,x_j)/∂x_i, which also
    // covers the diagonal term ∂k(x_i,x_i)/∂x_i (docs/maths.md §3; used by docs/maths.md §4.3).
    Eigen::MatrixXd gradX(const Eigen::MatrixXd& X, const Eigen::MatrixXd& G) const;
    // J = ∂k(x)/∂x (M×d), row j = ∂k_f(x, X_j)/∂x.
    Eigen::MatrixXd crossGradX(const Eigen::MatrixXd& X, const Eigen::VectorXd& x) const;
    // ∂k_f(x, x)/∂x = 2η·exp(‖φ‖²)·ε² x / n(x)⁴.
    Eigen::VectorXd diagGradX(const Eigen::VectorXd& x) const;

    // φ(x) and n(x) = sqrt(‖x‖² + ε²).
    static double norm(const Eigen::VectorXd& x);
    // φ of every row of X: row i is x_i / n(x_i).
    static Eigen::MatrixXd directions(const Eigen::MatrixXd& X);

private:
    KernelKind kind_;
    Eigen::VectorXd psi_;
    double alpha_ = 1, gamma_ = 1, beta_ = 1, eta_ = 0;
};

}  // namespace mgp::gp
