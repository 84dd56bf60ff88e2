#include "io/channel.h"

#include <algorithm>

namespace mgp {

RotationOrder rotationOrderOf(const std::vector<Channel>& channels, ChannelListing listing) {
    std::vector<int> listed;
    for (const Channel& c : channels)
        if (!c.translation) listed.push_back(c.axis);
    if (listing == ChannelListing::kAppliedFirst) std::reverse(listed.begin(), listed.end());
    for (int a = 0; a < 3; ++a)
        if (std::find(listed.begin(), listed.end(), a) == listed.end()) listed.push_back(a);
    return {listed[0], listed[1], listed[2]};
}

}  // namespace mgp
