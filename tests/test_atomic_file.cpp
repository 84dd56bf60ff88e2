// Atomic writes: the target is replaced whole, a failed write leaves the old file intact.
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "io/atomic_file.h"
#include "test_support.h"

using namespace mgp;

TEST_CASE("writeFileAtomically replaces the file and leaves no temporary behind") {
    const std::string dir = test::scratchDir("atomic");
    const std::string path = dir + "/a.txt";
    writeFileAtomically(path, "first");
    CHECK(test::readText(path) == "first");
    writeFileAtomically(path, "second, longer");
    CHECK(test::readText(path) == "second, longer");
    const auto r = std::system(("ls '" + dir + "' | grep -c tmp > /dev/null").c_str());
    CHECK(r != 0);  // grep found no temporary file
}

TEST_CASE("a write into a missing or read-only folder fails clearly and keeps the old file") {
    const std::string dir = test::scratchDir("atomic_fail");
    CHECK_THROWS_WITH(writeFileAtomically(dir + "/no/such/dir/x.txt", "x"),
                      (dir + "/no/such/dir/x.txt: expected a writable file, found No such file or directory").c_str());
    const std::string path = dir + "/keep.txt";
    writeFileAtomically(path, "precious");
    if (::geteuid() != 0) {  // root ignores directory permissions
        ::chmod(dir.c_str(), 0555);
        CHECK_THROWS_WITH(writeFileAtomically(path, "overwrite"),
                          (path + ": expected a writable file, found Permission denied").c_str());
        ::chmod(dir.c_str(), 0755);
    }
    CHECK(test::readText(path) == "precious");
}

namespace {

// Files in `dir` other than `keep`.
int strayFiles(const std::string& dir, const std::string& keep) {
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) n += e.path().filename() != keep;
    return n;
}

}  // namespace

TEST_CASE("a save killed half-way (MOTIONGP_FAULT=slow-write) leaves the old file byte-identical") {
    const std::string dir = test::scratchDir("atomic_kill");
    const std::string path = dir + "/session.mgsession";
    std::string old;
    for (int i = 0; i < 20000; ++i) old += "old line " + std::to_string(i) + "\n";
    writeFileAtomically(path, old);
    const std::string big(8u << 20, 'n');
    ::setenv("MOTIONGP_FAULT", "slow-write:3000", 1);
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {  // only async-safe-ish work here, then _exit: no doctest in the child
        try {
            writeFileAtomically(path, big);
        } catch (...) {
            ::_exit(2);
        }
        ::_exit(0);
    }
    ::unsetenv("MOTIONGP_FAULT");
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    REQUIRE(::kill(child, SIGKILL) == 0);
    int status = 0;
    REQUIRE(::waitpid(child, &status, 0) == child);
    CHECK(WIFSIGNALED(status));
    CHECK(test::readText(path) == old);
    // The child's half-written temporary is all that is left of the interrupted save.
    CHECK(std::filesystem::file_size(path + ".tmp." + std::to_string(child)) == big.size() / 2);
}

TEST_CASE("a full disk (MOTIONGP_FAULT=enospc) fails clearly, keeps the old file, leaves no temporary") {
    const std::string dir = test::scratchDir("atomic_enospc");
    const std::string path = dir + "/keep.txt";
    writeFileAtomically(path, "precious");
    ::setenv("MOTIONGP_FAULT", "enospc", 1);
    CHECK_THROWS_WITH_AS(writeFileAtomically(path, std::string(1 << 16, 'x')),
                         (path + ": expected a writable file, found No space left on device").c_str(),
                         std::runtime_error);
    ::unsetenv("MOTIONGP_FAULT");
    CHECK(test::readText(path) == "precious");
    CHECK(strayFiles(dir, "keep.txt") == 0);
    writeFileAtomically(path, "after");  // the variable is read on every call
    CHECK(test::readText(path) == "after");
}
