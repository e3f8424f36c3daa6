// Reading files without surprises, for the image reader and the glTF loader (src/io only): only
// regular files are read, they are opened without blocking (a FIFO or a device named as a file
// never makes a load wait), and the size is known before anything is allocated.
#ifndef TL_IO_FILE_H
#define TL_IO_FILE_H

#include <cstddef>
#include <string>

#include "thinlight/base.h"

namespace tl_io {

// An open regular file and its size; closed by the destructor.
struct regular_file {
    int fd = -1;
    size_t size = 0;
    regular_file() = default;
    ~regular_file();
    regular_file(const regular_file &) = delete;
    regular_file &operator=(const regular_file &) = delete;
};

// Opens `path` for reading (O_NONBLOCK, then fstat): TL_OK, or TL_ERROR_IO with *why ("no such
// file", "not a regular file", ...; the reason only, without the path).
tl_result open_regular(const char *path, regular_file *f, std::string *why);
// Reads exactly f.size bytes into `buf`: TL_OK, or TL_ERROR_IO with *why (a read error, or the
// file changed size while it was read).
tl_result read_all(const regular_file &f, void *buf, std::string *why);

} // namespace tl_io

#endif
