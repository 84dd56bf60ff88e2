#include "eval/ppca_density.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

namespace mgp {

PpcaDensity::PpcaDensity(const Eigen::MatrixXd& samples, int q, double varianceFloor) {
    const int n = static_cast<int>(samples.rows()), D = static_cast<int>(samples.cols());
    q = std::clamp(q, 1, std::max(1, D - 1));
    mu_ = samples.colwise().mean().transpose();
    const Eigen::MatrixXd centred = samples.rowwise() - mu_.transpose();
    const Eigen::MatrixXd cov = centred.transpose() * centred / std::max(1, n);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cov);
    const Eigen::VectorXd values = eig.eigenvalues().reverse().cwiseMax(varianceFloor);
    const Eigen::MatrixXd vectors = eig.eigenvectors().rowwise().reverse();
    U_ = vectors.leftCols(q);
    lambda_ = values.head(q);
    sigma2_ = D > q ? std::max(values.tail(D - q).mean(), varianceFloor) : varianceFloor;
    lambda_ = lambda_.cwiseMax(sigma2_);
    const double logDet = lambda_.array().log().sum() + (D - q) * std::log(sigma2_);
    logNorm_ = -0.5 * logDet - 0.5 * D * std::log(2.0 * M_PI);
}

double PpcaDensity::logDensity(const Eigen::VectorXd& y) const {
    const Eigen::VectorXd c = y - mu_;
    const Eigen::VectorXd proj = U_.transpose() * c;
    const double inPlane = (proj.array().square() / lambda_.array()).sum();
    const double offPlane = (c.squaredNorm() - proj.squaredNorm()) / sigma2_;
    return logNorm_ - 0.5 * (inPlane + std::max(0.0, offPlane));
}

double heldOutLogDensityQuantile(const Eigen::MatrixXd& samples, int q, int folds, double quantile) {
    const int n = static_cast<int>(samples.rows());
    folds = std::clamp(folds, 2, std::max(2, n));
    std::vector<double> scores;
    for (int f = 0; f < folds; ++f) {
        const int a = n * f / folds, b = n * (f + 1) / folds;
        Eigen::MatrixXd train(n - (b - a), samples.cols());
        train << samples.topRows(a), samples.bottomRows(n - b);
        const PpcaDensity model(train, q);
        for (int i = a; i < b; ++i) scores.push_back(model.logDensity(samples.row(i).transpose()));
    }
    std::sort(scores.begin(), scores.end());
    const std::size_t idx = std::min(scores.size() - 1, static_cast<std::size_t>(quantile * (scores.size() - 1)));
    return scores[idx];
}

}  // namespace mgp
