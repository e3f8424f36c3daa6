/* GLSL/C parity of albedo: luma/chroma in both colour spaces, the albedo encoding and the
 * edge-directed chroma reconstruction (parity.h). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "parity.h"

/* ---- albedo --------------------------------------------------------------------------------- */

/* Random colours in [0,1]^3, all 4096 colours of the 16^3 grid k/15 (0 and 1 included), a few
 * out-of-range, denormal, Inf and NaN channels. */
static void colour_inputs(fvec *a)
{
    tl_rng rng = {0xC010u};
    for (uint32_t i = 0; i < RANDOM_COUNT; i++)
        fpush3(a, (float)tl_rng_unit(&rng), (float)tl_rng_unit(&rng), (float)tl_rng_unit(&rng));
    for (int r = 0; r < 16; r++)
        for (int g = 0; g < 16; g++)
            for (int b = 0; b < 16; b++) fpush3(a, (float)r / 15.0f, (float)g / 15.0f, (float)b / 15.0f);
    const float s[] = {0.0f, 1.0f, -0.0f, -0.5f, 1.5f, 0x1.0p-149f, INFINITY, -INFINITY, NAN};
    for (size_t i = 0; i < 9; i++)
        for (size_t j = 0; j < 9; j++)
            for (size_t k = 0; k < 9; k++) fpush3(a, s[i], s[j], s[k]);
}

static void parity_luma_chroma(tl_color_space space)
{
    parity_env env;
    if (!env_open(&env)) return;
    const char *name = tl_color_space_name(space);
    fvec a = {0};
    colour_inputs(&a);
    size_t count = a.n / 3;
    uint32_t *expect = xmalloc_u32(a.n), *got = xmalloc_u32(a.n);
    fvec ycc = {0};
    for (size_t i = 0; i < count; i++) {
        float y[3];
        tl_rgb_to_luma_chroma(space, a.v + 3 * i, y);
        for (int k = 0; k < 3; k++) expect[3 * i + k] = f2u(y[k]);
        if (i < RANDOM_COUNT + 4096) fpush3(&ycc, y[0], y[1], y[2]);
    }
    parity_params pp = {.space = (uint32_t)space};
    char what[64];
    snprintf(what, sizeof what, "rgb_to_luma_chroma %s", name);
    if (run_op(&env, OP_RGB_TO_YCC, &pp, (uint32_t)count, a.v, a.n, NULL, 0, got, a.n))
        TL_CHECK_EQ_U(compare_words(what, expect, got, count, 3, describe_xyz, a.v), 0);
    /* Inverse: the forward outputs of the random and grid colours, their 8-bit quantised
     * versions (what the G-buffer stores), random triples in [0,1]^3 (out-of-gamut, clamped)
     * and the special values. */
    size_t nfwd = ycc.n;
    for (size_t i = 0; i < nfwd; i++) fpush(&ycc, roundf(ycc.v[i] * 255.0f) / 255.0f);
    tl_rng rng = {0xC011u};
    for (uint32_t i = 0; i < 16384; i++) fpush(&ycc, (float)tl_rng_unit(&rng));
    for (size_t i = 3 * (RANDOM_COUNT + 4096); i < a.n; i++) fpush(&ycc, a.v[i]);
    size_t icount = ycc.n / 3;
    uint32_t *iexp = xmalloc_u32(ycc.n), *igot = xmalloc_u32(ycc.n);
    for (size_t i = 0; i < icount; i++) {
        float rgb[3];
        tl_luma_chroma_to_rgb(space, ycc.v + 3 * i, rgb);
        for (int k = 0; k < 3; k++) iexp[3 * i + k] = f2u(rgb[k]);
    }
    snprintf(what, sizeof what, "luma_chroma_to_rgb %s", name);
    if (run_op(&env, OP_YCC_TO_RGB, &pp, (uint32_t)icount, ycc.v, ycc.n, NULL, 0, igot, ycc.n))
        TL_CHECK_EQ_U(compare_words(what, iexp, igot, icount, 3, describe_xyz, ycc.v), 0);
    free(iexp);
    free(igot);
    free(ycc.v);
    free(expect);
    free(got);
    free(a.v);
    env_close(&env);
}

