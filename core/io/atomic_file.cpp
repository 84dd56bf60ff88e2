#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

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
    if (s == "enospc") f.noSpace = true;
    else if (s.compare(0, slow.size(), slow) == 0) f.sleepMs = std::atoll(s.c_str() + slow.size());
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
}

}  // namespace mgp
