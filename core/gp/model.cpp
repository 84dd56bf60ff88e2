#include "gp/model.h"

#include "skeleton/pose_layout.h"

namespace mgp::gp {

Eigen::MatrixXd GpModel::activeYhat() const {
    Eigen::MatrixXd out(active.size(), D());
    for (std::size_t r = 0; r < active.size(); ++r) out.row(r) = Y.row(active[r]) - mu.transpose();
    return out;
}

Eigen::MatrixXd GpModel::activeX() const {
    Eigen::MatrixXd out(active.size(), latentDim());
    for (std::size_t r = 0; r < active.size(); ++r) out.row(r) = X.row(active[r]);
    return out;
}

ActiveSetPosterior GpModel::posterior() const { return ActiveSetPosterior(kernel(), activeX(), activeYhat(), mu, w); }

Eigen::VectorXd GpModel::fullPose(const Eigen::VectorXd& kept) const {
    Eigen::VectorXd full = Eigen::VectorXd::Zero(kPoseDofs);
    for (std::size_t k = 0; k < keptColumns.size(); ++k) full[keptColumns[k]] = kept[k];
    for (std::size_t k = 0; k < constantColumns.size(); ++k) full[constantColumns[k]] = constantValues[k];
    return full;
}

Eigen::VectorXd GpModel::keptPose(const Eigen::VectorXd& full47) const {
    Eigen::VectorXd kept(keptColumns.size());
    for (std::size_t k = 0; k < keptColumns.size(); ++k) kept[k] = full47[keptColumns[k]];
    return kept;
}

}  // namespace mgp::gp
