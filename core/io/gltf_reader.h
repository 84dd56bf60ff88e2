#pragma once
// glTF 2.0 import of a skinned animation (.glb or .gltf), so that our exports are not
// write-only: `motiongp info` and `fk` read them back (docs/export.md).
//
// The joints are the first skin's, in parent-before-child order; each becomes a joint with
// rotation order ZYX and no ASF axis frame (C = I), its offset = the node's rest translation in
// cm. Per frame, a joint's angles are the Euler ZYX decomposition of its animated local rotation
// (its rest rotation when no channel animates it); the root's position is its animated
// translation. The frame rate is the asset's `extras.fps` when present, else the key spacing;
// `extras.rest_frame` says that frame 1 is a converter's rest pose, as for the BVH it came from.
// Our exports' node extras give back each joint's ASF bone role and bone tail, so effectors
// resolve; a foreign file's joints have neither.
//
// Supported: LINEAR or STEP keys on one shared time line (every channel keyed at the same
// times), float outputs, no scale other than 1, translation animated on the root joint only.
// Anything else is a ParseError naming what was expected and what was found.
#include <string>

#include "skeleton/clip.h"

namespace mgp {

Clip readGltfClip(const std::string& path);

}  // namespace mgp
