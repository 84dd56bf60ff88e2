#pragma once
// ASF (Acclaim skeleton) reader. Lengths are converted to cm with `:units length L`
// (1 file unit = 2.54 / L cm; CMU: L = 0.45 → 5.6444 cm). Bones keep their ASF names as roles.
#include <string>
#include <vector>

#include "io/channel.h"
#include "skeleton/skeleton.h"

namespace mgp {

struct AsfSkeleton {
    std::string path;
    Skeleton skeleton;                           // root + every ASF bone, hierarchy order
    std::vector<std::vector<Channel>> channels;  // per joint, in AMC value order
    double cmPerUnit = 2.54;
    bool anglesInRadians = false;
    int channelCount() const;
};

// Throws ParseError ("file:line: expected ..., found ...") on any malformed input.
AsfSkeleton readAsf(const std::string& path);
AsfSkeleton parseAsf(const std::string& name, std::string text);

}  // namespace mgp
