#pragma once
// Loads a clip by extension: .amc (with its ASF: --skel, else SS.asf beside SS_TT.amc), .bvh, or
// .glb/.gltf (a skinned animation, io/gltf_reader.h).
#include <string>

#include "skeleton/clip.h"

namespace mgp {

// Whether loadClip reads this path (by its extension: .amc, .bvh, .glb, .gltf, any case).
bool isClipPath(const std::string& path);
// The ASF an AMC uses when none is given: "<dir>/35_01.amc" → "<dir>/35.asf".
std::string defaultAsfFor(const std::string& amcPath);
// Throws ParseError with file:line context on any problem.
Clip loadClip(const std::string& path, const std::string& skeletonPath = "");

}  // namespace mgp
