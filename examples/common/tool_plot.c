/* gnuplot for the tools: data and script files written whole or not at all, gnuplot run inside
 * the output directory (so scripts name their files relatively) with the PNG on its standard
 * output, checked and written by tl_file_write: gnuplot itself writes no file. */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tool_util.h"

int tl_tool_have_gnuplot(void)
{
    const char *path = getenv("PATH");
    if (!path) path = "/usr/bin:/bin";
    while (*path) {
        size_t n = strcspn(path, ":");
        char *exe = tl_tool_strf("%.*s/gnuplot", (int)n, n ? path : ".");
        int ok = exe && access(exe, X_OK) == 0;
        free(exe);
        if (ok) return 1;
        path += n;
        if (*path == ':') path++;
    }
    return 0;
}

/* The PNG gnuplot wrote on its standard output: grown as it comes; NULL on failure. */
static unsigned char *tl__read_pipe(int fd, size_t *size)
{
    size_t cap = 1 << 16, len = 0;
    unsigned char *buf = malloc(cap);
    while (buf) {
        if (len == cap) {
            unsigned char *grown = realloc(buf, cap *= 2);
            if (!grown) break;
            buf = grown;
        }
        ssize_t n = read(fd, buf + len, cap - len);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) break;
        if (n == 0) {
            *size = len;
            return buf;
        }
        len += (size_t)n;
    }
    free(buf);
    return NULL;
}

/* Runs `gnuplot -e tl_stdout=1 SCRIPT` with DIR as working directory; its exit status (-1 when
 * it did not run or exit), its standard output in *png (malloc'ed, *size bytes). */
static int tl__run_gnuplot(const char *tool, const char *dir, const char *script, unsigned char **png, size_t *size)
{
    int out[2];
    *png = NULL;
    fflush(NULL);
    if (pipe(out) != 0) {
        tl_tool_fail(tool, "cannot start gnuplot: %s", strerror(errno));
        return -1;
    }
    pid_t pid = fork();
    if (pid < 0) {
        tl_tool_fail(tool, "cannot start gnuplot: %s", strerror(errno));
        close(out[0]);
        close(out[1]);
        return -1;
    }
    if (pid == 0) {
        close(out[0]);
        if (dup2(out[1], 1) >= 0 && chdir(dir) == 0)
            execlp("gnuplot", "gnuplot", "-e", "tl_stdout=1", script, (char *)NULL);
        _exit(127);
    }
    close(out[1]);
    *png = tl__read_pipe(out[0], size);
    close(out[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            tl_tool_fail(tool, "waiting for gnuplot: %s", strerror(errno));
            return -1;
        }
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* A whole PNG: the signature, and the IEND chunk last (gnuplot cut short ends before it). */
static int tl__whole_png(const unsigned char *b, size_t n)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
    return b && n >= 8 + 12 && !memcmp(b, sig, 8) && !memcmp(b + n - 12, iend, 12);
}

int tl_tool_make_plot(tl_tool_plot *p)
{
    snprintf(p->set_output, sizeof p->set_output,
             "if (exists(\"tl_stdout\")) { set output } else { set output '%s.png' }", p->name);
    char *dat = tl_tool_strf("%s/%s.dat", p->dir, p->name);
    char *gp_name = tl_tool_strf("%s.gp", p->name);
    char *gp = tl_tool_strf("%s/%s.gp", p->dir, p->name);
    char *png_path = tl_tool_strf("%s/%s.png", p->dir, p->name);
    unsigned char *png = NULL;
    size_t size = 0;
    int err = 1;
    if (!dat || !gp_name || !gp || !png_path) {
        tl_tool_fail(p->tool, "out of memory");
        goto done;
    }
    if ((p->data && tl_tool_write_atomic(p->tool, dat, p->data, p)) || tl_tool_write_atomic(p->tool, gp, p->script, p))
        goto done;
    int status = tl__run_gnuplot(p->tool, p->dir, gp_name, &png, &size);
    if (status != 0 || !tl__whole_png(png, size)) {
        if (status >= 0) tl_tool_fail(p->tool, "gnuplot failed (status %d, %zu bytes of PNG) on %s", status, size, gp);
        goto done;
    }
    if (p->max_bytes && size > p->max_bytes)
        fprintf(stderr, "%s: warning: %s is %zu KiB (over %zu KiB)\n", p->tool, png_path, size / 1024,
                p->max_bytes / 1024);
    err = tl_tool_write_bytes(p->tool, png_path, png, size);
done:
    free(dat);
    free(gp_name);
    free(gp);
    free(png_path);
    free(png);
    return err;
}
