#include "gp/kernel.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mgp::gp {

const char* kernelKindName(KernelKind k) { return k == KernelKind::kFas ? "fas" : "sgplvm"; }

bool parseKernelKind(const std::string& s, KernelKind& out) {
    if (s == "fas" || s == "fasgplvm")
        out = KernelKind::kFas;
    else if (s == "sgplvm")
        out = KernelKind::kSgplvm;
    else
        return false;
    return true;
}

int paramCount(KernelKind k) { return k == KernelKind::kFas ? 4 : 3; }

Kernel::Kernel(KernelKind kind, const Eigen::VectorXd& logParams) : kind_(kind) {
    if (logParams.size() != gp::paramCount(kind)) throw std::invalid_argument("Kernel: wrong number of log-parameters");
    psi_ = logParams;
    for (Eigen::Index i = 0; i < psi_.size(); ++i) {
        // A NaN has no place in the box: say so rather than evaluate some other θ
        // (docs/maths.md §3).
        if (std::isnan(psi_[i]))
            throw std::invalid_argument("expected finite kernel log-parameters, found NaN at index " +
                                        std::to_string(i));
        psi_[i] = std::clamp(psi_[i], -kLogParamBound, kLogParamBound);
    }
    alpha_ = std::exp(psi_[kAlpha]);
    gamma_ = std::exp(psi_[kGamma]);
    beta_ = std::exp(psi_[kBeta]);
    eta_ = hasEta() ? std::exp(psi_[kEta]) : 0.0;
}

double Kernel::norm(const Eigen::VectorXd& x) { return std::sqrt(x.squaredNorm() + kAngularEps * kAngularEps); }

namespace {
void directionsAndNorms(const Eigen::MatrixXd& X, Eigen::MatrixXd& phi, Eigen::VectorXd& n);
}  // namespace

Eigen::MatrixXd Kernel::directions(const Eigen::MatrixXd& X) {
    Eigen::MatrixXd phi;
    Eigen::VectorXd n;
    directionsAndNorms(X, phi, n);
    return phi;
}

namespace {

// Row-wise φ and n for a point set.
void directionsAndNorms(const Eigen::MatrixXd& X, Eigen::MatrixXd& phi, Eigen::VectorXd& n) {
    n.resize(X.rows());
    phi.resize(X.rows(), X.cols());
    for (Eigen::Index i = 0; i < X.rows(); ++i) {
        n[i] = std::sqrt(X.row(i).squaredNorm() + kAngularEps * kAngularEps);
        phi.row(i) = X.row(i) / n[i];
    }
}

double sqDist(const Eigen::MatrixXd& X, Eigen::Index i, const Eigen::VectorXd& x) {
    double s = 0.0;
    for (Eigen::Index c = 0; c < X.cols(); ++c) {
        const double t = X(i, c) - x[c];
        s += t * t;
    }
    return s;
}

}  // namespace

GramParts Kernel::parts(const Eigen::MatrixXd& X) const {
    GramParts p;
    parts(X, p);
    return p;
}

void Kernel::parts(const Eigen::MatrixXd& X, GramParts& p) const {
    // The lower triangle, a column at a time with Eigen's vectorised exp (a column's part below
    // the diagonal is contiguous), then mirrored, so every matrix is exactly symmetric.
    const Eigen::Index m = X.rows();
    const double g = -0.5 * gamma_;
    p.r2.resize(m, m);
    p.R.resize(m, m);
    for (Eigen::Index j = 0; j < m; ++j) {
        p.r2(j, j) = 0.0;
        p.R(j, j) = 1.0;
        const Eigen::Index below = m - j - 1;
        auto r2 = p.r2.col(j).tail(below).array();
        r2.setZero();
        for (Eigen::Index c = 0; c < X.cols(); ++c) r2 += (X.col(c).tail(below).array() - X(j, c)).square();
        p.R.col(j).tail(below).array() = (g * r2).exp();
    }
    p.r2.triangularView<Eigen::StrictlyUpper>() = p.r2.transpose();
    p.R.triangularView<Eigen::StrictlyUpper>() = p.R.transpose();
    if (hasEta()) {
        directionsAndNorms(X, p.phi, p.n);
        p.C.resize(m, m);
        p.E.resize(m, m);
        const Eigen::Index d = X.cols();
        for (Eigen::Index j = 0; j < m; ++j) {
            auto c = p.C.col(j).tail(m - j).array();
            c.setZero();
            for (Eigen::Index k = 0; k < d; ++k) c += p.phi.col(k).tail(m - j).array() * p.phi(j, k);
            p.E.col(j).tail(m - j).array() = c.exp();
        }
        p.C.triangularView<Eigen::StrictlyUpper>() = p.C.transpose();
        p.E.triangularView<Eigen::StrictlyUpper>() = p.E.transpose();
    }
}

Eigen::MatrixXd Kernel::gram(const GramParts& p) const {
    Eigen::MatrixXd K = alpha_ * p.R;
    if (hasEta()) K += eta_ * p.E;
    K.diagonal().array() += 1.0 / beta_;
    return K;
}

Eigen::MatrixXd Kernel::gram(const Eigen::MatrixXd& X) const { return gram(parts(X)); }

