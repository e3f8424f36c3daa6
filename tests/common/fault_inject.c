/* A full disk on demand (fault_inject.h): an LD_PRELOAD library that makes the k-th write, fsync
 * or close of a regular file below one folder fail, and on request a system without O_TMPFILE
 * or without linkat. write, pwrite, writev and pwritev are
 * interposed; stdio streams opened for writing below the folder are made with fopencookie, so
 * that what fwrite/fprintf/fflush finally write comes through the same counted write (glibc's
 * own stdio calls its internal write, which no preload can reach). fileno() of such a stream
 * still returns its descriptor. Built without sanitizers: it is preloaded into sanitized tools
 * and into gnuplot alike. */
#define _GNU_SOURCE

#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

#include "fault_inject.h"

#define TLFI_EXPORT __attribute__((visibility("default")))

/* "short": the k-th write stores half of its bytes and says so (as a write that fills the disk
 * does), every later one fails; it shares the write count. */
enum { KIND_WRITE, KIND_FSYNC, KIND_CLOSE, KIND_COUNT, KIND_SHORT = KIND_COUNT };
static const char *const kind_names[KIND_COUNT + 1] = {"write", "fsync", "close", "short"};

static struct {
    char dir[PATH_MAX];   /* "" until armed */
    size_t dir_len;
    int kind;             /* the call that fails */
    unsigned long at;     /* 1-based; 0: count only */
    unsigned long seen[KIND_COUNT];
    char report[PATH_MAX];
    int no_tmpfile;       /* open(O_TMPFILE) fails with EOPNOTSUPP, as on a file system without it */
    int no_link;          /* linkat fails with ENOENT, as without /proc and CAP_DAC_READ_SEARCH */
} fi;
static pthread_mutex_t fi_lock = PTHREAD_MUTEX_INITIALIZER;

/* libc's function under the interposed one (dlsym's object pointer copied into a function
 * pointer, as POSIX allows and ISO C does not spell). */
typedef void (*any_fn)(void);
#define REAL(name) ((__typeof__(&name))real_fn(#name))

static any_fn real_fn(const char *name)
{
    void *p = dlsym(RTLD_NEXT, name);
    if (!p) _exit(127); /* no libc under it: nothing sensible is left to do */
    any_fn f;
    memcpy(&f, &p, sizeof f);
    return f;
}

/* Whether `fd` is a regular file below the armed folder (an unnamed O_TMPFILE file reads as
 * "DIR/#123 (deleted)", so it counts too), opened for writing unless `any_mode` (an fsync
 * through a descriptor opened for reading flushes the file all the same). */
static int counted(int fd, int any_mode)
{
    if (fd <= 2 || !fi.dir_len) return 0;
    struct stat st;
    int flags = fcntl(fd, F_GETFL);
    if (flags < 0 || (!any_mode && (flags & O_ACCMODE) == O_RDONLY)) return 0;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) return 0;
    char link[64], target[PATH_MAX];
    snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    ssize_t n = readlink(link, target, sizeof target - 1);
    if (n <= 0) return 0;
    target[n] = '\0';
    return (size_t)n > fi.dir_len && !strncmp(target, fi.dir, fi.dir_len) && target[fi.dir_len] == '/';
}

enum { PASS, FAIL, SHORT };

/* Counts a call of `kind` on `fd`: PASS, FAIL or (a write) SHORT. A full disk stays full: every
 * write from the k-th on fails; fsync and close fail once, at the k-th. */
static int must_fail(int fd, int kind)
{
    if (!counted(fd, kind == KIND_FSYNC)) return PASS;
    pthread_mutex_lock(&fi_lock);
    unsigned long n = ++fi.seen[kind];
    int armed = fi.at && n >= fi.at, r = PASS;
    if (armed && kind == KIND_WRITE && fi.kind == KIND_WRITE) r = FAIL;
    if (armed && kind == KIND_WRITE && fi.kind == KIND_SHORT) r = n == fi.at ? SHORT : FAIL;
    if (armed && kind == fi.kind && kind != KIND_WRITE && n == fi.at) r = FAIL;
    pthread_mutex_unlock(&fi_lock);
    return r;
}

static void configure(const char *dir, const char *call, unsigned long at)
{
    pthread_mutex_lock(&fi_lock);
    memset(fi.seen, 0, sizeof fi.seen);
    fi.dir_len = 0;
    fi.at = at;
    fi.kind = KIND_WRITE;
    for (int k = 0; call && k <= KIND_COUNT; k++)
        if (!strcmp(call, kind_names[k])) fi.kind = k;
    if (dir && dir[0] == '/' && strlen(dir) < sizeof fi.dir) {
        strcpy(fi.dir, dir);
        fi.dir_len = strlen(dir);
        while (fi.dir_len > 1 && fi.dir[fi.dir_len - 1] == '/') fi.dir[--fi.dir_len] = '\0';
    }
    pthread_mutex_unlock(&fi_lock);
}

