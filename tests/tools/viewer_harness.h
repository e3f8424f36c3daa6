/* Shared by the thinlight-viewer tests (test_viewer.c, test_viewer_effects.c): running the viewer
 * under Xvfb with --screenshot, reading the PNG, and looking at its pixels and grid cells. Needs
 * TL_VIEWER, TL_RENDER and TL_WORK defined (CMakeLists.txt). */
#ifndef TL_VIEWER_HARNESS_H
#define TL_VIEWER_HARNESS_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "thinlight/io.h"
#include "thinlight/metrics.h"
#include "tl_test.h"

/* The viewer's grid of every view (VW_GRID_COLS x VW_GRID_ROWS in examples/viewer/viewer.h). */
enum { GRID_COLS = 5, GRID_ROWS = 6 };

typedef struct image {
    uint32_t w, h;
    uint8_t *px; /* RGBA8, rows top to bottom */
} image;

/* Under THINLIGHT_SANITIZE the viewer's leak check is off: Mesa's GLX driver (swrast_dri.so)
 * leaks 112 bytes and is unloaded at exit, so LeakSanitizer reports an unknown module that no
 * suppression can name (with the driver kept loaded, the viewer reports no leak at all). Address
 * and undefined-behaviour checks stay on. */
#ifdef TL_SANITIZED
#define VW_ENV "env LSAN_OPTIONS=detect_leaks=0 "
#else
#define VW_ENV ""
#endif

/* -noreset: without it Xvfb resets when the viewer disconnects and signals xvfb-run again, which
 * can land in xvfb-run's clean-up and turn the viewer's exit status into 5 (about 1 run in 4). */
static inline const char *xvfb(void)
{
    const char *d = getenv("DISPLAY");
    return d && d[0] ? VW_ENV : "xvfb-run -a -s '-screen 0 1280x1024x24 -noreset' " VW_ENV;
}

/* Runs a command line; its exit status (-1 when it did not exit). */
static inline int run(const char *cmd)
{
    int s = system(cmd);
    if (s == -1 || !WIFEXITED(s)) return -1;
    return WEXITSTATUS(s);
}

static inline int viewer(const char *args, const char *png)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "%s'%s' --no-panel --light-strategy tiled --frames 2 --screenshot '%s/%s' %s", xvfb(),
             TL_VIEWER, TL_WORK, png, args);
    int s = run(cmd);
    if (s) fprintf(stderr, "exit %d: %s\n", s, cmd);
    return s;
}

static inline void log_line(void *user, tl_log_level level, const char *message)
{
    (void)user;
    (void)level;
    fprintf(stderr, "%s\n", message);
}

static inline image load(const char *png)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", TL_WORK, png);
    tl_rgba8_image r = {0};
    tl_image_read_desc d = {.logger = {.fn = log_line}}; /* default allocator: malloc, so free() releases */
    tl_image_read_rgba8(path, &d, &r);
    return (image){r.width, r.height, r.rgba};
}

/* The viewer at w x h with the arguments `more`, its screenshot `png` loaded; no pixels (px NULL)
 * when the viewer failed, whatever an earlier run left under that name. */
static inline image shot(uint32_t w, uint32_t h, const char *more, const char *png)
{
    char args[1024];
    snprintf(args, sizeof args, "--size %ux%u %s", w, h, more);
    if (viewer(args, png)) return (image){0, 0, NULL};
    return load(png);
}

static inline const uint8_t *at(const image *im, uint32_t x, uint32_t y) { return im->px + 4 * ((size_t)y * im->w + x); }

/* A grid cell's interior (rows top to bottom (the viewer leaves a 1-pixel border) as its own image. */
static inline image cell(const image *grid, int v)
{
    uint32_t cw = grid->w / GRID_COLS, ch = grid->h / GRID_ROWS, x0 = (uint32_t)(v % GRID_COLS) * cw,
             y0 = (uint32_t)(v / GRID_COLS) * ch;
    image c = {cw - 2, ch - 2, malloc((size_t)(cw - 2) * (ch - 2) * 4)};
    for (uint32_t y = 0; c.px && y < c.h; y++) memcpy(c.px + 4 * (size_t)y * c.w, at(grid, x0 + 1, y0 + 1 + y), 4 * (size_t)c.w);
    return c;
}

/* The placeholder of a view a mode lacks: 16-pixel squares of grey 32 and 48. */
static inline int is_placeholder(const image *c)
{
    for (size_t i = 0; i < (size_t)c->w * c->h; i++) {
        const uint8_t *p = c->px + 4 * i;
        if ((p[0] != 32 && p[0] != 48) || p[1] != p[0] || p[2] != p[0]) return 0;
    }
    return 1;
}

/* Distinct colours: a blank (one-colour) image has 1. */
static inline size_t colours(const image *c)
{
    size_t n = 0;
    uint32_t seen[64];
    for (size_t i = 0; i < (size_t)c->w * c->h && n < 64; i++) {
        uint32_t v;
        memcpy(&v, c->px + 4 * i, 4);
        size_t k = 0;
        while (k < n && seen[k] != v) k++;
        if (k == n) seen[n++] = v;
    }
    return n;
}

/* Screenshots are opaque: nothing of an earlier frame may show through. */
static inline int opaque(const image *im)
{
    for (size_t i = 0; im->px && i < (size_t)im->w * im->h; i++)
        if (im->px[4 * i + 3] != 255) return 0;
    return im->px != NULL;
}

static inline tl_image_error compare(const image *a, const image *b)
{
    tl_image_error e;
    memset(&e, 0, sizeof e);
    e.max_abs = 1e9;
    if (a->px && b->px && a->w == b->w && a->h == b->h) tl_image_compare_u8(a->px, b->px, (size_t)a->w * a->h * 4, &e);
    return e;
}

static inline void release(image *im) { free(im->px); im->px = NULL; }

#endif
