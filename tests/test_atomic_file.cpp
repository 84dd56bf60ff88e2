// Atomic writes: the target is replaced whole, a failed write leaves the old file intact.
#include <sys/stat.h>
#include <unistd.h>

#include <stdexcept>

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
        CHECK_THROWS(writeFileAtomically(path, "overwrite"));
        ::chmod(dir.c_str(), 0755);
    }
    CHECK(test::readText(path) == "precious");
}