TLFI_EXPORT void tl_fault_arm(const char *dir, const char *call, unsigned long at) { configure(dir, call, at); }

TLFI_EXPORT void tl_fault_without(const char *what)
{
    fi.no_tmpfile = what && strstr(what, "tmpfile") != NULL;
    fi.no_link = what && strstr(what, "link") != NULL;
}

TLFI_EXPORT unsigned long tl_fault_seen(const char *call)
{
    for (int k = 0; k <= KIND_COUNT; k++)
        if (!strcmp(call, kind_names[k])) return fi.seen[k == KIND_SHORT ? KIND_WRITE : k];
    return 0;
}

__attribute__((constructor)) static void fi_init(void)
{
    const char *at = getenv(TL_FAULT_ENV_AT), *report = getenv(TL_FAULT_ENV_REPORT);
    configure(getenv(TL_FAULT_ENV_DIR), getenv(TL_FAULT_ENV_CALL), at ? strtoul(at, NULL, 10) : 0);
    tl_fault_without(getenv(TL_FAULT_ENV_WITHOUT));
    if (report && strlen(report) < sizeof fi.report) strcpy(fi.report, report);
}

/* TL_FAULT_REPORT: "write N fsync N close N" appended at exit, one line per process. */
__attribute__((destructor)) static void fi_report(void)
{
    if (!fi.report[0] || !fi.dir_len) return;
    char line[128];
    int n = snprintf(line, sizeof line, "%ld write %lu fsync %lu close %lu\n", (long)getpid(), fi.seen[KIND_WRITE],
                     fi.seen[KIND_FSYNC], fi.seen[KIND_CLOSE]);
    int fd = open(fi.report, O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    if (fd >= 0) {
        (void)!REAL(write)(fd, line, (size_t)n);
        REAL(close)(fd);
    }
}

/* ---- descriptors ---------------------------------------------------------------------------- */

/* The bytes a write may store: n, half of them (SHORT; none left to halve is a failure) or -1. */
static ssize_t allowed(int fd, size_t n)
{
    if (!n) return 0;
    int r = must_fail(fd, KIND_WRITE);
    if (r == PASS) return (ssize_t)n;
    if (r == SHORT && n > 1) return (ssize_t)(n / 2);
    errno = ENOSPC;
    return -1;
}

TLFI_EXPORT ssize_t write(int fd, const void *buf, size_t n)
{
    ssize_t a = allowed(fd, n);
    return a < 0 ? -1 : REAL(write)(fd, buf, (size_t)a);
}

TLFI_EXPORT ssize_t pwrite(int fd, const void *buf, size_t n, off_t off)
{
    ssize_t a = allowed(fd, n);
    return a < 0 ? -1 : REAL(pwrite)(fd, buf, (size_t)a, off);
}

TLFI_EXPORT ssize_t pwrite64(int fd, const void *buf, size_t n, off64_t off)
{
    ssize_t a = allowed(fd, n);
    return a < 0 ? -1 : REAL(pwrite64)(fd, buf, (size_t)a, off);
}

/* Vectored writes fail whole (no short count): OIIO and libstdc++ retry what is left anyway. */
TLFI_EXPORT ssize_t writev(int fd, const struct iovec *iov, int count)
{
    if (count > 0 && must_fail(fd, KIND_WRITE) != PASS) return errno = ENOSPC, -1;
    return REAL(writev)(fd, iov, count);
}

TLFI_EXPORT ssize_t pwritev(int fd, const struct iovec *iov, int count, off_t off)
{
    if (count > 0 && must_fail(fd, KIND_WRITE) != PASS) return errno = ENOSPC, -1;
    return REAL(pwritev)(fd, iov, count, off);
}

TLFI_EXPORT int fsync(int fd)
{
    if (must_fail(fd, KIND_FSYNC) != PASS) return errno = EIO, -1;
    return REAL(fsync)(fd);
}

TLFI_EXPORT int fdatasync(int fd)
{
    if (must_fail(fd, KIND_FSYNC) != PASS) return errno = EIO, -1;
    return REAL(fdatasync)(fd);
}

/* As on Linux, the descriptor is closed even when close reports an error (NFS, a full quota). */
TLFI_EXPORT int close(int fd)
{
    int fail = must_fail(fd, KIND_CLOSE) != PASS;
    int r = REAL(close)(fd);
    if (fail && r == 0) return errno = EIO, -1;
    return r;
}

/* ---- what the writer falls back from ---------------------------------------------------------- */

static int open_flags_mode(int flags, va_list ap)
{
    return (flags & O_CREAT) || (flags & O_TMPFILE) == O_TMPFILE ? va_arg(ap, int) : 0;
}

TLFI_EXPORT int open(const char *path, int flags, ...)
{
    va_list ap;
    va_start(ap, flags);
    int mode = open_flags_mode(flags, ap);
    va_end(ap);
    if (fi.no_tmpfile && (flags & O_TMPFILE) == O_TMPFILE) return errno = EOPNOTSUPP, -1;
    return REAL(open)(path, flags, mode);
}

TLFI_EXPORT int open64(const char *path, int flags, ...)
{
    va_list ap;
    va_start(ap, flags);
    int mode = open_flags_mode(flags, ap);
    va_end(ap);
    if (fi.no_tmpfile && (flags & O_TMPFILE) == O_TMPFILE) return errno = EOPNOTSUPP, -1;
    return REAL(open64)(path, flags, mode);
}

TLFI_EXPORT int linkat(int olddir, const char *oldpath, int newdir, const char *newpath, int flags)
{
    if (fi.no_link) return errno = ENOENT, -1;
    return REAL(linkat)(olddir, oldpath, newdir, newpath, flags);
}

/* ---- stdio streams -------------------------------------------------------------------------- */

enum { MAX_STREAMS = 256 };
static struct {
    FILE *f;
    int fd;
} streams[MAX_STREAMS];

static ssize_t cookie_read(void *c, char *buf, size_t n) { return read((int)(intptr_t)c, buf, n); }

static ssize_t cookie_write(void *c, const char *buf, size_t n)
{
    size_t done = 0;
    while (done < n) {
        ssize_t w = write((int)(intptr_t)c, buf + done, n - done);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return done ? (ssize_t)done : -1; /* glibc: a short count sets the error flag */
        done += (size_t)w;
    }
    return (ssize_t)done;
}

static int cookie_seek(void *c, off64_t *off, int whence)
{
    off64_t r = lseek64((int)(intptr_t)c, *off, whence);
    if (r < 0) return -1;
    *off = r;
    return 0;
}

static int cookie_close(void *c)
{
    int fd = (int)(intptr_t)c;
    pthread_mutex_lock(&fi_lock);
    for (int i = 0; i < MAX_STREAMS; i++)
        if (streams[i].f && streams[i].fd == fd) streams[i].f = NULL;
    pthread_mutex_unlock(&fi_lock);
    return close(fd);
}

/* A counted stream for a descriptor opened for writing, or NULL (the caller uses libc's). */
static FILE *wrap(int fd, const char *mode)
{
    if (!strpbrk(mode, "wa+") || !counted(fd, 0)) return NULL;
    cookie_io_functions_t io = {cookie_read, cookie_write, cookie_seek, cookie_close};
    FILE *f = fopencookie((void *)(intptr_t)fd, mode, io);
    if (!f) return NULL;
    pthread_mutex_lock(&fi_lock);
    for (int i = 0; i < MAX_STREAMS; i++)
        if (!streams[i].f) {
            streams[i].f = f;
            streams[i].fd = fd;
            break;
        }
    pthread_mutex_unlock(&fi_lock);
    return f;
}

static FILE *open_stream(FILE *(*real)(const char *, const char *), const char *path, const char *mode)
{
    FILE *f = real(path, mode);
    if (!f || !fi.dir_len || !strpbrk(mode, "wa+")) return f;
    int fd = dup(fileno(f)); /* the stream's mode flags (append, ...) stay on the descriptor */
    if (fd < 0) return f;
    FILE *w = wrap(fd, mode);
    if (!w) {
        REAL(close)(fd);
        return f;
    }
    fclose(f); /* nothing was written through it yet */
    return w;
}

TLFI_EXPORT FILE *fopen(const char *path, const char *mode) { return open_stream(REAL(fopen), path, mode); }
TLFI_EXPORT FILE *fopen64(const char *path, const char *mode) { return open_stream(REAL(fopen64), path, mode); }

TLFI_EXPORT FILE *fdopen(int fd, const char *mode)
{
    FILE *w = fi.dir_len ? wrap(fd, mode) : NULL;
    return w ? w : REAL(fdopen)(fd, mode);
}

TLFI_EXPORT int fileno(FILE *f)
{
    pthread_mutex_lock(&fi_lock);
    int fd = -1;
    for (int i = 0; i < MAX_STREAMS && fd < 0; i++)
        if (streams[i].f == f) fd = streams[i].fd;
    pthread_mutex_unlock(&fi_lock);
    return fd >= 0 ? fd : REAL(fileno)(f);
}
