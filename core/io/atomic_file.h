#pragma once
// Atomic file replacement: the content goes to a temporary file in the same folder, is flushed
// to disk (fsync), then renamed over the target. A crash or a full disk never leaves a
// half-written file; the previous file stays intact until the rename.
#include <string>

namespace mgp {

// Throws std::runtime_error ("PATH: expected a writable file, found <reason>") on failure, after
// removing the temporary file.
void writeFileAtomically(const std::string& path, const std::string& content);

}  // namespace mgp
