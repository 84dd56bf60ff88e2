#pragma once
// What the compare ghost shows, and its names in session files and scripts ("none", "plain",
// "model"): the one place the enum and its names meet.
#include <string>

namespace mgp {

// The same targets solved by another solver: none, plain IK, or a second model.
enum class CompareMode { kNone, kPlainIk, kSecondModel };

const char* compareModeName(CompareMode mode);
// False (and `mode` untouched) for anything but the three names.
bool parseCompareMode(const std::string& name, CompareMode& mode);

}  // namespace mgp
