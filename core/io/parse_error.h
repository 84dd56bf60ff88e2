#pragma once
// ParseError: the one exception type thrown at I/O boundaries. Its message always reads
// "FILE:LINE: expected WHAT, found WHAT" (or "FILE: ..." when no line applies), so a user can
// find the problem. Nothing inside the frame loop throws; callers catch this at the boundary.
#include <stdexcept>
#include <string>

namespace mgp {

class ParseError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Builds "file:line: expected <expected>, found <found>" (line 0 = no line number).
std::string describeParseProblem(const std::string& file, int line, const std::string& expected,
                                 const std::string& found);

[[noreturn]] void throwParseError(const std::string& file, int line, const std::string& expected,
                                  const std::string& found);

}  // namespace mgp
