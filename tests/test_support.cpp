#include "test_support.h"

#include <fcntl.h>
#include <grp.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <thread>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "util/address_sanitizer.h"

namespace mgp::test {

namespace {
bool exists(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0;
}
}  // namespace

std::string mocap(const std::string& relative) {
    const std::string path = std::string(MOTIONGP_TEST_MOCAP) + "/" + relative;
    REQUIRE_MESSAGE(exists(path),
                    "expected a shipped clip at "
                        << path << ", found none (assets/mocap/README.md lists them; use sharedMocap for the rest)");
    return path;
}

std::string sharedMocapDir() {
    const std::string dir = MOTIONGP_TEST_SHARED_MOCAP;
    return exists(dir + "/asf_amc") ? dir : std::string();
}

std::optional<std::string> sharedMocap(const std::string& relative) {
    const std::string dir = sharedMocapDir();
    if (dir.empty() || !exists(dir + "/" + relative)) return std::nullopt;
    return dir + "/" + relative;
}

std::string scratchDir(const std::string& name) {
    // Per process: ctest runs test cases as parallel processes that must not share folders.
    const std::string dir = std::string(MOTIONGP_TEST_TMP) + "/" + std::to_string(::getpid()) + "/" + name;
    const std::string cmd = "rm -rf '" + dir + "' && mkdir -p '" + dir + "'";
    REQUIRE(std::system(cmd.c_str()) == 0);
    return dir;
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    REQUIRE(out.good());
}

bool bitsEqual(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    return a.rows() == b.rows() && a.cols() == b.cols() &&
           std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

CliLimits hostileLimits() {
    CliLimits l;
    l.timeoutSeconds = 20.0;
    l.addressSpaceBytes = std::size_t(2) << 30;
    return l;
}

namespace {
double steadySeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
int captureCounter = 0;
}  // namespace

Child spawnBounded(const std::vector<std::string>& argv, const CliLimits& limits) {
    REQUIRE(!argv.empty());
    // One capture folder per child, so children can overlap.
    const std::string dir = scratchDir("cli_capture_" + std::to_string(captureCounter++));
    Child c;
    c.outPath = dir + "/stdout.txt";
    c.errPath = dir + "/stderr.txt";
    // Everything the child needs is prepared before fork (no allocation between fork and exec).
    std::vector<char*> cargv;
    for (const std::string& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
    cargv.push_back(nullptr);
    std::vector<std::string> envStrings;
    for (const auto& [k, v] : limits.env) envStrings.push_back(k + "=" + v);
    c.startSeconds = steadySeconds();
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        ::setpgid(0, 0);  // its own process group: a timeout kills whatever it started too
        const int out = ::open(c.outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = ::open(c.errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int in = ::open("/dev/null", O_RDONLY);
        if (out < 0 || err < 0 || in < 0) ::_exit(126);
        ::dup2(in, 0);
        ::dup2(out, 1);
        ::dup2(err, 2);
        // No display: `motiongp` with no verb would open the editor window where DISPLAY is set.
        ::unsetenv("DISPLAY");
        ::unsetenv("WAYLAND_DISPLAY");
        for (std::string& kv : envStrings) ::putenv(kv.data());
        if (limits.addressSpaceBytes > 0) {
#if MGP_ADDRESS_SANITIZER
            // ASan reserves terabytes of shadow address space, so RLIMIT_AS would stop every run:
            // its allocator enforces the same bound instead (a larger single allocation fails,
            // and the process dies once its resident memory exceeds it).
            static std::string asan;
            const char* base = std::getenv("ASAN_OPTIONS");
            const std::size_t mb = limits.addressSpaceBytes >> 20;
            asan = std::string("ASAN_OPTIONS=") + (base ? std::string(base) + ":" : "") +
                   "max_allocation_size_mb=" + std::to_string(mb) + ":hard_rss_limit_mb=" + std::to_string(mb);
            ::putenv(asan.data());
#else
            const rlimit rl{limits.addressSpaceBytes, limits.addressSpaceBytes};
            if (::setrlimit(RLIMIT_AS, &rl) != 0) ::_exit(126);
#endif
        }
        if (limits.dropRoot && ::geteuid() == 0) {
            if (!becomeNobody()) ::_exit(126);
        }
        ::execv(cargv[0], cargv.data());
        ::_exit(127);
    }
    ::setpgid(child, child);  // (also from here, so a kill right after spawn reaches the group)
    c.pid = child;
    return c;
}

CliResult waitBounded(const Child& c, const CliLimits& limits) {
    CliResult r;
    int status = 0;
    while (true) {
        const pid_t w = ::waitpid(c.pid, &status, WNOHANG);
        REQUIRE(w >= 0);
        if (w == c.pid) break;
        if (limits.timeoutSeconds > 0 && steadySeconds() - c.startSeconds > limits.timeoutSeconds) {
            r.timedOut = true;
            ::kill(-c.pid, SIGKILL);
            ::kill(c.pid, SIGKILL);
            REQUIRE(::waitpid(c.pid, &status, 0) == c.pid);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    r.seconds = steadySeconds() - c.startSeconds;
    if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    r.out = readText(c.outPath);
    r.err = readText(c.errPath);
    return r;
}

CliResult runBounded(const std::vector<std::string>& argv, const CliLimits& limits) {
    return waitBounded(spawnBounded(argv, limits), limits);
}

Child spawnCli(const std::vector<std::string>& args, const CliLimits& limits) {
    std::vector<std::string> argv{MOTIONGP_TEST_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    return spawnBounded(argv, limits);
}

CliResult runCliArgs(const std::vector<std::string>& args, const CliLimits& limits) {
    std::vector<std::string> argv{MOTIONGP_TEST_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    return runBounded(argv, limits);
}

bool becomeNobody() { return ::setgroups(0, nullptr) == 0 && ::setgid(65534) == 0 && ::setuid(65534) == 0; }

std::string unreachableAsNobody(const std::vector<std::string>& paths) {
    if (::geteuid() != 0) return "";
    std::vector<std::pair<std::string, int>> wanted{{MOTIONGP_TEST_BINARY, X_OK}};
    for (const std::string& p : paths) wanted.push_back({p, F_OK});
    // The child reports the index of the first unreachable path as its exit code (0: all reached).
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        if (!becomeNobody()) ::_exit(255);
        for (std::size_t i = 0; i < wanted.size(); ++i)
            if (::access(wanted[i].first.c_str(), wanted[i].second) != 0) ::_exit(static_cast<int>(i + 1));
        ::_exit(0);
    }
    int status = 0;
    REQUIRE(::waitpid(pid, &status, 0) == pid);
    REQUIRE(WIFEXITED(status));
    const int code = WEXITSTATUS(status);
    if (code == 0) return "";
    if (code == 255) return "running as root, but could not become nobody (65534)";
    return "running as root, and nobody (65534), which makes file permissions apply, cannot reach " +
           wanted[static_cast<std::size_t>(code - 1)].first + " (a parent folder is private)";
}

CliResult runCli(const std::string& args, const CliLimits& limits) {
    // `exec` so that the shell is replaced by motiongp (the limits and a timeout's kill reach it).
    return runBounded({"/bin/sh", "-c", std::string("exec '") + MOTIONGP_TEST_BINARY + "' " + args}, limits);
}

std::string describe(const CliResult& r) {
    if (r.timedOut) return "timed out after " + std::to_string(r.seconds) + " s";
    if (r.signal != 0) return "killed by signal " + std::to_string(r.signal) + " (" + strsignal(r.signal) + ")";
    return "exit " + std::to_string(r.exitCode) + " after " + std::to_string(r.seconds) + " s";
}

}  // namespace mgp::test
