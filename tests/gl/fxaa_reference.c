/* FXAA (shaders/fxaa.frag.glsl) against the same algorithm run in double on the CPU, pixel by
 * pixel, for each preset, through tl_renderer_apply_fxaa on a generated image: smooth gradients,
 * edges at irrational slopes, a disc, one-pixel lines and noise.
 *
 * The reference reads the LDR target the luma pass wrote (RGB and 8-bit luma, read back), samples
 * it as GL does (clamp to edge, bilinear between texel centres) and takes every decision of the
 * shader: the contrast test, the edge's orientation and side, the search's ends, the blend.
 * llvmpipe filters 8-bit textures in 8-bit fixed point: a luma sampled between texels comes back
 * within one 8-bit step of the exact mean, so a decision whose two sides differ by less than
 * DECIDE_EPS (one step, 1/255) is undecided and the pixel is left out (a quarter at most; the test
 * image has many exact ties and one-pixel lines). The rest must match within one output step (the
 * final sample is an 8-bit value) plus 2^-9 of the two texels it blends (8-bit filter weights). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render_room.h"
#include "tl_test.h"

#define DECIDE_EPS (1.0 / 255.0)

typedef struct fx_image {
    int w, h;
    const float *ldr; /* RGBA in [0,1]: colour and luma (alpha), 8-bit values */
} fx_image;

/* Bilinear sample at uv (texture coordinates), clamp to edge. */
static void fx_sample(const fx_image *im, double u, double v, double out[4])
{
    double x = u * im->w - 0.5, y = v * im->h - 0.5, fx = x - floor(x), fy = y - floor(y);
    int x0 = (int)floor(x), y0 = (int)floor(y);
    for (int c = 0; c < 4; c++) out[c] = 0.0;
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 2; i++) {
            int xx = x0 + i < 0 ? 0 : x0 + i >= im->w ? im->w - 1 : x0 + i;
            int yy = y0 + j < 0 ? 0 : y0 + j >= im->h ? im->h - 1 : y0 + j;
            double wgt = (i ? fx : 1.0 - fx) * (j ? fy : 1.0 - fy);
            for (int c = 0; c < 4; c++) out[c] += wgt * im->ldr[4 * ((size_t)yy * im->w + xx) + c];
        }
}

static double fx_luma(const fx_image *im, double u, double v)
{
    double s[4];
    fx_sample(im, u, v, s);
    return s[3];
}

typedef struct fx_params {
    int steps; /* 5 or 12 */
    const double *step;
    double threshold, threshold_min, subpix;
} fx_params;

/* One pixel: 1 with the expected colour (0..255) and the larger difference of the two texels the
 * final sample blends; 0 when a decision is undecided. */