Eigen::VectorXd Kernel::gradLogParams(const GramParts& p, const Eigen::MatrixXd& G) const {
    Eigen::VectorXd g(paramCount());
    g[kAlpha] = alpha_ * (G.array() * p.R.array()).sum();
    g[kGamma] = -0.5 * alpha_ * gamma_ * (G.array() * p.r2.array() * p.R.array()).sum();
    g[kBeta] = -G.trace() / beta_;
    if (hasEta()) g[kEta] = eta_ * (G.array() * p.E.array()).sum();
    return g;
}

Eigen::VectorXd Kernel::gradLogParams(const Eigen::MatrixXd& X, const Eigen::MatrixXd& G) const {
    return gradLogParams(parts(X), G);
}

Eigen::MatrixXd Kernel::gradX(const Eigen::MatrixXd& X, const GramParts& p, const Eigen::MatrixXd& G) const {
    GradXScratch scratch;
    return gradX(X, p, G, scratch);
}

Eigen::MatrixXd Kernel::gradX(const Eigen::MatrixXd& X, const GramParts& p, const Eigen::MatrixXd& G,
                              GradXScratch& scratch) const {
    // RBF: 2 Σ_j G_ij (−αγ)(x_i − x_j) R_ij = −2αγ (diag(H1) X − H X)_i with H = G∘R.
    Eigen::MatrixXd& H = scratch.H;
    Eigen::MatrixXd& Q = scratch.Q;
    H.resize(G.rows(), G.cols());
    H.array() = G.array() * p.R.array();
    Eigen::MatrixXd out = (-2.0 * alpha_ * gamma_) * (H.rowwise().sum().asDiagonal() * X - H * X);
    if (hasEta()) {
        // Angular: 2 Σ_j G_ij η E_ij (φ_j − C_ij φ_i)/n_i = 2η/n_i ((QΦ)_i − ((Q∘C)1)_i φ_i), Q = G∘E.
        Q.resize(G.rows(), G.cols());
        Q.array() = G.array() * p.E.array();
        const Eigen::VectorXd qc = (Q.array() * p.C.array()).rowwise().sum();
        const Eigen::MatrixXd ang = Q * p.phi - qc.asDiagonal() * p.phi;
        out += (2.0 * eta_) * (p.n.cwiseInverse().asDiagonal() * ang);
    }
    return out;
}

Eigen::MatrixXd Kernel::gradX(const Eigen::MatrixXd& X, const Eigen::MatrixXd& G) const {
    return gradX(X, parts(X), G);
}

Eigen::VectorXd Kernel::cross(const Eigen::MatrixXd& X, const Eigen::VectorXd& x) const {
    Eigen::VectorXd k(X.rows());
    Eigen::VectorXd phiX;
    if (hasEta()) phiX = x / norm(x);
    for (Eigen::Index j = 0; j < X.rows(); ++j) {
        double v = alpha_ * std::exp(-0.5 * gamma_ * sqDist(X, j, x));
        if (hasEta()) {
            const double nj = std::sqrt(X.row(j).squaredNorm() + kAngularEps * kAngularEps);
            v += eta_ * std::exp(X.row(j).dot(phiX) / nj);
        }
        k[j] = v;
    }
    return k;
}

double Kernel::diagF(const Eigen::VectorXd& x) const {
    double v = alpha_;
    if (hasEta()) {
        const double n = norm(x);
        v += eta_ * std::exp(x.squaredNorm() / (n * n));
    }
    return v;
}

Eigen::VectorXd Kernel::diagFRows(const Eigen::MatrixXd& X) const {
    Eigen::VectorXd d(X.rows());
    for (Eigen::Index i = 0; i < X.rows(); ++i) d[i] = diagF(Eigen::VectorXd(X.row(i).transpose()));
    return d;
}

Eigen::MatrixXd Kernel::crossGradX(const Eigen::MatrixXd& X, const Eigen::VectorXd& x) const {
    const Eigen::Index m = X.rows(), d = X.cols();
    Eigen::MatrixXd J(m, d);
    const double nx = norm(x);
    const Eigen::VectorXd phiX = x / nx;
    for (Eigen::Index j = 0; j < m; ++j) {
        const double rbf = -alpha_ * gamma_ * std::exp(-0.5 * gamma_ * sqDist(X, j, x));
        for (Eigen::Index c = 0; c < d; ++c) J(j, c) = rbf * (x[c] - X(j, c));
        if (hasEta()) {
            double nj2 = kAngularEps * kAngularEps, dot = 0.0;
            for (Eigen::Index c = 0; c < d; ++c) {
                nj2 += X(j, c) * X(j, c);
                dot += X(j, c) * phiX[c];
            }
            const double nj = std::sqrt(nj2);
            const double C = dot / nj;  // φ_j·φ(x)
            const double s = eta_ * std::exp(C) / nx;
            for (Eigen::Index c = 0; c < d; ++c) J(j, c) += s * (X(j, c) / nj - C * phiX[c]);
        }
    }
    return J;
}

Eigen::VectorXd Kernel::diagGradX(const Eigen::VectorXd& x) const {
    if (!hasEta()) return Eigen::VectorXd::Zero(x.size());
    const double n = norm(x);
    const double n2 = n * n;
    const double e = std::exp(x.squaredNorm() / n2);
    return (2.0 * eta_ * e * kAngularEps * kAngularEps / (n2 * n2)) * x;
}

}  // namespace mgp::gp
