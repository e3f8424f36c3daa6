/* Whole-or-absent file output (thinlight/file.h): the bytes go to an unnamed file in the target's
 * folder (O_TMPFILE), are flushed, linked under a temporary name and renamed over the target;
 * without O_TMPFILE the temporary name is there from the start. Every call that can fail is
 * checked, and a failure removes what was made. No allocation: names live on the stack. */
#define _GNU_SOURCE /* O_TMPFILE, AT_EMPTY_PATH */

#include "thinlight/file.h"

#include "core/log.h"

#if defined(__unix__) || defined(__APPLE__)

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* One output being written. */
typedef struct tl__out {
    const char *path;
    const tl_logger *logger;
    char dir[PATH_MAX];       /* the folder of `path` ("." when it names none) */
    char tmp[PATH_MAX + 64];  /* the temporary name while one exists, else "" */
    int fd;                   /* the file being written, or -1 */
    int unnamed;              /* fd is an O_TMPFILE file, not yet linked */
    int replace;              /* path is a regular file now */
    mode_t mode;              /* its permission bits */
} tl__out;

/* The process ID in `name` when it is a temporary name of `base` ("BASE.tmpPID-N"), else 0. */
static long tl__temp_pid(const char *name, const char *base, size_t len)
{
    if (strncmp(name, base, len) != 0 || strncmp(name + len, ".tmp", 4) != 0) return 0;
    const char *digits = name + len + 4;
    char *end = NULL, *last = NULL;
    long pid = strtol(digits, &end, 10);
    if (end == digits || *end != '-' || end[1] < '0' || end[1] > '9') return 0;
    (void)strtol(end + 1, &last, 10);
    return *last ? 0 : pid;
}

/* Removes the temporary names of `path` that a process which no longer runs left (killed between
 * its link and its rename, or mid-write without O_TMPFILE): the next writer of a path cleans up
 * after the one before. A live process's name, and anything not a regular file, is left alone. */
static void tl__out_reclaim(const tl__out *o)
{
    const char *slash = strrchr(o->path, '/');
    const char *base = slash ? slash + 1 : o->path;
    size_t len = strlen(base);
    DIR *d = opendir(o->dir);
    if (!d) return;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        long pid = tl__temp_pid(e->d_name, base, len);
        struct stat st;
        if (pid <= 0 || pid == (long)getpid() || (pid_t)pid != pid) continue;
        if (kill((pid_t)pid, 0) == 0 || errno != ESRCH) continue;
        if (fstatat(dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(st.st_mode))
            (void)unlinkat(dirfd(d), e->d_name, 0);
    }
    closedir(d);
}

static tl_result tl__out_fail(tl__out *o, const char *what, int err)
{
    if (o->fd >= 0) close(o->fd); /* its error changes nothing now */
    o->fd = -1;
    if (o->tmp[0]) unlink(o->tmp);
    o->tmp[0] = '\0';
    return tl__logger_fail(o->logger, TL_ERROR_IO, "%s: %s: %s", o->path, what, strerror(err));
}

static const char *tl__file_kind(mode_t m)
{
    if (S_ISDIR(m)) return "a directory";
    if (S_ISLNK(m)) return "a symbolic link (never followed)";
    if (S_ISFIFO(m)) return "a FIFO";
    if (S_ISCHR(m)) return "a character device";
    if (S_ISBLK(m)) return "a block device";
    if (S_ISSOCK(m)) return "a socket";
    return "something else";
}

