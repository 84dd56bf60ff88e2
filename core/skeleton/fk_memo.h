#pragma once
// Forward kinematics remembered per slot (e.g. a clip frame): the editor draws the same frames'
// trails on every UI frame, and a pose changes far less often than the screen. A slot is computed
// again only when its pose is not identical (posesIdentical) to the one it was computed from.
#include <unordered_map>

#include "skeleton/forward_kinematics.h"

namespace mgp {

class FkMemo {
public:
    // The FK of `pose` on `skeleton`, from slot `slot` when that slot last saw exactly this pose.
    // Valid until the next call. Call forget() when the skeleton changes.
    const FkState& of(const Skeleton& skeleton, const Pose& pose, long slot);
    void forget() { slots_.clear(); }
    long computed() const { return computed_; }  // FK evaluations so far (tests)

    static constexpr std::size_t kMaxSlots = 4096;  // then it starts afresh (a few tens of MB at most)

private:
    struct Entry {
        Pose pose;
        FkState fk;
    };
    std::unordered_map<long, Entry> slots_;
    long computed_ = 0;
};

}  // namespace mgp
