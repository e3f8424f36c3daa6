/* Edge pixels, where a reduced light buffer can halo: within BENCH_EDGE_RADIUS pixels of a depth
 * discontinuity or a normal crease of the fat reference's frame (its DEPTH target's linear view
 * depth and its FAT_NORMAL target, read back after an extra frame of fat with those targets kept).
 * A discontinuity is a second difference of the linear depth along x or y over BENCH_EDGE_DEPTH of
 * the depth: on a plane the second difference of linear depth is 2 (dz/z)^2 z per pixel, under 2 %
 * unless a pixel spans 10 % of the depth, so planes seen at a slant are not edges, while a step of
 * 2 % or more (a silhouette, a box's edge in front of the floor) is, on both of its sides. A crease is
 * two 4-neighbours whose normals are more than BENCH_EDGE_CREASE_DEG apart; a pixel without a
 * surface (no finite depth, or a zero normal) beside one with a surface counts as a discontinuity. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

static int bench__surface(const float *depth, const float *normal, size_t i)
{
    const float *n = normal + 4 * i;
    float d = depth[4 * i + 1];
    return isfinite(d) && d > 0.0f && n[0] * n[0] + n[1] * n[1] + n[2] * n[2] > 1e-6f;
}

/* Pixel i against its neighbours i - step and i + step (both inside the frame). */
static int bench__depth_step(const float *depth, const float *normal, size_t i, size_t step)
{
    int a = bench__surface(depth, normal, i - step), b = bench__surface(depth, normal, i),
        c = bench__surface(depth, normal, i + step);
    if (!b) return a || c;
    if (!a || !c) return 1;
    double d0 = depth[4 * (i - step) + 1], d1 = depth[4 * i + 1], d2 = depth[4 * (i + step) + 1];
    return fabs(d0 + d2 - 2.0 * d1) > BENCH_EDGE_DEPTH * d1;
}

static int bench__crease(const float *normal, size_t i, size_t j)
{
    const float *a = normal + 4 * i, *b = normal + 4 * j;
    double la = sqrt((double)a[0] * a[0] + (double)a[1] * a[1] + (double)a[2] * a[2]),
           lb = sqrt((double)b[0] * b[0] + (double)b[1] * b[1] + (double)b[2] * b[2]);
    if (!(la > 1e-3) || !(lb > 1e-3)) return 0; /* no surface: the depth test decides */
    double c = ((double)a[0] * b[0] + (double)a[1] * b[1] + (double)a[2] * b[2]) / (la * lb);
    return c < cos(BENCH_EDGE_CREASE_DEG * 3.14159265358979323846 / 180.0);
}

/* The seeds: pixels on a discontinuity or a crease (mask = 1). */
static void bench__seeds(const float *depth, const float *normal, uint32_t w, uint32_t h, uint8_t *mask)
{
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            int e = (x > 0 && x + 1 < w && bench__depth_step(depth, normal, i, 1)) ||
                    (y > 0 && y + 1 < h && bench__depth_step(depth, normal, i, w));
            if (x + 1 < w && bench__crease(normal, i, i + 1)) e = mask[i + 1] = 1;
            if (y + 1 < h && bench__crease(normal, i, i + w)) e = mask[i + w] = 1;
            if (e) mask[i] = 1;
        }
}

size_t bench_edges_mask(const float *depth, const float *normal, uint32_t w, uint32_t h, uint8_t *mask)
{
    size_t n = (size_t)w * h, count = 0;
    uint8_t *seed = calloc(n ? n : 1, 1), *row = calloc(n ? n : 1, 1);
    if (!seed || !row) {
        free(seed);
        free(row);
        memset(mask, 0, n);
        return 0;
    }
    bench__seeds(depth, normal, w, h, seed);
    const int r = (int)BENCH_EDGE_RADIUS; /* dilation by a (2r + 1) square: rows, then columns */
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            uint8_t v = 0;
            for (int k = -r; k <= r && !v; k++)
                if ((int)x + k >= 0 && (int)x + k < (int)w) v = seed[(size_t)y * w + (size_t)((int)x + k)];
            row[(size_t)y * w + x] = v;
        }
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            uint8_t v = 0;
            for (int k = -r; k <= r && !v; k++)
                if ((int)y + k >= 0 && (int)y + k < (int)h) v = row[(size_t)((int)y + k) * w + x];
            mask[(size_t)y * w + x] = v;
            count += v;
        }
    free(seed);
    free(row);
    return count;
}

void bench_edges_compare(const uint8_t *a, const uint8_t *b, const uint8_t *mask, size_t pixels, tl_image_error *out)
{
    size_t n = 0;
    for (size_t i = 0; i < pixels; i++) n += mask[i] != 0;
    memset(out, 0, sizeof *out);
    uint8_t *ea = malloc(3 * (n ? n : 1)), *eb = malloc(3 * (n ? n : 1));
    if (ea && eb && n) {
        size_t k = 0;
        for (size_t i = 0; i < pixels; i++)
            if (mask[i]) {
                memcpy(ea + 3 * k, a + 3 * i, 3);
                memcpy(eb + 3 * k, b + 3 * i, 3);
                k++;
            }
        tl_image_compare_u8(ea, eb, 3 * n, out);
    }
    free(ea);
    free(eb);
}
