#include "io/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>
#include <vector>

namespace mgp {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& tmp, int err) {
    if (!tmp.empty()) ::unlink(tmp.c_str());
    throw std::runtime_error(path + ": expected a writable file, found " + std::strerror(err));
}

// $MOTIONGP_FAULT, parsed once per write (see the header).
struct Fault {
    long long sleepMs = 0;
    bool noSpace = false;
};

Fault faultFromEnvironment() {
    Fault f;
    const char* v = std::getenv("MOTIONGP_FAULT");
    if (!v) return f;
    const std::string s(v), slow = "slow-write:";
    if (s == "enospc")
        f.noSpace = true;
    else if (s.compare(0, slow.size(), slow) == 0)
        f.sleepMs = std::atoll(s.c_str() + slow.size());
    return f;
}

// Writes all of [data, data + size) or returns the errno of the failure (0 on success).
int writeAll(int fd, const char* data, std::size_t size) {
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = ::write(fd, data + done, size - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        done += static_cast<std::size_t>(n);
    }
    return 0;
}

// After a successful save: removes "<target>.tmp.<pid>" files that a killed save of the SAME
// target left behind, but only those whose process no longer exists (kill(pid, 0) says ESRCH),
// so a save in progress in another live process is never touched. Best effort: errors ignored.
void removeStaleTemporaries(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
    const std::string prefix = (slash == std::string::npos ? path : path.substr(slash + 1)) + ".tmp.";
    DIR* d = ::opendir(dir.c_str());
    if (!d) return;
    std::vector<std::string> stale;
    while (const dirent* e = ::readdir(d)) {
        const std::string name = e->d_name;
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string digits = name.substr(prefix.size());
        if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
        const long pid = std::atol(digits.c_str());
        if (pid <= 0 || pid == static_cast<long>(::getpid())) continue;
        if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) stale.push_back(name);
    }
    ::closedir(d);
    for (const std::string& name : stale) ::unlink((dir + "/" + name).c_str());
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& content) {
    const Fault fault = faultFromEnvironment();
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail(path, "", errno);
    const std::size_t half = content.size() / 2;
    int err = writeAll(fd, content.data(), half);
    if (err == 0 && fault.noSpace) err = ENOSPC;
    if (err == 0 && fault.sleepMs > 0) std::this_thread::sleep_for(std::chrono::milliseconds(fault.sleepMs));
    if (err == 0) err = writeAll(fd, content.data() + half, content.size() - half);
    if (err == 0 && ::fsync(fd) != 0) err = errno;
    if (err != 0) {
        ::close(fd);
        fail(path, tmp, err);
    }
    if (::close(fd) != 0) fail(path, tmp, errno);
    if (::rename(tmp.c_str(), path.c_str()) != 0) fail(path, tmp, errno);
    removeStaleTemporaries(path);
}

}  // namespace mgp
