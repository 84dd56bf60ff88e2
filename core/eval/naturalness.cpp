#include "eval/naturalness.h"

#include <algorithm>
#include <cmath>

#include "gp/capture_range.h"
#include "skeleton/forward_kinematics.h"

namespace mgp {

namespace {
constexpr int kDensityComponents = 15;

const char* boneOfEffector(Effector e) {
    switch (e) {
        case Effector::kLHand: return "lwrist";
        case Effector::kRHand: return "rwrist";
        case Effector::kLFoot: return "lfoot";
        case Effector::kRFoot: return "rfoot";
        default: return "head";
    }
}
}  // namespace

Eigen::VectorXd NaturalnessTests::bodyShape(const Skeleton& skeleton, const Eigen::VectorXd& poseDeg) {
    Pose pose;
    pose.anglesDeg.assign(skeleton.jointCount(), Eigen::Vector3d::Zero());
    PoseLayout(skeleton).apply(poseDeg.data(), pose);
    FkState fk;
    forwardKinematics(skeleton, pose, fk);
    const Eigen::Matrix3d unturn = headingRemoval(fk);
    Eigen::VectorXd out = Eigen::VectorXd::Zero(3 * kModelBones);
    for (int b = 0; b < kModelBones; ++b) {
        const int j = skeleton.findBone(modelBoneNames()[b]);
        if (j < 0) continue;
        out.segment<3>(3 * b) = unturn * (boneEndCm(skeleton, fk, j) - fk.jointCm[0]);
    }
    return out;
}

NaturalnessTests::NaturalnessTests(std::vector<ReferenceFrame> frames, Effector excluded) : frames_(std::move(frames)) {
    boneMask_.assign(kModelBones, true);
    for (int b = 0; b < kModelBones; ++b)
        if (std::string(modelBoneNames()[b]) == boneOfEffector(excluded)) boneMask_[b] = false;
    const int n = size();
    shapes_.resize(n, 3 * kModelBones);
    poses_.resize(n, n > 0 ? PoseLayout(frames_[0].clip->skeleton).size() : kAsfPoseDofs);
    // Unwrapped per clip, as the model sees them.
    std::vector<const Clip*> clips;
    for (const auto& f : frames_)
        if (std::find(clips.begin(), clips.end(), f.clip) == clips.end()) clips.push_back(f.clip);
    std::vector<Eigen::MatrixXd> unwrapped;
    for (const Clip* c : clips) unwrapped.push_back(poseMatrix(*c));
    for (int i = 0; i < n; ++i) {
        const auto ci = std::find(clips.begin(), clips.end(), frames_[i].clip) - clips.begin();
        poses_.row(i) = unwrapped[ci].row(frames_[i].frame);
        shapes_.row(i) = bodyShape(frames_[i].clip->skeleton, poses_.row(i).transpose()).transpose();
    }
    qMin_ = poses_.colwise().minCoeff().transpose();
    qMax_ = poses_.colwise().maxCoeff().transpose();
    // τ_NN: 99th percentile of leave-one-clip-out d_NN (single clip: leave out ±10 frames).
    const bool singleGroup = std::all_of(frames_.begin(), frames_.end(),
                                         [&](const ReferenceFrame& f) { return f.group == frames_[0].group; });
    std::vector<double> d(n);
    for (int i = 0; i < n; ++i)
        d[i] = singleGroup ? nearestDistance(shapes_.row(i).transpose(), frames_[i].group, frames_[i].frame - 10,
                                             frames_[i].frame + 10)
                           : nearestDistance(shapes_.row(i).transpose(), frames_[i].group);
    std::sort(d.begin(), d.end());
    tauNN_ = d[std::min<std::size_t>(d.size() - 1, static_cast<std::size_t>(0.99 * (d.size() - 1)))];
    // Density on the columns that move in R.
    for (int k = 0; k < static_cast<int>(qMax_.size()); ++k)
        if (qMax_[k] - qMin_[k] > 1e-6) densityColumns_.push_back(k);
    Eigen::MatrixXd cols(n, densityColumns_.size());
    for (std::size_t c = 0; c < densityColumns_.size(); ++c) cols.col(c) = poses_.col(densityColumns_[c]);
    density_ = std::make_unique<PpcaDensity>(cols, kDensityComponents);
    densityThreshold_ = heldOutLogDensityQuantile(cols, kDensityComponents, 5, 0.01);
}

std::pair<double, double> NaturalnessTests::rangeBounds(int dof) const {
    const double margin =
        std::max(gp::kCaptureRangeMarginDeg, gp::kCaptureRangeMarginFraction * (qMax_[dof] - qMin_[dof]));
    return {qMin_[dof] - margin, qMax_[dof] + margin};
}

double NaturalnessTests::nearestDistance(const Eigen::VectorXd& shape, int skipGroup, int skipFrom, int skipTo) const {
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < size(); ++i) {
        const ReferenceFrame& f = frames_[i];
        if (f.group == skipGroup && (skipTo < skipFrom || (f.frame >= skipFrom && f.frame <= skipTo))) continue;
        double sum = 0.0;
        int count = 0;
        for (int b = 0; b < kModelBones; ++b) {
            if (!boneMask_[b]) continue;
            sum += (shape.segment<3>(3 * b) - shapes_.row(i).segment<3>(3 * b).transpose()).norm();
            ++count;
        }
        best = std::min(best, sum / count);
    }
    return best;
}

NaturalnessVerdict NaturalnessTests::judge(const Skeleton& skeleton, const Eigen::VectorXd& pose,
                                           const Eigen::VectorXd* previous) const {
    NaturalnessVerdict v;
    // The protocol's margin, the one the admission also uses (gp/capture_range.h).
    const gp::RangeCheck check = gp::checkRanges(pose, qMin_, qMax_, nullptr, false);
    v.rangeViolations = check.violations;
    v.worstRangeDof = check.worstDof;
    v.worstRangeExcessDeg = check.worstExcessDeg;
    v.ranges = v.rangeViolations == 0;
    v.dNN = nearestDistance(bodyShape(skeleton, pose));
    v.nearest = v.dNN <= tauNN_;
    Eigen::VectorXd cols(densityColumns_.size());
    for (std::size_t c = 0; c < densityColumns_.size(); ++c) cols[c] = pose[densityColumns_[c]];
    v.logDensity = density_->logDensity(cols);
    v.density = v.logDensity >= densityThreshold_;
    if (previous) {
        Eigen::Index at = 0;
        v.maxStepDeg = (pose - *previous).cwiseAbs().maxCoeff(&at);
        v.maxStepDof = static_cast<int>(at);
    }
    v.continuity = v.maxStepDeg <= 15.0;
    return v;
}

}  // namespace mgp
