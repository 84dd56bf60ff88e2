#pragma once
// AMC (Acclaim motion) reader. Bones are matched by NAME against the ASF; frame numbers may
// start anywhere (124_03 starts at 700) but must be consecutive; every bone with DOFs must
// appear exactly once per frame with exactly its ASF number of values.
#include <string>

#include "io/asf_reader.h"
#include "skeleton/clip.h"

namespace mgp {

Clip readAmc(const std::string& amcPath, const AsfSkeleton& asf);
Clip parseAmc(const std::string& name, std::string text, const AsfSkeleton& asf);

}  // namespace mgp
