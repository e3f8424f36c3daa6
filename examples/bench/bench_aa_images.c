/* The AA measurement's images (--aa with --out): the truth's and each record's final image of the
 * last light count, full size, and for the doc a crop of BENCH_AA_CROP_W x BENCH_AA_CROP_H pixels
 * where the truth has the most edge pixels (the same window in every image), magnified
 * BENCH_AA_CROP_ZOOM times by repeating pixels, so that the stair steps and their smoothing show. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "tool_gl.h"

/* The window (cw x ch, every BENCH__STEP pixels) with the most edge pixels; the first of equals. */
#define BENCH__STEP 8u
static void bench__crop_origin(const bench_aa_truth *t, uint32_t cw, uint32_t ch, uint32_t *x0, uint32_t *y0)
{
    uint32_t w = t->width, h = t->height;
    uint32_t *sum = calloc((size_t)(w + 1) * (h + 1), sizeof *sum); /* summed-area table */
    *x0 = (w - cw) / 2;
    *y0 = (h - ch) / 2;
    if (!sum) return;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++)
            sum[(size_t)(y + 1) * (w + 1) + x + 1] = t->edge[(size_t)y * w + x] + sum[(size_t)y * (w + 1) + x + 1] +
                                                     sum[(size_t)(y + 1) * (w + 1) + x] - sum[(size_t)y * (w + 1) + x];
    uint32_t best = 0;
    for (uint32_t y = 0; y + ch <= h; y += BENCH__STEP)
        for (uint32_t x = 0; x + cw <= w; x += BENCH__STEP) {
            uint32_t n = sum[(size_t)(y + ch) * (w + 1) + x + cw] - sum[(size_t)y * (w + 1) + x + cw] -
                         sum[(size_t)(y + ch) * (w + 1) + x] + sum[(size_t)y * (w + 1) + x];
            if (n > best) best = n, *x0 = x, *y0 = y;
        }
    free(sum);
}

/* The crop of rgb (w wide, rows bottom up), magnified: (cw z) x (ch z), rows bottom up. */
static uint8_t *bench__crop(const bench_aa_truth *t, const uint8_t *rgb, uint32_t cw, uint32_t ch, uint32_t z)
{
    uint32_t x0, y0;
    bench__crop_origin(t, cw, ch, &x0, &y0);
    uint8_t *out = malloc((size_t)cw * z * ch * z * 3);
    for (uint32_t y = 0; out && y < ch * z; y++)
        for (uint32_t x = 0; x < cw * z; x++)
            memcpy(out + ((size_t)y * cw * z + x) * 3, rgb + ((size_t)(y0 + y / z) * t->width + x0 + x / z) * 3, 3);
    return out;
}

static int bench__note(bench_run *run, const char *path, const bench_aa_record *rec, int crop, uint32_t lights)
{
    bench_aa_image *grown = realloc(run->aa_images, (run->aa_image_count + 1) * sizeof *grown);
    if (!grown) {
        tl_tool_fail(BENCH_TOOL, "out of memory");
        return 1;
    }
    run->aa_images = grown;
    bench_aa_image *im = &grown[run->aa_image_count++];
    memset(im, 0, sizeof *im);
    snprintf(im->path, sizeof im->path, "%.511s", path);
    im->config = rec ? rec->config : bench_config_make(BENCH_REFERENCE, run->opt.strategies[0]);
    im->aa = rec ? rec->aa : BENCH_AAS;
    im->crop = crop;
    im->lights = lights;
    return 0;
}

static int bench__write(bench_run *run, const bench_aa_truth *t, const bench_aa_record *rec, const uint8_t *rgb,
                        uint32_t w, uint32_t h, int crop)
{
    char name[160], path[512];
    if (rec) snprintf(name, sizeof name, "%s_%s", bench_config_slug(rec->config), bench_aa_name(rec->aa));
    else snprintf(name, sizeof name, "truth");
    snprintf(path, sizeof path, "%s/bench_aa_%s_%ulights_%ux%u%s.png", run->opt.out, name, t->lights, t->width,
             t->height, crop ? "_crop" : "");
    tl_image_desc desc = {.width = w, .height = h, .channels = 3, .type = TL_PIXEL_U8, .bottom_up = 1};
    if (tl_tool_write_image(BENCH_TOOL, path, &desc, rgb)) return 1;
    return bench__note(run, path, rec, crop, t->lights);
}

int bench_aa_images(bench_run *run, const bench_aa_truth *t, const bench_aa_record *rec, const uint8_t *rgb)
{
    uint32_t cw = BENCH_AA_CROP_W < t->width ? BENCH_AA_CROP_W : t->width,
             ch = BENCH_AA_CROP_H < t->height ? BENCH_AA_CROP_H : t->height;
    if (bench__write(run, t, rec, rgb, t->width, t->height, 0)) return 1;
    uint8_t *crop = bench__crop(t, rgb, cw, ch, BENCH_AA_CROP_ZOOM);
    if (!crop) {
        tl_tool_fail(BENCH_TOOL, "out of memory for a crop");
        return 1;
    }
    int err = bench__write(run, t, rec, crop, cw * BENCH_AA_CROP_ZOOM, ch * BENCH_AA_CROP_ZOOM, 1);
    free(crop);
    return err;
}
