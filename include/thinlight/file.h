/**
 * @file thinlight/file.h
 * @brief Whole-or-absent file output: the one writer behind tl_image_write and every output of
 * the tools.
 *
 * In every build of thinlight (libthinlight-codec and libthinlight, with or without
 * THINLIGHT_WITH_IO); POSIX systems only (elsewhere both calls return TL_ERROR_UNSUPPORTED).
 * What is guaranteed (docs/outputs.md):
 * - On success `path` holds exactly the bytes given, flushed to the disk (fsync) before they
 *   replace anything. On failure `path` is as it was (its old bytes, or absent) and nothing is
 *   left beside it: every write, fsync, close, link and rename is checked.
 * - The bytes go first to a file with no name (Linux O_TMPFILE), which is given a name in the same
 *   folder and renamed over `path` only once it is whole; a process killed while writing leaves
 *   nothing. Only between that link and the rename (two system calls) would a kill leave the
 *   temporary name `PATH.tmpPID-N` (holding the whole new file). Where the file system has no
 *   O_TMPFILE (or the file cannot be linked), the bytes go to that temporary name from the start,
 *   and a kill mid-write leaves it behind. The next tl_file_write of `PATH` removes such names
 *   whose process no longer runs (a regular file only; a live process's name is left alone).
 * - `path` may be absent or a regular file. Anything else is refused with TL_ERROR_IO and nothing
 *   is touched: a directory, FIFO, socket or device (`/dev/null` included), and a symbolic link,
 *   which is not followed (replacing the link would lose it, writing through it would let a link
 *   choose which file gets replaced). A replaced file keeps its permission bits where the file
 *   system allows; a new one gets 0666 less the umask. The owner is the writer's.
 * - `-` is a file name like any other to the C library, but never to thinlight: it is refused
 *   with TL_ERROR_INVALID_ARGUMENT (standard output cannot be replaced whole or not at all);
 *   write `./-` for a file of that name.
 * - After the rename the folder is flushed too; a failure there is not reported, as the new file
 *   is already in place.
 */
#ifndef THINLIGHT_FILE_H
#define THINLIGHT_FILE_H

#include "thinlight/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Options of tl_file_write and tl_file_check_writable; NULL or zeroed means the defaults. */
typedef struct tl_file_write_desc {
    tl_logger logger; /**< receives the error line on failure ("PATH: reason"); zeroed: silent */
} tl_file_write_desc;

/**
 * Replaces `path` with the `size` bytes at `data` (NULL with size 0: an empty file), whole or not
 * at all (see the file comment). Returns TL_OK, TL_ERROR_INVALID_ARGUMENT (NULL or empty path,
 * `-`, NULL data with a size), TL_ERROR_IO (the folder is missing or not writable, `path` is not
 * a regular file, or a write, fsync, close, link or rename failed: a full disk, a quota) or
 * TL_ERROR_UNSUPPORTED (not a POSIX system), with one line to desc->logger on failure.
 */
TL_API tl_result tl_file_write(const char *path, const void *data, size_t size, const tl_file_write_desc *desc);

/**
 * Whether tl_file_write could write `path` now, checked without touching it, for tools that
 * check their outputs before minutes of work: the same refusals as tl_file_write, and a file can
 * be created in the folder (an unnamed one, or a temporary name removed at once). A disk that
 * fills up later is only found by the write itself. Results as tl_file_write.
 */
TL_API tl_result tl_file_check_writable(const char *path, const tl_file_write_desc *desc);

#ifdef __cplusplus
}
#endif
#endif