/* What `path` is now: absent or a regular file, else refused. */
static tl_result tl__out_begin(tl__out *o, const char *path, const tl_file_write_desc *desc)
{
    static const tl_file_write_desc none = {{0, 0}};
    o->fd = -1;
    o->tmp[0] = '\0';
    o->unnamed = o->replace = 0;
    o->mode = 0;
    o->path = path;
    o->logger = &(desc ? desc : &none)->logger;
    if (!path || !path[0]) return tl__logger_fail(o->logger, TL_ERROR_INVALID_ARGUMENT, "tl_file_write: no path");
    if (!strcmp(path, "-"))
        return tl__logger_fail(o->logger, TL_ERROR_INVALID_ARGUMENT,
                               "-: standard output is not a file thinlight writes (name a file, ./- for one named '-')");
    const char *slash = strrchr(path, '/');
    if (slash && !slash[1]) return tl__logger_fail(o->logger, TL_ERROR_IO, "%s: names a directory, not a file", path);
    size_t dir_len = slash ? (size_t)(slash - path) : 0;
    if (strlen(path) >= sizeof o->dir) return tl__logger_fail(o->logger, TL_ERROR_IO, "%s: path too long", path);
    snprintf(o->dir, sizeof o->dir, "%.*s", slash ? (dir_len ? (int)dir_len : 1) : 1, slash ? path : ".");
    struct stat st;
    if (lstat(path, &st) == 0) {
        if (!S_ISREG(st.st_mode))
            return tl__logger_fail(o->logger, TL_ERROR_IO, "%s: %s, not a regular file: refused", path,
                                   tl__file_kind(st.st_mode));
        o->replace = 1;
        o->mode = st.st_mode & 07777;
    } else if (errno != ENOENT) {
        return tl__logger_fail(o->logger, TL_ERROR_IO, "%s: %s", path, strerror(errno));
    }
    return TL_OK;
}

/* The next free temporary name beside `path` for `make` (open O_EXCL or link); 0 or an errno. */
static int tl__out_name(tl__out *o, int (*make)(tl__out *))
{
    for (int n = 0; n < 100; n++) {
        snprintf(o->tmp, sizeof o->tmp, "%s.tmp%ld-%d", o->path, (long)getpid(), n);
        if (make(o) == 0) return 0;
        int err = errno;
        o->tmp[0] = '\0';
        if (err != EEXIST) return err;
    }
    return EEXIST;
}

