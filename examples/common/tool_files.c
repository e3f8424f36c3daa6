/* File output for the tools: every output is made in memory and written by tl_file_write
 * (thinlight/file.h), whole or not at all, never over anything but a regular file; generated doc
 * sections between markers. */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "thinlight/file.h"
#include "tool_log.h"
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

int tl_tool_check_output(const char *tool, const char *path)
{
    tl_file_write_desc d = {tl_tool_logger(tool)};
    return tl_file_check_writable(path, &d) != TL_OK;
}

int tl_tool_write_bytes(const char *tool, const char *path, const void *data, size_t size)
{
    tl_file_write_desc d = {tl_tool_logger(tool)}; /* its line: "TOOL: PATH: reason" */
    return tl_file_write(path, data, size, &d) != TL_OK;
}

int tl_tool_write_atomic(const char *tool, const char *path, tl_tool_write_fn fn, const void *ctx)
{
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    if (!f) {
        tl_tool_fail(tool, "%s: out of memory", path);
        return 1;
    }
    int bad = fn(f, ctx) != 0;
    bad |= fflush(f) != 0 || ferror(f) != 0;
    bad |= fclose(f) != 0; /* a memory stream fails only for want of memory */
    int err = bad ? 1 : tl_tool_write_bytes(tool, path, text, size);
    if (bad) tl_tool_fail(tool, "%s: out of memory", path);
    free(text);
    return err;
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

int tl_tool_copy_file(const char *tool, const char *src, const char *dst)
{
    size_t size = 0;
    char *data = tl_tool_read_file(src, &size);
    if (!data) {
        tl_tool_fail(tool, "cannot read '%s': %s", src, strerror(errno));
        return 1;
    }
    int err = tl_tool_write_bytes(tool, dst, data, size);
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
