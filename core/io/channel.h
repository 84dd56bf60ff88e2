#pragma once
// One animated value of a mocap file: a translation or a rotation about x, y or z.
#include <vector>

#include "skeleton/rotation.h"

namespace mgp {

struct Channel {
    bool translation = false;
    int axis = kAxisX;
};

// How a file's listing of rotation channels maps to a matrix product. ASF/AMC lists the axis
// applied first ("rx ry rz" = Rz·Ry·Rx); BVH lists the outermost matrix first ("Zrotation
// Xrotation Yrotation" = Rz·Rx·Ry).
enum class ChannelListing { kAppliedFirst, kOutermostFirst };

// The joint's RotationOrder (outermost first) from its channels; axes the file does not animate
// are completed in x, y, z order (their angle is 0, so where they go does not matter).
RotationOrder rotationOrderOf(const std::vector<Channel>& channels, ChannelListing listing);

}  // namespace mgp
