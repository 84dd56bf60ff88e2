#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace mgp {

namespace {
[[noreturn]] void fail(const std::string& path, const std::string& tmp, int err) {
    if (!tmp.empty()) ::unlink(tmp.c_str());
    throw std::runtime_error(path + ": expected a writable file, found " + std::strerror(err));
}
}  // namespace

void writeFileAtomically(const std::string& path, const std::string& content) {
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail(path, "", errno);
    std::size_t done = 0;
    while (done < content.size()) {
        const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int err = errno;
            ::close(fd);
            fail(path, tmp, err);
        }
        done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0) {
        const int err = errno;
        ::close(fd);
        fail(path, tmp, err);
    }
    if (::close(fd) != 0) fail(path, tmp, errno);
    if (::rename(tmp.c_str(), path.c_str()) != 0) fail(path, tmp, errno);
}

}  // namespace mgp
