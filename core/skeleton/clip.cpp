#include "skeleton/clip.h"

#include <cmath>
#include <stdexcept>

namespace mgp {

const char* clipFormatName(ClipFormat f) {
    switch (f) {
        case ClipFormat::kAmc: return "amc";
        case ClipFormat::kBvh: return "bvh";
        case ClipFormat::kGltf: return "gltf";
        case ClipFormat::kSynthetic: break;
    }
    return "synthetic";
}

void appendFrames(Clip& into, const Clip& from, int first, int count) {
    if (first < 0 || count < 0 || first + count > from.frameCount())
        throw std::invalid_argument("expected frames within 1.." + std::to_string(from.frameCount()) + " of " +
                                    from.name);
    if (into.frames.empty() && into.skeleton.joints.empty()) {
        std::vector<Pose> none;
        into = from;
        into.frames.swap(none);
        into.restFrame = from.restFrame && first == 0;  // a slice after frame 0 starts on motion
    } else if (into.skeleton.jointCount() != from.skeleton.jointCount()) {
        throw std::invalid_argument("expected clips of one skeleton, found " + into.name + " and " + from.name);
    }
    into.frames.insert(into.frames.end(), from.frames.begin() + first, from.frames.begin() + first + count);
}

void unwrapAngles(Eigen::MatrixXd& a) {
    for (Eigen::Index c = 0; c < a.cols(); ++c) {
        double shift = 0.0;
        for (Eigen::Index r = 1; r < a.rows(); ++r) {
            // Compare raw neighbours: the shift accumulates for this frame and every later one.
            const double step = a(r, c) + shift - a(r - 1, c);
            if (step > 180.0)
                shift -= 360.0 * std::ceil((step - 180.0) / 360.0);
            else if (step < -180.0)
                shift += 360.0 * std::ceil((-step - 180.0) / 360.0);
            a(r, c) += shift;
        }
    }
}

Eigen::MatrixXd poseMatrix(const Clip& clip) {
    const PoseLayout layout(clip.skeleton);
    Eigen::MatrixXd y(clip.frameCount(), layout.size());
    Eigen::VectorXd row(layout.size());
    for (int t = 0; t < clip.frameCount(); ++t) {
        layout.extract(clip.frames[t], row.data());
        y.row(t) = row.transpose();
    }
    unwrapAngles(y);
    return y;
}

void unwrapClip(Clip& clip) {
    const Eigen::MatrixXd y = poseMatrix(clip);
    const PoseLayout layout(clip.skeleton);
    for (int t = 0; t < clip.frameCount(); ++t) {
        const Eigen::VectorXd row = y.row(t).transpose();
        layout.apply(row.data(), clip.frames[t]);
    }
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
