/* Images of the sweep: each mode's final image, and a heat map of |mode - fat| over the final
 * image (largest RGB channel difference, in 8-bit steps); for thin-lpp's light-scale variants also
 * one of |variant - thin-lpp at scale 1| (bench_heat_<slug>_vs_scale1_*), on the same scale. The heat map's colour is
 * ramp(sqrt(min(err, S) / S)) with S = BENCH_HEAT_SCALE steps, so that one step is already a
 * quarter of the ramp; a difference of exactly 0 is black. A legend strip below the image runs
 * linearly from 0 to S steps, with a tick at every step and a taller one every 4. For the doc a
 * second heat map at most BENCH__DOC_WIDTH wide keeps the largest error of each block of pixels,
 * so that no isolated error disappears. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "tool_gl.h"
#include "tool_util.h"

#define BENCH__LEGEND_ROWS 16u
#define BENCH__DOC_WIDTH 640u

/* An inferno-like ramp: black, purple, red, orange, pale yellow. */
static void bench__ramp(double t, uint8_t rgb[3])
{
    static const double stops[5][3] = {{0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}};
    t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
    double x = t * 4.0;
    int i = x >= 4.0 ? 3 : (int)x;
    double f = x - i;
    for (int c = 0; c < 3; c++) rgb[c] = (uint8_t)lround(stops[i][c] + f * (stops[i + 1][c] - stops[i][c]));
}

/* Largest channel difference per pixel. */
static uint8_t *bench__errors(const uint8_t *ldr, const uint8_t *ref, size_t n)
{
    uint8_t *e = malloc(n ? n : 1);
    for (size_t i = 0; e && i < n; i++) {
        int m = 0;
        for (int c = 0; c < 3; c++) {
            int d = abs((int)ldr[3 * i + c] - (int)ref[3 * i + c]);
            if (d > m) m = d;
        }
        e[i] = (uint8_t)m;
    }
    return e;
}

/* The largest error of each k x k block (partial blocks at the edges included). */
static uint8_t *bench__pool(const uint8_t *err, uint32_t w, uint32_t h, uint32_t k, uint32_t *pw, uint32_t *ph)
{
    *pw = (w + k - 1) / k;
    *ph = (h + k - 1) / k;
    uint8_t *p = calloc((size_t)*pw * *ph, 1);
    for (uint32_t y = 0; p && y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            uint8_t *q = p + (size_t)(y / k) * *pw + x / k;
            if (err[(size_t)y * w + x] > *q) *q = err[(size_t)y * w + x];
        }
    return p;
}

/* RGB, rows bottom to top (GL order): the legend first, then the image. */
static uint8_t *bench__colourise(const uint8_t *err, uint32_t w, uint32_t h)
{
    uint8_t *out = calloc((size_t)w * (h + BENCH__LEGEND_ROWS), 3);
    if (!out) return NULL;
    for (uint32_t y = 2; y < 10; y++) /* the ramp, linear in steps */
        for (uint32_t x = 0; x < w; x++)
            bench__ramp(sqrt((x + 0.5) / w), out + ((size_t)y * w + x) * 3);
    for (uint32_t k = 0; k <= BENCH_HEAT_SCALE; k++) { /* ticks above it, taller every 4 steps */
        uint32_t x = (uint32_t)((uint64_t)k * w / BENCH_HEAT_SCALE);
        if (x >= w) x = w - 1;
        for (uint32_t y = k % 4 ? 12 : 10; y < BENCH__LEGEND_ROWS; y++) memset(out + ((size_t)y * w + x) * 3, 255, 3);
    }
    uint8_t *img = out + (size_t)BENCH__LEGEND_ROWS * w * 3;
    for (size_t i = 0; i < (size_t)w * h; i++) {
        if (err[i]) {
            double v = err[i] > BENCH_HEAT_SCALE ? 1.0 : (double)err[i] / BENCH_HEAT_SCALE;
            bench__ramp(sqrt(v), img + 3 * i);
        }
    }
    return out;
}

static int bench__note_image(bench_run *run, const char *path, bench_image_kind kind, const bench_record *rec)
{
    if (run->image_count == run->image_capacity) {
        size_t cap = run->image_capacity ? 2 * run->image_capacity : 16;
        bench_image_file *grown = realloc(run->images, cap * sizeof *grown);
        if (!grown) {
            tl_tool_fail(BENCH_TOOL, "out of memory");
            return 1;
        }
        run->images = grown;
        run->image_capacity = cap;
    }
    bench_image_file *f = &run->images[run->image_count++];
    snprintf(f->path, sizeof f->path, "%s", path);
    f->kind = kind;
    f->config = rec->config;
    f->lights = rec->lights;
    f->width = rec->width;
    f->height = rec->height;
    return 0;
}

const char *const bench_image_kind_names[BENCH_IMAGE_KINDS] = {"final", "heat", "heat-doc", "heat-vs-scale1",
                                                               "heat-vs-scale1-doc", "edges"};

