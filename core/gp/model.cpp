#include "gp/model.h"

#include <cstdlib>
#include <stdexcept>
#include <utility>

#include "skeleton/clip_match.h"
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
    Eigen::VectorXd full =
        Eigen::VectorXd::Zero(static_cast<Eigen::Index>(keptColumns.size() + constantColumns.size()));
    for (std::size_t k = 0; k < keptColumns.size(); ++k) full[keptColumns[k]] = kept[k];
    for (std::size_t k = 0; k < constantColumns.size(); ++k) full[constantColumns[k]] = constantValues[k];
    return full;
}

Eigen::VectorXd GpModel::keptPose(const Eigen::VectorXd& full) const {
    Eigen::VectorXd kept(keptColumns.size());
    for (std::size_t k = 0; k < keptColumns.size(); ++k) kept[k] = full[keptColumns[k]];
    return kept;
}

int GpModel::findClip(const std::string& name) const {
    for (int i = 0; i < clipCount(); ++i)
        if (clipName(i) == name) return i;
    return -1;
}

std::string GpModel::clipNames() const {
    std::string out;
    for (int i = 0; i < clipCount(); ++i) out += (i ? ", " : "") + clipName(i);
    return out;
}

int GpModel::primaryRowNearest(int frame) const {
    int nearest = -1;
    for (int r = 0; r < static_cast<int>(trainingFrames.size()); ++r) {
        if (rowClip(r) != 0) continue;
        const int gap = std::abs(trainingFrames[static_cast<std::size_t>(r)] - frame);
        if (nearest < 0 || gap < std::abs(trainingFrames[static_cast<std::size_t>(nearest)] - frame)) nearest = r;
    }
    return nearest < 0 ? 0 : nearest;
}

std::vector<int> GpModel::rowsOfClip(int c) const {
    std::vector<int> rows;
    for (int r = 0; r < N(); ++r)
        if (rowClip(r) == c) rows.push_back(r);
    return rows;
}

std::vector<Eigen::MatrixXd> GpModel::clipPoseMatrices() const {
    std::vector<Eigen::MatrixXd> poses;
    for (int c = 0; c < clipCount(); ++c) poses.push_back(poseMatrix(clipAt(c)));
    return poses;
}

int findCapture(const GpModel& model, const Clip& open, std::string* difference) {
    for (int i = 0; i < model.clipCount(); ++i)
        if (sameCapture(open, model.clipAt(i), i == 0 ? difference : nullptr)) return i;
    return -1;
}

GpModel withPrimaryClip(GpModel model, int index) {
    if (index < 0 || index >= model.clipCount())
        throw std::out_of_range("withPrimaryClip: expected a clip index in 0.." +
                                std::to_string(model.clipCount() - 1) + ", found " + std::to_string(index));
    if (index == 0) return model;
    SourceClip& other = model.moreClips[static_cast<std::size_t>(index - 1)];
    std::swap(model.clip, other.clip);
    std::swap(model.sourceFile, other.file);
    std::swap(model.sourceSha256, other.sha256);
    for (int& c : model.trainingClips) c = c == 0 ? index : c == index ? 0 : c;
    return model;
}

}  // namespace mgp::gp
