#pragma once
// Strict parsing of action and script arguments with the project's parsers (io/text_reader.h):
// the whole token must be the number, so "12abc" is refused with a message that names the
// argument, instead of being read as 12.
#include <string>

namespace mgp::ui {

// Each returns "" or "expected WHAT (an integer), found '12abc'"; `out` is set only on success.
std::string parseIntArg(const std::string& token, const std::string& what, int& out);
std::string parseFloatArg(const std::string& token, const std::string& what, double& out);

}  // namespace mgp::ui
