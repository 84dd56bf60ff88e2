#include "edit/path_session.h"

#include <algorithm>

#include "motion/foot_contacts.h"
#include "motion/motion_edit.h"

namespace mgp {

PathSession::PathSession(const Clip& clip, std::function<void()> onChange)
    : clip_(clip), onChange_(std::move(onChange)) {}

void PathSession::reset() {
    path_.reset();
    trajectoryEffector_ = -1;
}

const std::vector<Eigen::Vector3d>& PathSession::capturedTrajectory(Effector e) const {
    if (trajectoryEffector_ != static_cast<int>(e)) {
        trajectory_ = effectorTrajectory(clip_, e);
        if (trajectory_.empty()) trajectory_.assign(clip_.frameCount(), Eigen::Vector3d::Zero());  // no such effector
        trajectoryEffector_ = static_cast<int>(e);
    }
    return trajectory_;
}

std::string PathSession::begin(Effector e, int frame) {
    PathEdit p;
    p.effector = e;
    p.keyFrames = defaultPathKeys(frame, clip_.frameCount());
    p.keyOffsetsCm.assign(p.keyFrames.size(), Eigen::Vector3d::Zero());
    return set(std::move(p));
}

std::string PathSession::set(PathEdit p) {
    if (clip_.frameCount() <= 0) return "no clip is open";
    if (!clip_.skeleton.hasEffector(p.effector)) return std::string("this skeleton has no ") + effectorName(p.effector);
    if (std::string problem = validatePathKeys(p.keyFrames, clip_.frameCount()); !problem.empty()) return problem;
    if (p.keyOffsetsCm.size() != p.keyFrames.size())
        return "expected one offset per key (" + std::to_string(p.keyFrames.size()) + "), found " +
               std::to_string(p.keyOffsetsCm.size());
    for (const Eigen::Vector3d& o : p.keyOffsetsCm)
        if (!o.allFinite()) return "expected finite key offsets, found NaN or Inf";
    path_ = std::move(p);
    changed();
    return "";
}

void PathSession::end() {
    if (path_) changed();
    path_.reset();
}

std::string PathSession::setKeyFrames(std::vector<int> keyFrames) {
    if (!path_) return "no path is being edited";
    PathEdit p = *path_;
    p.keyFrames = std::move(keyFrames);
    p.keyOffsetsCm.assign(p.keyFrames.size(), Eigen::Vector3d::Zero());
    for (std::size_t i = 0; i < p.keyFrames.size(); ++i) {
        const auto it = std::find(path_->keyFrames.begin(), path_->keyFrames.end(), p.keyFrames[i]);
        if (it != path_->keyFrames.end()) p.keyOffsetsCm[i] = path_->keyOffsetsCm[it - path_->keyFrames.begin()];
    }
    return set(std::move(p));
}

std::string PathSession::setKeyOffset(int key, const Eigen::Vector3d& offsetCm) {
    if (!path_) return "no path is being edited";
    if (key < 0 || key >= static_cast<int>(path_->keyFrames.size()))
        return "expected a key in 1.." + std::to_string(path_->keyFrames.size()) + ", found " + std::to_string(key + 1);
    if (!offsetCm.allFinite()) return "expected a finite offset, found NaN or Inf";
    path_->keyOffsetsCm[key] = offsetCm;
    changed();
    return "";
}

std::string PathSession::setKeyPosition(int key, const Eigen::Vector3d& positionCm) {
    if (!path_ || key < 0 || key >= static_cast<int>(path_->keyFrames.size())) return setKeyOffset(key, positionCm);
    return setKeyOffset(key, positionCm - capturedTrajectory(path_->effector)[path_->keyFrames[key]]);
}

void PathSession::setMode(PathMode mode) {
    if (!path_ || path_->mode == mode) return;
    path_->mode = mode;
    changed();
}

Eigen::Vector3d PathSession::keyPosition(int key) const {
    return capturedTrajectory(path_->effector)[path_->keyFrames[key]] + path_->keyOffsetsCm[key];
}

std::vector<Eigen::Vector3d> PathSession::targets() const {
    if (!path_) return {};
    return editTargetPath(capturedTrajectory(path_->effector), path_->keyFrames, path_->keyOffsetsCm, path_->mode);
}

std::vector<Eigen::Vector3d> PathSession::captured() const {
    if (!path_) return {};
    const std::vector<Eigen::Vector3d>& c = capturedTrajectory(path_->effector);
    return {c.begin() + path_->keyFrames.front(), c.begin() + path_->keyFrames.back() + 1};
}

}  // namespace mgp
