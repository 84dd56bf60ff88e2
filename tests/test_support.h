#pragma once
// Shared helpers for the unit tests: where the mocap folder is, scratch files, running the CLI.
#include <doctest/doctest.h>

#include <string>

namespace mgp::test {

// ../shared/mocap beside the checkout (CI has it too). Fails the calling test if it is missing.
std::string mocap(const std::string& relative);
bool haveMocap();
// A fresh scratch directory under the build tree, private to this test process.
std::string scratchDir(const std::string& name);
void writeText(const std::string& path, const std::string& text);
std::string readText(const std::string& path);

struct CliResult {
    int exitCode = -1;
    std::string out;  // stdout
    std::string err;  // stderr
};
// Runs the motiongp binary with the given argument string (shell-quoted by the caller).
CliResult runCli(const std::string& args);

}  // namespace mgp::test