static int bench__write_png(bench_run *run, const bench_record *rec, bench_image_kind kind, const uint8_t *rgb,
                            uint32_t w, uint32_t h)
{
    char path[512];
    const char *mode = bench_config_slug(rec->config);
    int scale1 = kind == BENCH_IMAGE_HEAT_SCALE1 || kind == BENCH_IMAGE_HEAT_SCALE1_DOC,
        doc = kind == BENCH_IMAGE_HEAT_DOC || kind == BENCH_IMAGE_HEAT_SCALE1_DOC;
    if (kind == BENCH_IMAGE_FINAL)
        snprintf(path, sizeof path, "%s/bench_final_%s_%ulights_%ux%u.png", run->opt.out, mode, rec->lights,
                 rec->width, rec->height);
    else if (kind == BENCH_IMAGE_EDGES)
        snprintf(path, sizeof path, "%s/bench_edges_%ux%u.png", run->opt.out, rec->width, rec->height);
    else
        snprintf(path, sizeof path, "%s/bench_heat_%s_vs_%s_%ulights_%ux%u_0-%usteps%s.png", run->opt.out, mode,
                 scale1 ? "scale1" : "fat", rec->lights, rec->width, rec->height, BENCH_HEAT_SCALE, doc ? "_doc" : "");
    tl_image_desc desc = {.width = w, .height = h, .channels = 3, .type = TL_PIXEL_U8, .bottom_up = 1};
    if (tl_tool_write_image(BENCH_TOOL, path, &desc, rgb)) return 1;
    return bench__note_image(run, path, kind, rec);
}

/* The heat map (against fat, or with scale1 against thin-lpp at scale 1), and for the doc one at
 * most BENCH__DOC_WIDTH wide. */
static int bench__heat(bench_run *run, const bench_record *rec, const uint8_t *err, int doc, int scale1)
{
    uint32_t w = rec->width, h = rec->height, k = doc ? (w + BENCH__DOC_WIDTH - 1) / BENCH__DOC_WIDTH : 1;
    uint8_t *pooled = k > 1 ? bench__pool(err, w, h, k, &w, &h) : NULL;
    uint8_t *rgb = k > 1 && !pooled ? NULL : bench__colourise(pooled ? pooled : err, w, h);
    int e = !rgb;
    if (e) tl_tool_fail(BENCH_TOOL, "out of memory for a heat map");
    else
        e = bench__write_png(run, rec,
                             scale1 ? (doc ? BENCH_IMAGE_HEAT_SCALE1_DOC : BENCH_IMAGE_HEAT_SCALE1)
                                    : (doc ? BENCH_IMAGE_HEAT_DOC : BENCH_IMAGE_HEAT),
                             rgb, w, h + BENCH__LEGEND_ROWS);
    free(pooled);
    free(rgb);
    return e;
}

static int bench__heat_against(bench_run *run, const bench_record *rec, const uint8_t *ldr, const uint8_t *ref,
                               int scale1)
{
    uint8_t *err = bench__errors(ldr, ref, (size_t)rec->width * rec->height);
    if (!err) {
        tl_tool_fail(BENCH_TOOL, "out of memory for a heat map");
        return 1;
    }
    int e = bench__heat(run, rec, err, 0, scale1) || (run->opt.doc && bench__heat(run, rec, err, 1, scale1));
    free(err);
    return e;
}

int bench_images_write(bench_run *run, const bench_record *rec, const uint8_t *ldr, const uint8_t *ref_ldr,
                       const uint8_t *scale1_ldr, int final_image, int heat_map)
{
    if (final_image && bench__write_png(run, rec, BENCH_IMAGE_FINAL, ldr, rec->width, rec->height)) return 1;
    if (heat_map && bench__heat_against(run, rec, ldr, ref_ldr, 0)) return 1;
    return scale1_ldr && bench__heat_against(run, rec, ldr, scale1_ldr, 1);
}

int bench_images_write_edges(bench_run *run, const bench_record *rec, const uint8_t *ref_ldr, const uint8_t *mask)
{
    size_t n = (size_t)rec->width * rec->height;
    uint8_t *rgb = malloc(3 * (n ? n : 1));
    if (!rgb) {
        tl_tool_fail(BENCH_TOOL, "out of memory for the edge image");
        return 1;
    }
    for (size_t i = 0; i < n; i++) { /* beneath: fat's luma, a third, in steps of 8 (a small PNG) */
        const uint8_t *c = ref_ldr + 3 * i;
        uint8_t grey = (uint8_t)(((77u * c[0] + 150u * c[1] + 29u * c[2]) / 768u) & ~7u);
        memset(rgb + 3 * i, mask[i] ? 255 : grey, 3);
    }
    int e = bench__write_png(run, rec, BENCH_IMAGE_EDGES, rgb, rec->width, rec->height);
    free(rgb);
    return e;
}
