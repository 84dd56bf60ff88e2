#pragma once
// SHA-256 (FIPS 180-4) of a byte string or a file, as lowercase hex. Used for the model file's
// provenance field only.
#include <string>

namespace mgp::gp {

std::string sha256Hex(const std::string& bytes);
// Throws mgp::ParseError if the file cannot be read.
std::string sha256OfFile(const std::string& path);

}  // namespace mgp::gp
