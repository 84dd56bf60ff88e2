#pragma once
// Atomic file replacement: the content goes to a temporary file in the same folder, is flushed
// to disk (fsync), then renamed over the target. A crash or a full disk never leaves a
// half-written file; the previous file stays intact until the rename.
//
// Fault injection (for the "nothing is lost" tests), read from $MOTIONGP_FAULT on every call:
//   slow-write:<ms>  after the first half of the content is in the temporary file, sleep <ms>
//                    milliseconds, then continue (a test can kill the process mid-save);
//   enospc           after the first half, fail as a full disk would (ENOSPC): the temporary file
//                    is removed and the error reads "... found No space left on device".
// Anything else in the variable is ignored.
//
// A save killed mid-write leaves "<path>.tmp.<pid>" behind (the target itself is untouched). The
// next successful save of the same target removes such leftovers whose process is gone.
#include <string>

namespace mgp {

// Throws std::runtime_error ("PATH: expected a writable file, found <reason>") on failure, after
// removing the temporary file.
void writeFileAtomically(const std::string& path, const std::string& content);

}  // namespace mgp