static int fx_pixel(const fx_image *im, const fx_params *p, int x, int y, double out[3], double *blend_span)
{
    const double rx = 1.0 / im->w, ry = 1.0 / im->h, u = (x + 0.5) * rx, v = (y + 0.5) * ry;
    double centre[4];
    fx_sample(im, u, v, centre);
    double lm = centre[3], ln = fx_luma(im, u, v + ry), ls = fx_luma(im, u, v - ry), le = fx_luma(im, u + rx, v),
           lw = fx_luma(im, u - rx, v);
    double lmax = fmax(fmax(fmax(ln, ls), fmax(le, lw)), lm), lmin = fmin(fmin(fmin(ln, ls), fmin(le, lw)), lm);
    double range = lmax - lmin, limit = fmax(p->threshold_min, lmax * p->threshold);
    *blend_span = 0.0;
    if (fabs(range - limit) < DECIDE_EPS) return 0;
    if (range < limit) {
        for (int c = 0; c < 3; c++) out[c] = 255.0 * centre[c];
        return 1;
    }
    double lne = fx_luma(im, u + rx, v + ry), lnw = fx_luma(im, u - rx, v + ry), lse = fx_luma(im, u + rx, v - ry),
           lsw = fx_luma(im, u - rx, v - ry);
    double lowpass = (2.0 * (ln + ls + le + lw) + (lne + lnw + lse + lsw)) / 12.0;
    double sa = fmin(fmax(fabs(lowpass - lm) / range, 0.0), 1.0), sb = (-2.0 * sa + 3.0) * sa * sa;
    double subpix = sb * sb * p->subpix;
    double horz = fabs(lnw - 2.0 * lw + lsw) + 2.0 * fabs(ln - 2.0 * lm + ls) + fabs(lne - 2.0 * le + lse);
    double vert = fabs(lnw - 2.0 * ln + lne) + 2.0 * fabs(lw - 2.0 * lm + le) + fabs(lsw - 2.0 * ls + lse);
    if (fabs(horz - vert) < DECIDE_EPS) return 0;
    int horizontal = horz >= vert;
    double l_neg = horizontal ? ls : lw, l_pos = horizontal ? ln : le, g_neg = fabs(l_neg - lm), g_pos = fabs(l_pos - lm);
    if (fabs(g_neg - g_pos) < DECIDE_EPS) return 0;
    int neg_steeper = g_neg >= g_pos;
    double step_len = horizontal ? ry : rx, local_avg = 0.5 * ((neg_steeper ? l_neg : l_pos) + lm);
    double grad_scaled = 0.25 * fmax(g_neg, g_pos);
    if (neg_steeper) step_len = -step_len;
    double eu = u + (horizontal ? 0.0 : 0.5 * step_len), ev = v + (horizontal ? 0.5 * step_len : 0.0);
    double au = horizontal ? rx : 0.0, av = horizontal ? 0.0 : ry;
    double u1 = eu - au, v1 = ev - av, u2 = eu + au, v2 = ev + av;
    double e1 = fx_luma(im, u1, v1) - local_avg, e2 = fx_luma(im, u2, v2) - local_avg;
    if (fabs(fabs(e1) - grad_scaled) < DECIDE_EPS || fabs(fabs(e2) - grad_scaled) < DECIDE_EPS) return 0;
    int done1 = fabs(e1) >= grad_scaled, done2 = fabs(e2) >= grad_scaled;
    for (int i = 1; i < p->steps && !(done1 && done2); i++) {
        if (!done1) {
            u1 -= au * p->step[i], v1 -= av * p->step[i];
            e1 = fx_luma(im, u1, v1) - local_avg;
            if (fabs(fabs(e1) - grad_scaled) < DECIDE_EPS) return 0;
            done1 = fabs(e1) >= grad_scaled;
        }
        if (!done2) {
            u2 += au * p->step[i], v2 += av * p->step[i];
            e2 = fx_luma(im, u2, v2) - local_avg;
            if (fabs(fabs(e2) - grad_scaled) < DECIDE_EPS) return 0;
            done2 = fabs(e2) >= grad_scaled;
        }
    }
    double d1 = horizontal ? u - u1 : v - v1, d2 = horizontal ? u2 - u : v2 - v;
    if (fabs(d1 - d2) < DECIDE_EPS * rx) return 0;
    int nearer1 = d1 < d2;
    double offset = 0.5 - fmin(d1, d2) / (d1 + d2), en = nearer1 ? e1 : e2;
    if (fabs(lm - local_avg) < DECIDE_EPS || fabs(en) < DECIDE_EPS) return 0;
    int good = (en < 0.0) != (lm < local_avg);
    double final_offset = fmax(good ? offset : 0.0, subpix);
    double fu = u + (horizontal ? 0.0 : final_offset * step_len), fv = v + (horizontal ? final_offset * step_len : 0.0);
    double s[4], far[4];
    fx_sample(im, fu, fv, s);
    fx_sample(im, u + (horizontal ? 0.0 : step_len), v + (horizontal ? step_len : 0.0), far);
    for (int c = 0; c < 3; c++) {
        out[c] = 255.0 * s[c];
        *blend_span = fmax(*blend_span, 255.0 * fabs(far[c] - centre[c]));
    }
    return 1;
}

