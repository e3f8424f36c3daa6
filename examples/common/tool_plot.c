/* gnuplot for the tools: data and script files written atomically, gnuplot run inside the output
 * directory (so scripts name their files relatively), the PNG renamed into place on success. */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
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

/* Runs `gnuplot SCRIPT` with DIR as working directory; its exit status, or -1. */
static int tl__run_gnuplot(const char *tool, const char *dir, const char *script)
{
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        tl_tool_fail(tool, "cannot start gnuplot: %s", strerror(errno));
        return -1;
    }
    if (pid == 0) {
        if (chdir(dir) == 0) execlp("gnuplot", "gnuplot", script, (char *)NULL);
        _exit(127);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            tl_tool_fail(tool, "waiting for gnuplot: %s", strerror(errno));
            return -1;
        }
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int tl_tool_make_plot(tl_tool_plot *p)
{
    snprintf(p->png_tmp, sizeof p->png_tmp, "%s.png.tmp.%ld", p->name, (long)getpid());
    char *dat = tl_tool_strf("%s/%s.dat", p->dir, p->name);
    char *gp_name = tl_tool_strf("%s.gp", p->name);
    char *gp = tl_tool_strf("%s/%s.gp", p->dir, p->name);
    char *png = tl_tool_strf("%s/%s.png", p->dir, p->name);
    char *tmp = tl_tool_strf("%s/%s", p->dir, p->png_tmp);
    int err = 1;
    if (!dat || !gp_name || !gp || !png || !tmp) {
        tl_tool_fail(p->tool, "out of memory");
        goto done;
    }
    if ((p->data && tl_tool_write_atomic(p->tool, dat, p->data, p)) || tl_tool_write_atomic(p->tool, gp, p->script, p))
        goto done;
    int status = tl__run_gnuplot(p->tool, p->dir, gp_name);
    struct stat st;
    if (status != 0 || stat(tmp, &st) != 0 || st.st_size == 0) {
        if (status >= 0) tl_tool_fail(p->tool, "gnuplot failed (status %d) on %s", status, gp);
        remove(tmp);
        goto done;
    }
    if (p->max_bytes && (size_t)st.st_size > p->max_bytes)
        fprintf(stderr, "%s: warning: %s is %ld KiB (over %zu KiB)\n", p->tool, png, (long)(st.st_size / 1024),
                p->max_bytes / 1024);
    if (tl_tool_fsync_file(tmp) != 0 || rename(tmp, png) != 0) {
        tl_tool_fail(p->tool, "cannot write '%s': %s", png, strerror(errno));
        remove(tmp);
        goto done;
    }
    err = 0;
done:
    free(dat);
    free(gp_name);
    free(gp);
    free(png);
    free(tmp);
    return err;
}
