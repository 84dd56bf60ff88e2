#pragma once
// Loads a clip by extension: .amc (with its ASF: --skel, else SS.asf beside SS_TT.amc) or .bvh.
#include <string>

#include "skeleton/clip.h"

namespace mgp {

// The ASF an AMC uses when none is given: "<dir>/35_01.amc" → "<dir>/35.asf".
std::string defaultAsfFor(const std::string& amcPath);
// Throws ParseError with file:line context on any problem.
Clip loadClip(const std::string& path, const std::string& skeletonPath = "");

}  // namespace mgp