TL_TEST(parity_luma_chroma_ycbcr) { parity_luma_chroma(TL_COLOR_SPACE_YCBCR); }
TL_TEST(parity_luma_chroma_ycocg) { parity_luma_chroma(TL_COLOR_SPACE_YCOCG); }

static void parity_albedo(tl_color_space space)
{
    parity_env env;
    if (!env_open(&env)) return;
    fvec a = {0};
    colour_inputs(&a);
    size_t count = a.n / 3;
    uvec px = {0};
    tl_rng rng = {0xA1BEu};
    for (size_t i = 0; i < count; i++) {
        upush(&px, (uint32_t)(tl_rng_u64(&rng) & 0xFFFFu));
        upush(&px, (uint32_t)(tl_rng_u64(&rng) & 0xFFFFu));
    }
    uint32_t *expect = xmalloc_u32(2 * count), *got = xmalloc_u32(2 * count);
    for (size_t i = 0; i < count; i++) {
        uint8_t b[2];
        tl_albedo_encode_pixel(space, a.v + 3 * i, px.v[2 * i], px.v[2 * i + 1], b);
        expect[2 * i] = b[0];
        expect[2 * i + 1] = b[1];
    }
    parity_params pp = {.space = (uint32_t)space};
    char what[64];
    snprintf(what, sizeof what, "albedo_encode_pixel %s", tl_color_space_name(space));
    if (run_op(&env, OP_ALBEDO_ENCODE, &pp, (uint32_t)count, a.v, a.n, px.v, px.n, got, 2 * count))
        TL_CHECK_EQ_U(compare_words(what, expect, got, count, 2, describe_xyz, a.v), 0);
    free(expect);
    free(got);
    free(px.v);
    free(a.v);
    env_close(&env);
}

TL_TEST(parity_albedo_ycbcr) { parity_albedo(TL_COLOR_SPACE_YCBCR); }
TL_TEST(parity_albedo_ycocg) { parity_albedo(TL_COLOR_SPACE_YCOCG); }

/* Same as the C's neighbour mirroring (albedo.c tl__mirror). */
static int mirror(int64_t c, uint32_t n, uint32_t *out)
{
    if (c < 0) c = -c;
    if (c >= (int64_t)n) c = 2 * ((int64_t)n - 1) - c;
    if (c < 0 || c >= (int64_t)n) return 0;
    *out = (uint32_t)c;
    return 1;
}

/* Appends the GLSL arguments for pixel (x, y): luma, nl[4], nc[4], count, with neighbours in the
 * C's order left, right, up (y - 1), down (y + 1), mirrored at the borders. */
static void edge_args(uvec *u, const uint8_t *yc, uint32_t w, uint32_t h, uint32_t x, uint32_t y)
{
    static const int dx[4] = {-1, 1, 0, 0}, dy[4] = {0, 0, -1, 1};
    uint32_t nl[4] = {0}, nc[4] = {0}, count = 0;
    for (int i = 0; i < 4; i++) {
        uint32_t mx, my;
        if (!mirror((int64_t)x + dx[i], w, &mx) || !mirror((int64_t)y + dy[i], h, &my)) continue;
        nl[count] = yc[2 * ((size_t)my * w + mx)];
        nc[count] = yc[2 * ((size_t)my * w + mx) + 1];
        count++;
    }
    upush(u, yc[2 * ((size_t)y * w + x)]);
    for (int i = 0; i < 4; i++) upush(u, nl[i]);
    for (int i = 0; i < 4; i++) upush(u, nc[i]);
    upush(u, count);
}

