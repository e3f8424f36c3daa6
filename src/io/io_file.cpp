// Regular files only, opened without blocking (io_file.h).
#include "io_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace tl_io {

regular_file::~regular_file()
{
    if (fd >= 0) close(fd);
}

tl_result open_regular(const char *path, regular_file *f, std::string *why)
{
    // O_NONBLOCK: opening a FIFO with no writer returns at once instead of waiting for one.
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        *why = errno == ENOENT ? "no such file" : std::strerror(errno);
        return TL_ERROR_IO;
    }
    struct stat st;
    bool stat_ok = fstat(fd, &st) == 0;
    if (!stat_ok || !S_ISREG(st.st_mode)) {
        *why = !stat_ok ? std::strerror(errno) : S_ISDIR(st.st_mode) ? "a directory, not a file" : "not a regular file";
        close(fd);
        return TL_ERROR_IO;
    }
    // Reads of a regular file never return EAGAIN; blocking mode keeps read_all simple anyway.
    int flags = fcntl(fd, F_GETFL);
    if (flags >= 0) fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    f->fd = fd;
    f->size = st.st_size > 0 ? (size_t)st.st_size : 0;
    return TL_OK;
}

tl_result read_all(const regular_file &f, void *buf, std::string *why)
{
    unsigned char *p = static_cast<unsigned char *>(buf);
    size_t done = 0;
    while (done < f.size) {
        ssize_t n = read(f.fd, p + done, f.size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            *why = n < 0 ? std::strerror(errno) : "the file shrank while it was read";
            return TL_ERROR_IO;
        }
        done += (size_t)n;
    }
    return TL_OK;
}

} // namespace tl_io
