#include "eval/inbetween_metrics.h"

#include <Eigen/Geometry>
#include <unsupported/Eigen/FFT>

#include <cmath>
#include <complex>
#include <stdexcept>

#include "skeleton/forward_kinematics.h"

namespace mgp {

WindowGlobals windowGlobals(const Skeleton& skeleton, const std::vector<Pose>& frames) {
    if (frames.size() < 3)
        throw std::invalid_argument("expected a window of key, transition and key, found " +
                                    std::to_string(frames.size()) + " frames");
    const int J = skeleton.jointCount();
    const int T = static_cast<int>(frames.size()) - 2;
    FkState fk;
    forwardKinematics(skeleton, frames.front(), fk);
    const Eigen::Matrix3d heading = headingRemoval(fk);
    const Eigen::Vector3d origin(fk.jointCm[0].x(), 0.0, fk.jointCm[0].z());
    // Quaternion signs: w ≥ 0 on the key, then each frame on the side of the one before.
    std::vector<Eigen::Quaterniond> previous(J);
    for (int j = 0; j < J; ++j) {
        previous[j] = Eigen::Quaterniond(heading * fk.global[j]);
        if (previous[j].w() < 0.0) previous[j].coeffs() *= -1.0;
    }
    WindowGlobals w;
    w.positions.resize(T, 3 * J);
    w.quaternions.resize(T, 4 * J);
    for (int t = 0; t < T; ++t) {
        forwardKinematics(skeleton, frames[static_cast<std::size_t>(t + 1)], fk);
        for (int j = 0; j < J; ++j) {
            w.positions.row(t).segment<3>(3 * j) = (heading * (fk.jointCm[j] - origin)).transpose();
            Eigen::Quaterniond q(heading * fk.global[j]);
            if (q.coeffs().dot(previous[j].coeffs()) < 0.0) q.coeffs() *= -1.0;
            previous[j] = q;
            w.quaternions.row(t).segment<4>(4 * j) << q.w(), q.x(), q.y(), q.z();
        }
    }
    return w;
}

Eigen::VectorXd positionSpread(const std::vector<WindowGlobals>& windows) {
    if (windows.empty())
        throw std::invalid_argument("expected at least one window for the position spread, found none");
    const Eigen::Index C = windows.front().positions.cols();
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(C), sumSq = Eigen::VectorXd::Zero(C);
    double n = 0.0;
    for (const WindowGlobals& w : windows) {
        if (w.positions.cols() != C) throw std::invalid_argument("expected windows of one skeleton");
        sum += w.positions.colwise().sum().transpose();
        sumSq += w.positions.array().square().colwise().sum().matrix().transpose();
        n += static_cast<double>(w.positions.rows());
    }
    Eigen::VectorXd sd(C);
    for (Eigen::Index c = 0; c < C; ++c) {
        const double mean = sum[c] / n;
        const double var = std::max(0.0, sumSq[c] / n - mean * mean);
        sd[c] = var > 1e-12 ? std::sqrt(var) : 1.0;
    }
    return sd;
}

NpssTerms npssTerms(const Eigen::MatrixXd& truth, const Eigen::MatrixXd& prediction) {
    if (truth.rows() != prediction.rows() || truth.cols() != prediction.cols())
        throw std::invalid_argument("expected truth and prediction of one shape");
    const std::size_t T = static_cast<std::size_t>(truth.rows());
    Eigen::FFT<double> fft;
    std::vector<double> in(T);
    std::vector<std::complex<double>> out;
    // Squared real parts of the DFT of one channel (LaFAN1 takes np.real of the coefficients).
    auto power = [&](const Eigen::MatrixXd& m, Eigen::Index c, Eigen::VectorXd& p) {
        for (std::size_t t = 0; t < T; ++t) in[t] = m(static_cast<Eigen::Index>(t), c);
        fft.fwd(out, in);
        p.resize(static_cast<Eigen::Index>(T));
        for (std::size_t t = 0; t < T; ++t) p[static_cast<Eigen::Index>(t)] = out[t].real() * out[t].real();
    };
    NpssTerms terms;
    Eigen::VectorXd pt, pp;
    for (Eigen::Index c = 0; c < truth.cols(); ++c) {
        power(truth, c, pt);
        power(prediction, c, pp);
        const double wt = pt.sum(), wp = pp.sum();
        if (!(wt > 0.0)) continue;
        double cdfT = 0.0, cdfP = 0.0, emd = 0.0;
        for (Eigen::Index t = 0; t < pt.size(); ++t) {
            cdfT += pt[t] / wt;
            cdfP += wp > 0.0 ? pp[t] / wp : 0.0;
            emd += std::abs(cdfP - cdfT);
        }
        terms.weightedEmd += wt * emd;
        terms.weight += wt;
    }
    return terms;
}

void InbetweenScore::add(const WindowGlobals& truth, const WindowGlobals& prediction,
                         const Eigen::VectorXd& positionSd) {
    if (truth.positions.rows() != prediction.positions.rows() || truth.positions.cols() != positionSd.size() ||
        prediction.positions.cols() != positionSd.size() || truth.quaternions.cols() != prediction.quaternions.cols())
        throw std::invalid_argument("expected truth and prediction windows of one shape and skeleton");
    for (Eigen::Index t = 0; t < truth.positions.rows(); ++t) {
        l2pSum_ +=
            ((truth.positions.row(t) - prediction.positions.row(t)).transpose().cwiseQuotient(positionSd)).norm();
        l2qSum_ += (truth.quaternions.row(t) - prediction.quaternions.row(t)).norm();
    }
    frames_ += static_cast<int>(truth.positions.rows());
    const NpssTerms n = npssTerms(truth.quaternions, prediction.quaternions);
    npssWeighted_ += n.weightedEmd;
    npssWeight_ += n.weight;
}

double InbetweenScore::l2p() const { return frames_ > 0 ? l2pSum_ / frames_ : 0.0; }
double InbetweenScore::l2q() const { return frames_ > 0 ? l2qSum_ / frames_ : 0.0; }
double InbetweenScore::npss() const { return npssWeight_ > 0.0 ? npssWeighted_ / npssWeight_ : 0.0; }

}  // namespace mgp