TL_TEST(parity_albedo_edge_chroma)
{
    parity_env env;
    if (!env_open(&env)) return;
    /* A 96x96 image: 8x8 blocks of random base luma (hard edges between blocks) plus per-pixel
     * noise of up to +-40 (so luma differences straddle the 30/255 threshold), isolated
     * single-pixel features, flat runs (equal lumas: ties for the closest neighbour), random
     * chroma; then thin images (1 pixel wide or high: 2 neighbours; 1x1: none). */
    enum { W = 96, H = 96 };
    static uint8_t yc[W * H * 2];
    tl_rng rng = {0xED6Eu};
    uint8_t base[(W / 8) * (H / 8)];
    for (size_t i = 0; i < sizeof base; i++) base[i] = (uint8_t)(tl_rng_u64(&rng) & 0xFF);
    for (uint32_t y = 0; y < H; y++)
        for (uint32_t x = 0; x < W; x++) {
            int l = base[(y / 8) * (W / 8) + x / 8];
            uint64_t r = tl_rng_u64(&rng);
            if ((r & 15u) == 0) l = (int)((r >> 8) & 0xFF);              /* single-pixel feature */
            else if ((y / 8 + x / 8) % 3 != 0) l += (int)((r >> 16) % 81u) - 40; /* noise */
            yc[2 * (y * W + x)] = (uint8_t)(l < 0 ? 0 : l > 255 ? 255 : l);
            yc[2 * (y * W + x) + 1] = (uint8_t)(r >> 32);
        }
    uvec args = {0};
    fvec expect_f = {0};
    size_t interior = 0;
    for (uint32_t y = 0; y < H; y++)
        for (uint32_t x = 0; x < W; x++) {
            edge_args(&args, yc, W, H, x, y);
            fpush(&expect_f, tl_albedo_missing_chroma(TL_CHROMA_FILTER_EDGE, yc, W, H, x, y));
            interior += x > 0 && y > 0 && x + 1 < W && y + 1 < H;
        }
    /* Thin images taken from the first row / column (and a 1x1 one). */
    static uint8_t row[W * 2], col[H * 2];
    memcpy(row, yc, sizeof row);
    for (uint32_t y = 0; y < H; y++) memcpy(col + 2 * y, yc + 2 * (y * W), 2);
    for (uint32_t x = 0; x < W; x++) {
        edge_args(&args, row, W, 1, x, 0);
        fpush(&expect_f, tl_albedo_missing_chroma(TL_CHROMA_FILTER_EDGE, row, W, 1, x, 0));
    }
    for (uint32_t y = 0; y < H; y++) {
        edge_args(&args, col, 1, H, 0, y);
        fpush(&expect_f, tl_albedo_missing_chroma(TL_CHROMA_FILTER_EDGE, col, 1, H, 0, y));
    }
    edge_args(&args, yc, 1, 1, 0, 0);
    fpush(&expect_f, tl_albedo_missing_chroma(TL_CHROMA_FILTER_EDGE, yc, 1, 1, 0, 0));
    /* Every (centre, neighbour) luma difference class on a small synthetic set: 4 neighbours at
     * luma offsets from -40 to 40 around a centre, covering d = 0, 29, 30, 31 exactly. */
    static const int offs[] = {-40, -31, -30, -29, -15, -1, 0, 1, 15, 29, 30, 31, 40};
    for (size_t i = 0; i < 13; i++)
        for (size_t j = 0; j < 13; j++) {
            uint8_t img[3 * 3 * 2];
            for (int k = 0; k < 9; k++) {
                img[2 * k] = 128;
                img[2 * k + 1] = (uint8_t)(tl_rng_u64(&rng) & 0xFF);
            }
            img[2 * 3] = (uint8_t)(128 + offs[i]);     /* left */
            img[2 * 5] = (uint8_t)(128 + offs[j]);     /* right */
            img[2 * 1] = (uint8_t)(128 + offs[12 - i]); /* up */
            img[2 * 7] = (uint8_t)(128 + offs[(i + j) % 13]); /* down */
            edge_args(&args, img, 3, 3, 1, 1);
            fpush(&expect_f, tl_albedo_missing_chroma(TL_CHROMA_FILTER_EDGE, img, 3, 3, 1, 1));
        }
    size_t count = expect_f.n;
    uint32_t *expect = xmalloc_u32(count), *got = xmalloc_u32(count);
    for (size_t i = 0; i < count; i++) expect[i] = f2u(expect_f.v[i]);
    if (run_op(&env, OP_EDGE_CHROMA, NULL, (uint32_t)count, NULL, 0, args.v, args.n, got, count)) {
        printf("(%zu interior pixels of %dx%d, %zu border, thin-image and synthetic pixels)\n", interior, W, H,
               count - interior);
        TL_CHECK_EQ_U(compare_words("albedo_edge_chroma", expect, got, count, 1, NULL, NULL), 0);
    }
    free(expect);
    free(got);
    free(expect_f.v);
    free(args.v);
    env_close(&env);
}
