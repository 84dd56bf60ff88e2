#pragma once
// BVH reader: hierarchy with per-joint channel orders, End Sites, mixed CRLF/LF, `Frame Time`.
// Joints are mapped onto ASF bone roles by name (io/bvh_conventions.h); every data row is kept.
// Position channels are accepted on the root only.
#include <string>

#include "skeleton/clip.h"

namespace mgp {

Clip readBvh(const std::string& path);
Clip parseBvh(const std::string& name, std::string text);

}  // namespace mgp
