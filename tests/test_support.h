#pragma once
// Shared helpers for the unit tests: where the mocap folder is, scratch files, running the CLI.
#include <doctest/doctest.h>

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "test_paths.h"

namespace mgp::test {

// A clip shipped with the repository (assets/mocap, always there). Fails the calling test if the
// file is not one of the shipped ones: tests that need more use sharedMocap.
std::string mocap(const std::string& relative);
// A file of the full CMU set (../shared/mocap beside the checkout, as the long runs read it), or
// nullopt when that folder or file is absent: the caller then skips (MGP_SKIP, skip.h).
std::optional<std::string> sharedMocap(const std::string& relative);
// The full set's folder ("" when absent).
std::string sharedMocapDir();
// A fresh scratch directory under the build tree, private to this test process.
std::string scratchDir(const std::string& name);
void writeText(const std::string& path, const std::string& text);
std::string readText(const std::string& path);
// Same shape and the same bits in every entry (no tolerance: for "reproduces exactly" checks).
bool bitsEqual(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);

// |p(t−1) − 2 p(t) + p(t+1)| in cm, p(s) = positionAt(s) an effector's position on frame s: where a
// one-frame jump of the effector shows.
template <class PositionAt>
double positionSecondDifferenceCm(const PositionAt& positionAt, int t) {
    return (positionAt(t - 1) - 2.0 * positionAt(t) + positionAt(t + 1)).norm();
}

struct CliResult {
    int exitCode = -1;      // -1 unless the process exited normally
    int signal = 0;         // the signal that ended it (0: it exited)
    bool timedOut = false;  // killed (SIGKILL) after CliLimits::timeoutSeconds
    double seconds = 0.0;   // wall time
    std::string out;        // stdout
    std::string err;        // stderr
};

// Bounds for one child process, applied in the forked child before exec (so a bad input cannot
// hang the test run, eat the machine's memory or, as root, read a chmod-000 file).
struct CliLimits {
    double timeoutSeconds = 0.0;                           // > 0: SIGKILL the child's process group after this long
    std::size_t addressSpaceBytes = 0;                     // > 0: setrlimit(RLIMIT_AS): a huge allocation fails
    bool dropRoot = false;                                 // as root: setgid/setuid(65534) (nobody) before exec
    std::vector<std::pair<std::string, std::string>> env;  // extra environment variables
};
// The bounds of the hostile-input table: 20 s wall clock, 2 GiB address space.
CliLimits hostileLimits();
// In a forked child of root: become nobody (65534) with no supplementary groups, so that file
// permissions apply. Only async-signal-safe calls (it runs between fork and exec). False if it failed.
bool becomeNobody();
// Why a child dropped to nobody (CliLimits::dropRoot) could not run the motiongp binary or reach
// one of `paths` ("" when it can, or when this process is not root and drops nothing). As root in
// a private folder (a home of mode 0700, a mktemp -d), nobody cannot even reach the binary.
std::string unreachableAsNobody(const std::vector<std::string>& paths);

// Runs the motiongp binary with the given argument string (shell-quoted by the caller).
CliResult runCli(const std::string& args, const CliLimits& limits = {});
// Runs the motiongp binary with these arguments, no shell involved.
CliResult runCliArgs(const std::vector<std::string>& args, const CliLimits& limits = {});
// Runs any program (argv[0] is its path) under the limits; stdout and stderr are captured.
CliResult runBounded(const std::vector<std::string>& argv, const CliLimits& limits);

// The same in two halves, for a test that acts on the child while it runs (e.g. SIGKILL mid-save).
struct Child {
    int pid = -1;  // also the child's process group
    std::string outPath, errPath;
    double startSeconds = 0.0;  // steady clock
};
Child spawnBounded(const std::vector<std::string>& argv, const CliLimits& limits);
Child spawnCli(const std::vector<std::string>& args, const CliLimits& limits);
// Waits for the child (killing it after limits.timeoutSeconds from its start) and collects it.
CliResult waitBounded(const Child& child, const CliLimits& limits);
// "exit 2", "signal 11", "timed out after 20 s": for failure messages.
std::string describe(const CliResult& r);

}  // namespace mgp::test
