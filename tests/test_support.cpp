#include "test_support.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace mgp::test {

bool haveMocap() {
    struct stat st {};
    return ::stat((std::string(MOTIONGP_TEST_MOCAP) + "/asf_amc").c_str(), &st) == 0;
}

std::string mocap(const std::string& relative) {
    REQUIRE_MESSAGE(haveMocap(), "the CMU mocap folder is missing: expected it at "
                                     << MOTIONGP_TEST_MOCAP << " (../shared/mocap beside the checkout)");
    return std::string(MOTIONGP_TEST_MOCAP) + "/" + relative;
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

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

CliResult runCli(const std::string& args) {
    const std::string dir = scratchDir("cli_capture");
    const std::string errPath = dir + "/stderr.txt";
    // No display: `motiongp` with no verb would open the editor window where DISPLAY is set.
    const std::string cmd = std::string("env -u DISPLAY -u WAYLAND_DISPLAY '") + MOTIONGP_TEST_BINARY + "' " + args + " 2>'" + errPath + "'";
    CliResult r;
    FILE* pipe = ::popen(cmd.c_str(), "r");
    REQUIRE(pipe != nullptr);
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) r.out.append(buf, n);
    const int status = ::pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.err = readText(errPath);
    return r;
}

}  // namespace mgp::test
