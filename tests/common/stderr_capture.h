/* Captures what the process writes to file descriptor 2 (stderr, through stdio or write(2), from
 * thinlight or from the libraries below it) between tlc_stderr_begin and tlc_stderr_end, for
 * tests that require a library call to print nothing. POSIX only; header-only. */
#ifndef TL_STDERR_CAPTURE_H
#define TL_STDERR_CAPTURE_H

#include <stdio.h>
#include <string.h>
#include <unistd.h>

typedef struct tlc_stderr {
    int saved; /* the real stderr; -1 when capturing could not start */
    FILE *file;
} tlc_stderr;

/* Sends stderr into a temporary file until tlc_stderr_end. */
static inline void tlc_stderr_begin(tlc_stderr *c)
{
    fflush(stderr);
    c->file = tmpfile();
    c->saved = c->file ? dup(2) : -1;
    if (c->saved >= 0 && dup2(fileno(c->file), 2) < 0) {
        close(c->saved);
        c->saved = -1;
    }
}

/* Restores stderr and copies what was written meanwhile into `out` (at most size - 1 bytes, NUL
 * terminated); returns how many bytes were written in all, or -1 when capturing failed. */
static inline long tlc_stderr_end(tlc_stderr *c, char *out, size_t size)
{
    if (size) out[0] = '\0';
    if (c->saved < 0) {
        if (c->file) fclose(c->file);
        return -1;
    }
    fflush(stderr);
    dup2(c->saved, 2);
    close(c->saved);
    /* written through the descriptor, not the FILE: ask the descriptor */
    int fd = fileno(c->file);
    long total = (long)lseek(fd, 0, SEEK_END);
    size_t n = 0;
    if (size && lseek(fd, 0, SEEK_SET) == 0)
        for (ssize_t got; n < size - 1 && (got = read(fd, out + n, size - 1 - n)) > 0;) n += (size_t)got;
    if (size) out[n] = '\0';
    fclose(c->file);
    return total;
}

#endif
