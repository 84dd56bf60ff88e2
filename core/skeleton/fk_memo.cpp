// Forward kinematics remembered per slot (fk_memo.h).
#include "skeleton/fk_memo.h"

#include "skeleton/pose_layout.h"

namespace mgp {

const FkState& FkMemo::of(const Skeleton& skeleton, const Pose& pose, long slot) {
    if (slots_.size() >= kMaxSlots && slots_.find(slot) == slots_.end()) slots_.clear();
    auto [it, added] = slots_.try_emplace(slot);
    Entry& e = it->second;
    if (added || !posesIdentical(e.pose, pose)) {
        e.pose = pose;
        forwardKinematics(skeleton, pose, e.fk);
        ++computed_;
    }
    return e.fk;
}

}  // namespace mgp