static int tl__make_named(tl__out *o)
{
    o->fd = open(o->tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
    return o->fd >= 0 ? 0 : -1;
}

/* An unnamed file in the folder, else a temporary name. */
static tl_result tl__out_open(tl__out *o, int allow_unnamed)
{
#ifdef O_TMPFILE
    if (allow_unnamed) {
        o->fd = open(o->dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
        if (o->fd >= 0) {
            o->unnamed = 1;
            return TL_OK;
        }
        /* no O_TMPFILE here: the kernel (EISDIR: an old one reads it as O_DIRECTORY) or the file system */
        if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL)
            return tl__out_fail(o, "cannot create a file in its folder", errno);
    }
#else
    (void)allow_unnamed;
#endif
    o->unnamed = 0;
    int err = tl__out_name(o, tl__make_named);
    return err ? tl__out_fail(o, "cannot create a file in its folder", err) : TL_OK;
}

static int tl__write_all(int fd, const unsigned char *p, size_t size)
{
    while (size) {
        ssize_t n = write(fd, p, size > ((size_t)1 << 30) ? ((size_t)1 << 30) : size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return n < 0 ? errno : EIO;
        p += n;
        size -= (size_t)n;
    }
    return 0;
}

#ifdef O_TMPFILE
/* Gives the unnamed file a name (through /proc; AT_EMPTY_PATH where /proc is missing). */
static int tl__link_fd(int fd, const char *name)
{
    char proc[64];
    snprintf(proc, sizeof proc, "/proc/self/fd/%d", fd);
    if (linkat(AT_FDCWD, proc, AT_FDCWD, name, AT_SYMLINK_FOLLOW) == 0) return 0;
    if (errno == EEXIST) return -1;
    return linkat(fd, "", AT_FDCWD, name, AT_EMPTY_PATH);
}

static int tl__link_tmp(tl__out *o) { return tl__link_fd(o->fd, o->tmp); }

/* Names the unnamed file: `path` itself when it is new (nothing to replace, no temporary name
 * ever), else a temporary name; 0, EEXIST (path appeared and is not a regular file) or another
 * errno (the file cannot be linked here: write again through a named file). */
static int tl__out_link(tl__out *o)
{
    struct stat st;
    if (!o->replace) {
        if (tl__link_fd(o->fd, o->path) == 0) return 0;
        if (errno != EEXIST) return errno;
        if (lstat(o->path, &st) != 0 || !S_ISREG(st.st_mode)) return EEXIST; /* appeared meanwhile */
    }
    return tl__out_name(o, tl__link_tmp);
}
#endif

/* The bytes written, flushed and closed under their name (o->tmp, or `path` when it was new and
 * could be linked there); 0, 1 (the unnamed file could not be named: write again through a named
 * one) or -1 after the error was logged into *r. */
static int tl__out_finish(tl__out *o, const void *data, size_t size, tl_result *r)
{
    int err = tl__write_all(o->fd, data, size);
    if (err) return *r = tl__out_fail(o, "write failed", err), -1;
    if (o->replace) (void)fchmod(o->fd, o->mode); /* kept where the file system allows */
    if (fsync(o->fd) != 0) return *r = tl__out_fail(o, "fsync failed", errno), -1;
#ifdef O_TMPFILE
    if (o->unnamed && (err = tl__out_link(o)) != 0) {
        if (err == EEXIST) return *r = tl__out_fail(o, "appeared while written, not as a regular file", err), -1;
        int fd = o->fd; /* discarded, but its close is checked like every other */
        o->fd = -1;
        return close(fd) == 0 ? 1 : (*r = tl__out_fail(o, "close failed", errno), -1);
    }
#endif
    int fd = o->fd;
    o->fd = -1;
    if (close(fd) != 0) {
        if (!o->tmp[0]) unlink(o->path); /* linked as `path` itself, which did not exist */
        return *r = tl__out_fail(o, "close failed", errno), -1;
    }
    return 0;
}

static void tl__sync_dir(const char *dir)
{
    int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    (void)fsync(fd);
    close(fd);
}

tl_result tl_file_write(const char *path, const void *data, size_t size, const tl_file_write_desc *desc)
{
    tl__out o;
    tl_result r = tl__out_begin(&o, path, desc);
    if (r != TL_OK) return r;
    if (!data && size) return tl__logger_fail(o.logger, TL_ERROR_INVALID_ARGUMENT, "%s: NULL data", path);
    tl__out_reclaim(&o);
    if ((r = tl__out_open(&o, 1)) != TL_OK) return r;
    int step = tl__out_finish(&o, data, size, &r);
    if (step == 1) { /* unnamed but not linkable: once more through a named file */
        if ((r = tl__out_open(&o, 0)) != TL_OK) return r;
        step = tl__out_finish(&o, data, size, &r);
    }
    if (step != 0) return r;
    if (o.tmp[0] && rename(o.tmp, path) != 0) return tl__out_fail(&o, "rename failed", errno);
    o.tmp[0] = '\0';
    tl__sync_dir(o.dir);
    return TL_OK;
}

tl_result tl_file_check_writable(const char *path, const tl_file_write_desc *desc)
{
    tl__out o;
    tl_result r = tl__out_begin(&o, path, desc);
    if (r == TL_OK) r = tl__out_open(&o, 1);
    if (r != TL_OK) return r;
    int fd = o.fd;
    o.fd = -1;
    if (close(fd) != 0) return tl__out_fail(&o, "close failed", errno);
    if (o.tmp[0]) unlink(o.tmp);
    return TL_OK;
}

#else /* not POSIX */

tl_result tl_file_write(const char *path, const void *data, size_t size, const tl_file_write_desc *desc)
{
    (void)data;
    (void)size;
    return tl__logger_fail(desc ? &desc->logger : NULL, TL_ERROR_UNSUPPORTED, "%s: tl_file_write needs POSIX",
                           path ? path : "(null)");
}

tl_result tl_file_check_writable(const char *path, const tl_file_write_desc *desc)
{
    return tl_file_write(path, NULL, 0, desc);
}

#endif
