#include "skeleton/clip.h"

#include <cmath>

namespace mgp {

const char* clipFormatName(ClipFormat f) {
    switch (f) {
        case ClipFormat::kAmc: return "amc";
        case ClipFormat::kBvh: return "bvh";
        default: return "synthetic";
    }
}

void unwrapAngles(Eigen::MatrixXd& a) {
    for (Eigen::Index c = 0; c < a.cols(); ++c) {
        double shift = 0.0;
        for (Eigen::Index r = 1; r < a.rows(); ++r) {
            // Compare raw neighbours: the shift accumulates for this frame and every later one.
            const double step = a(r, c) + shift - a(r - 1, c);
            if (step > 180.0) shift -= 360.0 * std::ceil((step - 180.0) / 360.0);
            else if (step < -180.0) shift += 360.0 * std::ceil((-step - 180.0) / 360.0);
            a(r, c) += shift;
        }
    }
}

Eigen::MatrixXd poseMatrix(const Clip& clip) {
    const PoseLayout layout(clip.skeleton);
    Eigen::MatrixXd y(clip.frameCount(), kPoseDofs);
    Eigen::VectorXd row(kPoseDofs);
    for (int t = 0; t < clip.frameCount(); ++t) {
        layout.extract(clip.frames[t], row.data());
        y.row(t) = row.transpose();
    }
    unwrapAngles(y);
    return y;
}

Eigen::MatrixXd rootTranslations(const Clip& clip) {
    Eigen::MatrixXd t(clip.frameCount(), 3);
    for (int i = 0; i < clip.frameCount(); ++i) t.row(i) = clip.frames[i].rootCm.transpose();
    return t;
}

std::vector<int> constantColumns(const Eigen::MatrixXd& y, double tolDeg) {
    std::vector<int> out;
    if (y.rows() == 0) return out;
    for (Eigen::Index c = 0; c < y.cols(); ++c) {
        const double mean = y.col(c).mean();
        const double var = (y.col(c).array() - mean).square().mean();
        if (std::sqrt(var) <= tolDeg) out.push_back(static_cast<int>(c));
    }
    return out;
}

}  // namespace mgp
