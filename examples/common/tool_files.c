/* File output for the tools: every output is written under a temporary name and renamed into
 * place, so that a failure never leaves a partial file; generated doc sections between markers. */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "tool_util.h"

void tl_tool_fail(const char *tool, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: ", tool);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}

char *tl_tool_strf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0) return NULL;
    char *s = malloc((size_t)n + 1);
    if (!s) return NULL;
    va_start(ap, fmt);
    vsnprintf(s, (size_t)n + 1, fmt, ap);
    va_end(ap);
    return s;
}

char *tl_tool_dir_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (!slash) return tl_tool_strf(".");
    if (slash == path) return tl_tool_strf("/");
    return tl_tool_strf("%.*s", (int)(slash - path), path);
}

int tl_tool_is_dir(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

int tl_tool_make_dirs(const char *path)
{
    char *p = tl_tool_strf("%s", path);
    if (!p) return ENOMEM;
    int err = 0;
    for (char *s = p + 1;; s++) {
        if (*s != '/' && *s != '\0') continue;
        char c = *s;
        *s = '\0';
        if (mkdir(p, 0777) != 0 && errno != EEXIST) err = errno;
        *s = c;
        if (err || c == '\0') break;
    }
    if (!err && !tl_tool_is_dir(p)) err = ENOTDIR;
    free(p);
    return err;
}

char *tl_tool_temp_name(const char *path) { return tl_tool_strf("%s.tmp.%ld", path, (long)getpid()); }

int tl_tool_probe_writable(const char *path)
{
    char *tmp = tl_tool_temp_name(path);
    if (!tmp) return ENOMEM;
    FILE *f = fopen(tmp, "wb");
    int err = f ? 0 : errno;
    if (f) {
        fclose(f);
        remove(tmp);
    }
    free(tmp);
    return err;
}

int tl_tool_fsync_file(const char *path)
{
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return errno;
    int err = fsync(fd) == 0 ? 0 : errno;
    close(fd);
    return err;
}

int tl_tool_write_atomic(const char *tool, const char *path, tl_tool_write_fn fn, const void *ctx)
{
    char *tmp = tl_tool_temp_name(path);
    if (!tmp) {
        tl_tool_fail(tool, "out of memory");
        return 1;
    }
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        tl_tool_fail(tool, "cannot write '%s': %s", path, strerror(errno));
        free(tmp);
        return 1;
    }
    errno = 0;
    int bad = fn(f, ctx) != 0;
    /* on disk before the rename: even a crash of the machine leaves the old file or the new one */
    bad |= fflush(f) != 0 || ferror(f) != 0 || fsync(fileno(f)) != 0;
    bad |= fclose(f) != 0;
    if (bad || rename(tmp, path) != 0) {
        tl_tool_fail(tool, "cannot write '%s': %s", path, errno ? strerror(errno) : "write error");
        remove(tmp);
        free(tmp);
        return 1;
    }
    free(tmp);
    return 0;
}

char *tl_tool_read_file(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    size_t cap = 1 << 16, len = 0;
    char *buf = malloc(cap);
    while (buf) {
        len += fread(buf + len, 1, cap - 1 - len, f);
        if (ferror(f)) {
            free(buf);
            buf = NULL;
            errno = EIO;
            break;
        }
        if (feof(f)) break;
        char *grown = realloc(buf, cap * 2);
        if (!grown) {
            free(buf);
            buf = NULL;
            errno = ENOMEM;
            break;
        }
        buf = grown;
        cap *= 2;
    }
    fclose(f);
    if (!buf) return NULL;
    buf[len] = '\0';
    if (size) *size = len;
    return buf;
}

static int tl__write_span(FILE *f, const void *ctx)
{
    const char *const *span = ctx; /* [begin, end) */
    size_t n = (size_t)(span[1] - span[0]);
    return fwrite(span[0], 1, n, f) != n;
}

int tl_tool_copy_file(const char *tool, const char *src, const char *dst)
{
    size_t size = 0;
    char *data = tl_tool_read_file(src, &size);
    if (!data) {
        tl_tool_fail(tool, "cannot read '%s': %s", src, strerror(errno));
        return 1;
    }
    const char *span[2] = {data, data + size};
    int err = tl_tool_write_atomic(tool, dst, tl__write_span, span);
    free(data);
    return err;
}

int tl_tool_doc_split(const char *tool, const char *path, const char *text, const char *begin, const char *end,
                      size_t *head_len, const char **tail)
{
    const char *b = strstr(text, begin);
    const char *e = b ? strstr(b + strlen(begin), end) : NULL;
    if (!b || !e) {
        tl_tool_fail(tool, "%s: markers %s ... %s not found (add them where the tables belong)", path, begin, end);
        return 1;
    }
    *head_len = (size_t)(b - text) + strlen(begin);
    *tail = e;
    return 0;
}
