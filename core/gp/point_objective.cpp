#include "gp/point_objective.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "gp/gp_objective.h"
#include "util/parallel_for.h"

namespace mgp::gp {

namespace {
// L_IK from its parts (docs/maths.md §9): E = ‖W(y − f(x))‖², s2 = σ²(x), D pose dimensions.
double likFromResidual(double E, double s2, double D, const Eigen::VectorXd& x) {
    return E / (2.0 * s2) + 0.5 * D * std::log(s2) + 0.5 * x.squaredNorm();
}
}  // namespace

ActiveSetPosterior::ActiveSetPosterior(const Kernel& kernel, const Eigen::MatrixXd& XI, const Eigen::MatrixXd& Yhat,
                                       const Eigen::VectorXd& mu, const Eigen::VectorXd& w)
    : kernel_(kernel), XI_(XI), mu_(mu), w_(w) {
    if (Yhat.rows() != XI.rows() || Yhat.cols() != mu.size() || w.size() != mu.size())
        throw std::invalid_argument("ActiveSetPosterior: inconsistent sizes");
    if (!jitterCholesky(kernel_.gram(XI_), llt_, jitter_))
        throw std::runtime_error("ActiveSetPosterior: the kernel matrix could not be factored");
    Kinv_ = llt_.solve(Eigen::MatrixXd::Identity(XI.rows(), XI.rows()));
    Linv_ = llt_.matrixL().solve(Eigen::MatrixXd::Identity(XI.rows(), XI.rows()));
    B_ = llt_.solve(Yhat);
    phiI_ = Kernel::directions(XI_);
}

void ActiveSetPosterior::crossTerms(const Eigen::VectorXd& x, PointWorkspace& ws) const {
    const Eigen::Index m = XI_.rows(), d = XI_.cols();
    const double alpha = kernel_.alpha(), gamma = kernel_.gamma(), eta = kernel_.eta();
    const bool fas = kernel_.hasEta();
    ws.k.resize(m);
    ws.rbf.resize(m);
    ws.angular.resize(m);
    ws.cosine.resize(m);
    ws.J.resize(m, d);
    ws.phiX.resize(d);
    const double n = std::sqrt(x.squaredNorm() + kAngularEps * kAngularEps);
    ws.phiX = x / n;
    // k and ∂k/∂x (docs/maths.md §3) a latent dimension at a time: XI's columns are contiguous,
    // so the distances, the cosines, their exponentials and J's columns are all vectorised.
    ws.rbf.setZero();
    for (Eigen::Index c = 0; c < d; ++c) ws.rbf.array() += (XI_.col(c).array() - x[c]).square();
    ws.rbf.array() = alpha * (-0.5 * gamma * ws.rbf.array()).exp();
    ws.cosine.setZero();
    ws.angular.setZero();
    if (fas) {
        for (Eigen::Index c = 0; c < d; ++c) ws.cosine.array() += phiI_.col(c).array() * ws.phiX[c];
        ws.angular.array() = eta * ws.cosine.array().exp();
    }
    ws.k = ws.rbf + ws.angular;
    for (Eigen::Index c = 0; c < d; ++c) {
        ws.J.col(c).array() = -gamma * (x[c] - XI_.col(c).array()) * ws.rbf.array();
        if (fas)
            ws.J.col(c).array() += ws.angular.array() * (phiI_.col(c).array() - ws.cosine.array() * ws.phiX[c]) / n;
    }
}

double ActiveSetPosterior::evaluate(const Eigen::VectorXd& x, const Eigen::VectorXd& y, PointWorkspace& ws,
                                    Eigen::VectorXd* gradX, Eigen::VectorXd* gradY) const {
    const Eigen::Index m = XI_.rows();
    const double D = static_cast<double>(mu_.size());
    crossTerms(x, ws);
    ws.v.resize(m);
    ws.a.resize(m);
    // From the Cholesky factor, not K⁻¹: k(x,x) − ‖L⁻¹k‖² keeps σ² accurate where it is small,
    // while k(x,x) − kᵀ(K⁻¹k) lost up to cond(K)·ε of k(x,x) to cancellation
    // (docs/maths.md §9.1). Two triangular products with the stored L⁻¹ cost what one product
    // with K⁻¹ did.
    ws.v.noalias() = Linv_.triangularView<Eigen::Lower>() * ws.k;
    ws.a.noalias() = Linv_.transpose().triangularView<Eigen::Upper>() * ws.v;
    ws.f = mu_;
    ws.f.noalias() += B_.transpose() * ws.k;
    const double noiseFree = diagonalAt(ws) - ws.v.squaredNorm();
    const bool clamped = !(noiseFree > 0.0);
    const double s2 = 1.0 / kernel_.beta() + (clamped ? 0.0 : noiseFree);
    ws.variance = s2;
    ws.clamped = clamped;
    ws.r = w_.cwiseProduct(y - ws.f);
    const double E = ws.r.squaredNorm();
    const double value = likFromResidual(E, s2, D, x);
    gradients(x, ws, gradX, gradY);
    return value;
}

void ActiveSetPosterior::evaluateBatch(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y, PointBatchWorkspace& ws,
                                       Eigen::VectorXd& values, Eigen::MatrixXd& gradX) const {
    const Eigen::Index m = XI_.rows(), d = XI_.cols(), b = X.cols();
    if (X.rows() != d || Y.rows() != mu_.size() || Y.cols() != b)
        throw std::invalid_argument("ActiveSetPosterior::evaluateBatch: expected X d×b and Y D×b");
    const double D = static_cast<double>(mu_.size());
    ws.K.resize(m, b);
    ws.J.resize(m, d * b);
    ws.diagGrad.resize(b);
    ws.diag.resize(b);
    Eigen::VectorXd& x = ws.x;
    for (Eigen::Index j = 0; j < b; ++j) {
        x = X.col(j);
        crossTerms(x, ws.point);
        ws.K.col(j) = ws.point.k;
        ws.J.middleCols(j * d, d) = ws.point.J;
        ws.diag[j] = diagonalAt(ws.point);
        ws.diagGrad[j] = diagonalGradientScale(x, ws.point);
    }
    // The products evaluate() does per point, here for all b points at once (the same σ² from L⁻¹).
    ws.V.noalias() = Linv_.triangularView<Eigen::Lower>() * ws.K;
    ws.A.noalias() = Linv_.transpose().triangularView<Eigen::Upper>() * ws.V;
    ws.F.noalias() = B_.transpose() * ws.K;
    ws.F.colwise() += mu_;
    ws.WR = (Y - ws.F).array().colwise() * w_.array();  // W(y − f)
    values.resize(b);
    Eigen::VectorXd& E = ws.E;
    Eigen::VectorXd& s2 = ws.s2;
    E.resize(b);
    s2.resize(b);
    std::vector<char>& clamped = ws.clamped;
    clamped.resize(static_cast<std::size_t>(b));
    for (Eigen::Index j = 0; j < b; ++j) {
        x = X.col(j);
        E[j] = ws.WR.col(j).squaredNorm();
        const double noiseFree = ws.diag[j] - ws.V.col(j).squaredNorm();
        clamped[static_cast<std::size_t>(j)] = !(noiseFree > 0.0);
        s2[j] = 1.0 / kernel_.beta() + (clamped[static_cast<std::size_t>(j)] ? 0.0 : noiseFree);
        values[j] = likFromResidual(E[j], s2[j], D, x);
    }
    ws.WR.array().colwise() *= w_.array();  // W²(y − f)
    ws.BWR.noalias() = B_ * ws.WR;
    gradX.resize(d, b);
    for (Eigen::Index j = 0; j < b; ++j) {
        x = X.col(j);
        latentGradient(x, ws.J.middleCols(j * d, d), ws.A.col(j), ws.BWR.col(j), E[j], s2[j],
                       clamped[static_cast<std::size_t>(j)] != 0, ws.diagGrad[j], gradX.col(j));
    }
}

double ActiveSetPosterior::diagonalAt(const PointWorkspace& ws) const {
    // k(x,x) = α + η e^{|φ(x)|²} (the angular part only in FAS).
    return kernel_.alpha() + (kernel_.hasEta() ? kernel_.eta() * std::exp(ws.phiX.squaredNorm()) : 0.0);
}

double ActiveSetPosterior::diagonalGradientScale(const Eigen::VectorXd& x, const PointWorkspace& ws) const {
    // ∂k(x,x)/∂x = 2η e^{|φ|²} ε² x / n⁴ (FAS only; the RBF part of k(x,x) is constant).
    if (!kernel_.hasEta()) return 0.0;
    const double n2 = x.squaredNorm() + kAngularEps * kAngularEps;
    return 2.0 * kernel_.eta() * std::exp(ws.phiX.squaredNorm()) * kAngularEps * kAngularEps / (n2 * n2);
}

void ActiveSetPosterior::latentGradient(const Eigen::VectorXd& x, const Eigen::Ref<const Eigen::MatrixXd>& J,
                                        const Eigen::Ref<const Eigen::VectorXd>& a,
                                        const Eigen::Ref<const Eigen::VectorXd>& bwr, double E, double s2, bool clamped,
                                        double diagGrad, Eigen::Ref<Eigen::VectorXd> gradX) const {
    const double D = static_cast<double>(mu_.size());
    const double c = D / (2.0 * s2) - E / (2.0 * s2 * s2);
    for (Eigen::Index i = 0; i < J.cols(); ++i) {
        const double dS2 = clamped ? 0.0 : diagGrad * x[i] - 2.0 * J.col(i).dot(a);
        gradX[i] = -(1.0 / s2) * J.col(i).dot(bwr) + c * dS2 + x[i];
    }
}

void ActiveSetPosterior::gradients(const Eigen::VectorXd& x, PointWorkspace& ws, Eigen::VectorXd* gradX,
                                   Eigen::VectorXd* gradY) const {
    const double s2 = ws.variance;
    if (gradX) {
        ws.wr = w_.cwiseProduct(ws.r);
        ws.bwr.noalias() = B_ * ws.wr;
        latentGradient(x, ws.J, ws.a, ws.bwr, ws.r.squaredNorm(), s2, ws.clamped, diagonalGradientScale(x, ws), *gradX);
    }
    if (gradY) *gradY = w_.cwiseProduct(ws.r) / s2;  // same size: evaluated in place
}

void ActiveSetPosterior::meanVarianceJacobians(const Eigen::VectorXd& x, const PointWorkspace& ws, Eigen::MatrixXd& Jf,
                                               Eigen::VectorXd& dSigma2) const {
    const Eigen::Index d = XI_.cols();
    Jf.resize(mu_.size(), d);
    dSigma2.resize(d);
    // f = μ + Bᵀk  ⇒  ∂f/∂x = Bᵀ ∂k/∂x.
    // One matrix-vector product per latent dimension: as a matrix product, packing Bᵀ (D×M) took
    // longer than the arithmetic (d is 2 or 3).
    for (Eigen::Index c = 0; c < d; ++c) Jf.col(c).noalias() = B_.transpose() * ws.J.col(c);
    if (ws.clamped) {
        dSigma2.setZero();
        return;
    }
    // σ² = 1/β + k(x,x) − kᵀK⁻¹k  ⇒  ∂σ²/∂x = ∂k(x,x)/∂x − 2 (∂k/∂x)ᵀ a.
    dSigma2.noalias() = -2.0 * ws.J.transpose() * ws.a;
    dSigma2 += diagonalGradientScale(x, ws) * x;
}

void ActiveSetPosterior::latentHessian(const Eigen::VectorXd& x, PointWorkspace& ws, const Eigen::MatrixXd& Jf,
                                       const Eigen::VectorXd& dSigma2, Eigen::MatrixXd& H) const {
    // L = E/(2s) + (D/2) ln s + ½‖x‖² with E = ‖r‖², r = W(y − f), s = σ²(x); q_i = ∂_i fᵀ W r,
    // c = D/(2s) − E/(2s²), and k_m the cross-kernel entries:
    //   ∂_ij L = Σ_m u_m ∂_ij k_m + ∂_i fᵀ W² ∂_j f / s + (q_i ∂_j s + ∂_i s q_j)/s²
    //          + (E/s³ − D/(2s²)) ∂_i s ∂_j s + c (∂_ij k(x,x) − 2 ∂_i kᵀ K⁻¹ ∂_j k) + δ_ij,
    //   u = −B W r / s − 2c K⁻¹k   (the last part, and every ∂s, is 0 where the clamp is active).
    const Eigen::Index m = XI_.rows(), d = XI_.cols();
    const double D = static_cast<double>(mu_.size());
    const double s = ws.variance, E = ws.r.squaredNorm();
    const double c = D / (2.0 * s) - E / (2.0 * s * s);
    const double gamma = kernel_.gamma();
    const bool fas = kernel_.hasEta();
    H.resize(d, d);
    H.setZero();
    const double n2 = x.squaredNorm() + kAngularEps * kAngularEps;
    const double n = std::sqrt(n2);
    // Σ_m u_m ∂_ij k_m. RBF: ∂_ij R = (γ² Δ_i Δ_j − γ δ_ij) R with Δ = x − x_m. Angular:
    // ∂_i A = A g_i with g_i = (φ_m,i − C φ_i)/n, C = φ·φ_m, so ∂_ij A = A (g_i g_j + ∂_j g_i),
    // ∂_j g_i = −(g_j φ_i + C (δ_ij/n − x_i x_j/n³))/n − g_i x_j/n².
    for (Eigen::Index j = 0; j < m; ++j) {
        const double u = -ws.bwr[j] / s - (ws.clamped ? 0.0 : 2.0 * c * ws.a[j]);
        const double R = ws.rbf[j];
        for (Eigen::Index a = 0; a < d; ++a)
            for (Eigen::Index b = 0; b <= a; ++b) {
                double h = gamma * gamma * (x[a] - XI_(j, a)) * (x[b] - XI_(j, b)) * R - (a == b ? gamma * R : 0.0);
                if (fas) {
                    const double A = ws.angular[j], C = ws.cosine[j];
                    const double ga = (phiI_(j, a) - C * ws.phiX[a]) / n, gb = (phiI_(j, b) - C * ws.phiX[b]) / n;
                    const double dgab =
                        -(gb * ws.phiX[a] + C * ((a == b ? 1.0 / n : 0.0) - x[a] * x[b] / (n2 * n))) / n -
                        ga * x[b] / n2;
                    h += A * (ga * gb + dgab);
                }
                H(a, b) += u * h;
            }
    }
    // The mean's and the variance's first-derivative terms.
    for (Eigen::Index a = 0; a < d; ++a) {
        const double qa = Jf.col(a).dot(ws.wr);
        for (Eigen::Index b = 0; b <= a; ++b) {
            const double qb = Jf.col(b).dot(ws.wr);
            double h = Jf.col(a).cwiseProduct(w_).dot(Jf.col(b).cwiseProduct(w_)) / s;
            h += (qa * dSigma2[b] + dSigma2[a] * qb) / (s * s) +
                 (E / (s * s * s) - D / (2.0 * s * s)) * dSigma2[a] * dSigma2[b];
            H(a, b) += h;
        }
    }
    if (!ws.clamped) {
        // c (∂_ij k(x,x) − 2 ∂_i kᵀ K⁻¹ ∂_j k); k(x,x) = α + η e^{|φ|²}, |φ|² = |x|²/n²:
        // ∂_i = η e^{|φ|²} 2ε² x_i/n⁴, ∂_ij = η e^{|φ|²} [4ε⁴ x_i x_j/n⁸ + 2ε² (δ_ij/n⁴ − 4 x_i x_j/n⁶)].
        // ∂_i kᵀ K⁻¹ ∂_j k = (L⁻¹∂_i k)·(L⁻¹∂_j k): d triangular products with the stored L⁻¹ (as σ²
        // in evaluate()), half the work of d products with K⁻¹.
        ws.linvJ.resize(m, d);
        for (Eigen::Index b = 0; b < d; ++b)
            ws.linvJ.col(b).noalias() = Linv_.triangularView<Eigen::Lower>() * ws.J.col(b);
        const double eps2 = kAngularEps * kAngularEps;
        const double ephi = fas ? kernel_.eta() * std::exp(ws.phiX.squaredNorm()) : 0.0;
        for (Eigen::Index a = 0; a < d; ++a)
            for (Eigen::Index b = 0; b <= a; ++b) {
                const double diag =
                    ephi * (4.0 * eps2 * eps2 * x[a] * x[b] / (n2 * n2 * n2 * n2) +
                            2.0 * eps2 * ((a == b ? 1.0 : 0.0) / (n2 * n2) - 4.0 * x[a] * x[b] / (n2 * n2 * n2)));
                H(a, b) += c * (diag - 2.0 * ws.linvJ.col(a).dot(ws.linvJ.col(b)));
            }
    }
    for (Eigen::Index a = 0; a < d; ++a) {
        H(a, a) += 1.0;
        for (Eigen::Index b = 0; b < a; ++b) H(b, a) = H(a, b);
    }
}

void ActiveSetPosterior::predict(const Eigen::VectorXd& x, Eigen::VectorXd& mean, double& variance) const {
    const Eigen::VectorXd k = kernel_.cross(XI_, x);
    mean = mu_ + B_.transpose() * k;
    variance = varianceGiven(x, k.dot(Kinv_ * k));
}

double ActiveSetPosterior::varianceGiven(const Eigen::VectorXd& x, double explained) const {
    return 1.0 / kernel_.beta() + std::max(0.0, kernel_.diagF(x) - explained);
}

Eigen::VectorXd ActiveSetPosterior::variances(const Eigen::MatrixXd& points) const {
    constexpr Eigen::Index kBlock = 512;  // points per product: bounds k and K⁻¹k to M × 512 each
    Eigen::VectorXd v(points.rows());
    Eigen::MatrixXd k, a;
    for (Eigen::Index first = 0; first < points.rows(); first += kBlock) {
        const Eigen::Index n = std::min(kBlock, points.rows() - first);
        k.resize(XI_.rows(), n);
        for (Eigen::Index j = 0; j < n; ++j) k.col(j) = kernel_.cross(XI_, points.row(first + j).transpose());
        a.noalias() = Kinv_ * k;
        for (Eigen::Index j = 0; j < n; ++j)
            v[first + j] = varianceGiven(points.row(first + j).transpose(), k.col(j).dot(a.col(j)));
    }
    return v;
}

void ActiveSetPosterior::predictHoldingOut(const Eigen::VectorXd& x, const std::vector<int>& heldOut,
                                           Eigen::VectorXd& mean, double& variance) const {
    if (heldOut.empty()) return predict(x, mean, variance);
    const Eigen::Index b = static_cast<Eigen::Index>(heldOut.size());
    // z = k(x) with the held-out entries zeroed; v = K⁻¹z holds P k_keep (kept rows) and Qᵀ k_keep
    // (held-out rows), so (K_{−B})⁻¹k_keep = v_keep − Q S⁻¹ v_B.
    Eigen::VectorXd z = kernel_.cross(XI_, x);
    for (const int j : heldOut) z[j] = 0.0;
    const Eigen::VectorXd v = Kinv_ * z;
    Eigen::MatrixXd S(b, b);
    Eigen::VectorXd vB(b);
    Eigen::MatrixXd BB(b, B_.cols());
    for (Eigen::Index r = 0; r < b; ++r) {
        vB[r] = v[heldOut[static_cast<std::size_t>(r)]];
        BB.row(r) = B_.row(heldOut[static_cast<std::size_t>(r)]);
        for (Eigen::Index c = 0; c < b; ++c)
            S(r, c) = Kinv_(heldOut[static_cast<std::size_t>(r)], heldOut[static_cast<std::size_t>(c)]);
    }
    const Eigen::VectorXd t = S.llt().solve(vB);  // S⁻¹ v_B (S is a principal block of K⁻¹: SPD)
    // B_keep = (K⁻¹Ŷ)_keep, and (K_{−B})⁻¹Ŷ_keep = B_keep − Q S⁻¹ B_B, so the mean is
    // μ + B_keepᵀ k_keep − B_Bᵀ S⁻¹ Qᵀ k_keep = μ + B_ᵀz − B_Bᵀ t.
    mean = mu_ + B_.transpose() * z - BB.transpose() * t;
    variance = 1.0 / kernel_.beta() + std::max(0.0, kernel_.diagF(x) - z.dot(v) + vB.dot(t));
}

double ActiveSetPosterior::evaluateHoldingOut(const Eigen::VectorXd& x, const Eigen::VectorXd& y,
                                              const std::vector<int>& heldOut, double& variance) const {
    Eigen::VectorXd mean;
    predictHoldingOut(x, heldOut, mean, variance);
    return likFromResidual(w_.cwiseProduct(y - mean).squaredNorm(), variance, static_cast<double>(mu_.size()), x);
}

double ActiveSetPosterior::evaluate(const Eigen::VectorXd& x, const Eigen::VectorXd& y, Eigen::VectorXd* gradX,
                                    Eigen::VectorXd* gradY) const {
    const double D = static_cast<double>(mu_.size());
    const Eigen::VectorXd k = kernel_.cross(XI_, x);
    const Eigen::VectorXd a = Kinv_ * k;
    const Eigen::VectorXd f = mu_ + B_.transpose() * k;
    const double noiseFree = kernel_.diagF(x) - k.dot(a);
    const bool clamped = !(noiseFree > 0.0);
    const double s2 = 1.0 / kernel_.beta() + (clamped ? 0.0 : noiseFree);
    const Eigen::VectorXd r = w_.cwiseProduct(y - f);
    const double E = r.squaredNorm();
    const double value = likFromResidual(E, s2, D, x);
    if (gradX) {
        const Eigen::MatrixXd J = kernel_.crossGradX(XI_, x);
        Eigen::VectorXd dS2 = Eigen::VectorXd::Zero(x.size());
        if (!clamped) dS2 = kernel_.diagGradX(x) - 2.0 * J.transpose() * a;
        *gradX = -(1.0 / s2) * (J.transpose() * (B_ * w_.cwiseProduct(r))) +
                 (D / (2.0 * s2) - E / (2.0 * s2 * s2)) * dS2 + x;
    }
    if (gradY) *gradY = w_.cwiseProduct(r) / s2;
    return value;
}

namespace {

// Points per block: their SCG runs side by side, each round's evaluations one batched evaluation
// (a matrix product runs several times faster per multiply-add than a matrix-vector product).
// Up to 64 columns, fewer where a pass has few points so that it still splits into about 8 blocks
// for the workers to share. The size depends on the number of points only and the blocks are cut
// from `points` in order, so a point's arithmetic never depends on the thread count.
std::size_t pointBlockSize(std::size_t points) { return std::clamp<std::size_t>((points + 7) / 8, 8, 64); }

void optimizePass(const ActiveSetPosterior& model, const Eigen::MatrixXd& Y, const std::vector<int>& points,
                  Eigen::MatrixXd& X, const ScgOptions& options, int threads, const std::atomic<bool>* cancel,
                  const TemporalPrior* prior) {
    if (points.empty()) return;
    const std::size_t blockSize = pointBlockSize(points.size());
    const std::size_t blocks = (points.size() + blockSize - 1) / blockSize;
    threads = std::min<int>(threads, static_cast<int>(blocks));
    std::vector<Eigen::VectorXd> results(points.size());
    std::atomic<std::size_t> next{0};
    auto worker = [&]() {
        // Storage only: a block's fits do not depend on which worker ran it.
        PointBatchWorkspace ws;
        Eigen::MatrixXd Xb, Yb, G;
        Eigen::VectorXd values, x, gp;
        std::vector<ScgMachine> machines;
        std::vector<std::size_t> running;  // indices into the block of the machines still iterating
        for (std::size_t blk = next++; blk < blocks; blk = next++) {
            const std::size_t first = blk * blockSize, last = std::min(points.size(), first + blockSize);
            if (cancel && cancel->load()) {
                for (std::size_t t = first; t < last; ++t) results[t] = X.row(points[t]).transpose();
                continue;
            }
            machines.clear();
            for (std::size_t t = first; t < last; ++t) machines.emplace_back(X.row(points[t]).transpose(), options);
            for (;;) {
                running.clear();
                for (std::size_t k = 0; k < machines.size(); ++k)
                    if (!machines[k].done()) running.push_back(k);
                if (running.empty()) break;
                const Eigen::Index nb = static_cast<Eigen::Index>(running.size());
                Xb.resize(X.cols(), nb);
                Yb.resize(Y.cols(), nb);
                for (Eigen::Index j = 0; j < nb; ++j) {
                    const std::size_t k = running[static_cast<std::size_t>(j)];
                    Xb.col(j) = machines[k].request();
                    Yb.col(j) = Y.row(points[first + k]).transpose();
                }
                model.evaluateBatch(Xb, Yb, ws, values, G);
                for (Eigen::Index j = 0; j < nb; ++j) {
                    const std::size_t k = running[static_cast<std::size_t>(j)];
                    double v = values[j];
                    Eigen::VectorXd& g = machines[k].gradientSlot();
                    g = G.col(j);
                    if (prior) {
                        x = Xb.col(j);
                        v += prior->pointValue(X, points[first + k], x, &gp);
                        g += gp;
                    }
                    machines[k].supply(v);
                }
            }
            for (std::size_t k = 0; k < machines.size(); ++k) {
                const Eigen::VectorXd& r = machines[k].result().x;
                results[first + k] = r.allFinite() ? r : Eigen::VectorXd(X.row(points[first + k]).transpose());
            }
        }
    };
    parallelFor(threads, [&](int) { worker(); });
    for (std::size_t t = 0; t < points.size(); ++t) X.row(points[t]) = results[t].transpose();
}

}  // namespace

void optimizeInactivePoints(const ActiveSetPosterior& model, const Eigen::MatrixXd& Y, const std::vector<int>& points,
                            Eigen::MatrixXd& X, const ScgOptions& options, int threads, const std::atomic<bool>* cancel,
                            const TemporalPrior* prior) {
    if (points.empty()) return;
    threads = resolveWorkers(threads);
    if (!prior || prior->empty()) {
        optimizePass(model, Y, points, X, options, threads, cancel, nullptr);
        return;
    }
    std::vector<int> position(static_cast<std::size_t>(X.rows()), 0);
    const std::vector<int>& order = prior->timeOrder();
    for (std::size_t k = 0; k < order.size() && order[k] < X.rows(); ++k) position[order[k]] = static_cast<int>(k);
    for (int colour = 0; colour < 3; ++colour) {
        std::vector<int> pass;
        for (int i : points)
            if (position[static_cast<std::size_t>(i)] % 3 == colour) pass.push_back(i);
        optimizePass(model, Y, pass, X, options, threads, cancel, prior);
    }
}

}  // namespace mgp::gp