/* Smooth gradients, a disc, two edges at irrational slopes, one-pixel lines and a little noise. */
static void fx_test_image(uint8_t *rgba, int w, int h)
{
    tl_rng rng = {0xF8A4u};
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double r = 40.0 + 150.0 * x / w, g = 60.0 + 120.0 * y / h, b = 90.0;
            double dx = x + 0.5 - 0.3 * w, dy = y + 0.5 - 0.5 * h;
            if (dx * dx + dy * dy < 0.09 * h * h) r = 230.0, g = 200.0, b = 40.0;
            if (y + 0.5 > 0.41421356 * (x + 0.5) + 0.6 * h) r *= 0.25, g *= 0.3, b = 220.0;
            if (x + 0.5 > 0.7 * w + 0.17320508 * (y + 0.5)) r = 250.0 - r * 0.5, g *= 0.5;
            if (x % 23 == 7 || y % 19 == 11) r = g = b = 20.0;
            double noise = 6.0 * (tl_rng_unit(&rng) - 0.5);
            uint8_t *p = rgba + 4 * ((size_t)y * w + x);
            p[0] = (uint8_t)fmin(fmax(r + noise, 0.0), 255.0);
            p[1] = (uint8_t)fmin(fmax(g + noise, 0.0), 255.0);
            p[2] = (uint8_t)fmin(fmax(b + noise, 0.0), 255.0);
            p[3] = 255;
        }
}

TL_TEST(fxaa_matches_cpu_reference_every_preset)
{
    const int w = 160, h = 96;
    const size_t n = (size_t)w * h;
    TL_CHECK(ensure_context());
    if (!g_ctx) return;
    static const double steps5[5] = {1.0, 1.5, 2.0, 4.0, 12.0};
    static const double steps29[12] = {1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0};
    static const double steps39[12] = {1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 4.0, 8.0};
    const struct { tl_fxaa_preset preset; fx_params p; } presets[] = {
        {TL_FXAA_12, {5, steps5, 0.166, 0.0833, 0.75}},
        {TL_FXAA_29, {12, steps29, 0.166, 0.0833, 0.75}},
        {TL_FXAA_39, {12, steps39, 0.125, 0.0625, 0.5}},
    };
    uint8_t *img = malloc(n * 4), *out = malloc(n * 4);
    float *ldr = malloc(n * 4 * sizeof *ldr);
    TL_CHECK(img && out && ldr);
    if (!img || !out || !ldr) return;
    fx_test_image(img, w, h);
    for (size_t k = 0; k < sizeof presets / sizeof presets[0]; k++) {
        const fx_params *p = &presets[k].p;
        tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
            .renderer = {.width = (uint32_t)w, .height = (uint32_t)h, .options.fxaa = presets[k].preset,
                         .options.fxaa_edge_threshold = (float)p->threshold,
                         .options.fxaa_edge_threshold_min = (float)p->threshold_min, .options.fxaa_subpix = (float)p->subpix},
            .readable = true});
        size_t size = n * 4 * sizeof *ldr;
        int ok = r && tl_renderer_apply_fxaa(r, img, out, &(size_t){n * 4}) == TL_OK &&
                 tl_renderer_read_target(r, TL_TARGET_LDR, ldr, &size) == TL_OK;
        TL_CHECK(ok);
        if (!ok) {
            tl_renderer_destroy(r);
            continue;
        }
        fx_image im = {w, h, ldr};
        size_t decided = 0, changed = 0, bad = 0;
        double worst = 0.0;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                double want[3], span;
                if (!fx_pixel(&im, p, x, y, want, &span)) continue;
                decided++;
                const uint8_t *got = out + 4 * ((size_t)y * w + x), *in = img + 4 * ((size_t)y * w + x);
                int moved = 0;
                double e = 0.0;
                for (int c = 0; c < 3; c++) {
                    e = fmax(e, fabs(got[c] - want[c]) / (1.0 + span * 0x1.0p-9 + 1e-9));
                    moved |= got[c] != in[c];
                }
                worst = fmax(worst, e);
                changed += moved;
                if (e > 1.0 && bad++ < 3)
                    printf("    (%d, %d): %d %d %d, reference %.2f %.2f %.2f\n", x, y, got[0], got[1], got[2], want[0],
                           want[1], want[2]);
            }
        printf("  preset %d: %zu of %zu pixels decided, %zu of them changed by FXAA; worst %.3f of the tolerance\n",
               (int)presets[k].preset, decided, n, changed, worst);
        TL_CHECK(decided * 4 >= n * 3);
        TL_CHECK(changed > n / 20); /* the image has edges FXAA works on */
        TL_CHECK_LE(worst, 1.0);
        tl_renderer_destroy(r);
    }
    free(img);
    free(out);
    free(ldr);
}
