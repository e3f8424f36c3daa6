/* Bloom (issue 14, docs/effects.md): off, it plans nothing and changes no byte; its half-size mip
 * chain has the sizes the plan promises (odd sizes round up, never 0) and is counted in the plan's
 * memory; with threshold 0 the chain conserves the energy of an HDR image written by an
 * application pass, within the FP16 rounding of its steps; a bright block at the centre spreads
 * mirror-symmetrically and a bright pixel does not move; nothing is NaN or Inf on 1x1 and 7x3
 * targets or with HDR at the FP16 maximum. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl/gl.h"
#include "render_fixture.h"
#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"
#include "tl_test.h"

#define BIT(t) TL_TARGET_BIT(t)

static const tl_render_mode k_modes[] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD,
                                         TL_MODE_VISIBILITY};
#define K_MODES ((int)(sizeof k_modes / sizeof k_modes[0]))
static const tl_light_strategy k_strategies[2] = {TL_LIGHT_STRATEGY_VOLUMES, TL_LIGHT_STRATEGY_TILED};

static tl_renderer *renderer(tl_renderer_desc d, const tl_scene *s)
{
    return tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .scene = s});
}

static tl_scene *small_scene(void)
{
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 8, .detail = 1}, &s) == TL_OK);
    return s;
}

static int plan_has_pass(const tl_frame_plan *p, tl_pass pass)
{
    for (size_t i = 0; i < p->pass_count; i++)
        if (p->passes[i].pass == pass) return 1;
    return 0;
}

static float *read_target(tl_renderer *r, tl_target_id t, size_t *count)
{
    size_t size = 0;
    TL_CHECK(tl_renderer_read_target(r, t, NULL, &size) == TL_OK);
    float *p = malloc(size ? size : 1);
    TL_CHECK(p && tl_renderer_read_target(r, t, p, &size) == TL_OK);
    *count = size / (4 * sizeof(float));
    return p;
}

/* ---- planning -------------------------------------------------------------------------------- */

/* GL's mip chain of a w x h level 0: levels while the larger side >= 2^level, at most `want`. */
static uint32_t expected_levels(uint32_t w, uint32_t h, uint32_t want)
{
    uint32_t side = w > h ? w : h, n = 1;
    while (n < want && (side >> n) >= 1) n++;
    return n;
}

TL_TEST(bloom_plan_half_size_chain_rounds_up)
{
    static const uint32_t sizes[][2] = {{1, 1}, {7, 3}, {2, 1}, {3, 5}, {1280, 720}, {1281, 719}, {16384, 1}};
    tl_scene_feature_set f = {.point_lights = 1, .has_specular = 1};
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
        for (uint32_t want = 1; want <= 8; want += 7) {
            uint32_t w = sizes[i][0], h = sizes[i][1];
            tl_renderer_desc d = {.width = w, .height = h, .options.bloom = {.enabled = 1, .levels = want}};
            tl_frame_plan p;
            TL_CHECK(tl_frame_plan_build(&d, &f, &p) == TL_OK);
            const tl_plan_target *t = &p.target_info[TL_TARGET_BLOOM];
            uint32_t w0 = (w + 1) / 2, h0 = (h + 1) / 2;
            TL_CHECK_EQ_U(t->width, w0);
            TL_CHECK_EQ_U(t->height, h0);
            TL_CHECK(t->width >= 1 && t->height >= 1);
            TL_CHECK_EQ_U(t->levels, expected_levels(w0, h0, want));
            size_t bytes = 0;
            for (uint32_t k = 0; k < t->levels; k++) {
                size_t lw = w0 >> k, lh = h0 >> k;
                bytes += (lw ? lw : 1) * (lh ? lh : 1) * 8u; /* RGBA16F */
            }
            size_t px = (size_t)w * h;
            TL_CHECK_EQ_U(t->bytes, bytes);
            TL_CHECK_EQ_U(t->bytes_per_pixel, (bytes + px - 1) / px);
            /* memory of its own, counted once in the allocation */
            TL_CHECK_EQ_U(p.blocks[t->block].targets, BIT(TL_TARGET_BLOOM));
            size_t blocks = 0;
            for (size_t b = 0; b < p.block_count; b++)
                for (int k = 0; k < TL_TARGET_COUNT; k++)
                    if (p.blocks[b].targets & BIT(k)) {
                        blocks += p.target_info[k].bytes;
                        break;
                    }
            TL_CHECK_EQ_U(p.allocated_bytes, blocks);
            /* the bloom pass, then tone mapping reading it */
            TL_CHECK(plan_has_pass(&p, TL_PASS_BLOOM));
            for (size_t k = 0; k < p.pass_count; k++)
                if (p.passes[k].pass == TL_PASS_TONEMAP) TL_CHECK(p.passes[k].reads & BIT(TL_TARGET_BLOOM));
            char text[8192];
            TL_CHECK(tl_frame_plan_format(&p, text, sizeof text) < sizeof text);
            char want_text[96]; /* the size and levels when they are not the frame's */
            snprintf(want_text, sizeof want_text, "(%ux%u, %u level", w0, h0, t->levels);
            TL_CHECK((strstr(text, want_text) != NULL) == (w0 != w || h0 != h || t->levels > 1));
        }
}

/* Off (zeroed, or enabled = 0 with other fields set): no pass, no target, the same plan bit for bit;
 * on: the pass in every mode and strategy. */
TL_TEST(bloom_off_plans_nothing_in_every_mode)
{
    tl_scene_feature_set f = {.point_lights = 40, .directional_lights = 1, .has_specular = 1};
    for (int m = 0; m < K_MODES; m++)
        for (int s = 0; s < 2; s++) {
            tl_renderer_desc d = {.options.mode = k_modes[m], .options.light_strategy = k_strategies[s], .width = 320,
                                  .height = 180};
            tl_frame_plan off, off_fields, on;
            TL_CHECK(tl_frame_plan_build(&d, &f, &off) == TL_OK);
            tl_renderer_desc e = d;
            e.options.bloom = (tl_bloom_desc){.enabled = 0, .threshold = 3, .knee = 0.2f, .intensity = 2,
                                              .scatter = 0.3f, .levels = 2};
            TL_CHECK(tl_frame_plan_build(&e, &f, &off_fields) == TL_OK);
            TL_CHECK(memcmp(&off, &off_fields, sizeof off) == 0);
            TL_CHECK(!plan_has_pass(&off, TL_PASS_BLOOM) && !(off.targets & BIT(TL_TARGET_BLOOM)));
            TL_CHECK_EQ_U(off.target_info[TL_TARGET_BLOOM].bytes, 0);
            e.options.bloom.enabled = 1;
            TL_CHECK(tl_frame_plan_build(&e, &f, &on) == TL_OK);
            TL_CHECK(plan_has_pass(&on, TL_PASS_BLOOM) && (on.targets & BIT(TL_TARGET_BLOOM)));
            TL_CHECK_EQ_U(on.allocated_bytes, off.allocated_bytes + on.target_info[TL_TARGET_BLOOM].bytes);
        }
}

TL_TEST(bloom_options_out_of_range_are_refused)
{
    tl_scene_feature_set f = {.point_lights = 1};
    const tl_bloom_desc bad[] = {{.enabled = 1, .levels = 9},      {.enabled = 1, .knee = 1.5f},
                                 {.enabled = 1, .scatter = 1.5f},  {.enabled = 1, .intensity = INFINITY},
                                 {.enabled = 1, .threshold = NAN}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        tl_renderer_desc d = {.options.bloom = bad[i]};
        tl_frame_plan p;
        TL_CHECK(tl_frame_plan_build(&d, &f, &p) == TL_ERROR_INVALID_ARGUMENT);
    }
}

/* ---- rendering ------------------------------------------------------------------------------- */

/* Bloom off renders what a renderer with the bloom fields zeroed renders, byte for byte, in every
 * mode and strategy; bloom on renders (finite HDR, a different image). */
TL_TEST(bloom_off_renders_identical_bytes_in_every_mode)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_scene *s = small_scene();
    if (!s) return;
    const uint32_t w = 96, h = 64;
    size_t n = (size_t)w * h * 4;
    uint8_t *a = malloc(n), *b = malloc(n), *c = malloc(n);
    for (int m = 0; m < K_MODES && a && b && c; m++)
        for (int st = 0; st < 2; st++) {
            tl_renderer_desc d = {.options.mode = k_modes[m], .options.light_strategy = k_strategies[st], .width = w,
                                  .height = h};
            tl_renderer_desc e = d;
            e.options.bloom = (tl_bloom_desc){.enabled = 0, .threshold = 0.1f, .intensity = 5, .levels = 3};
            tl_renderer_desc on = d;
            on.options.bloom = (tl_bloom_desc){.enabled = 1, .threshold = 0.05f, .intensity = 1};
            tl_renderer *r0 = renderer(d, s), *r1 = renderer(e, s), *r2 = renderer(on, s);
            size_t sa = n, sb = n, sc = n;
            if (r0 && r1 && r2) {
                TL_CHECK(tl_renderer_render(r0, NULL, NULL) == TL_OK && tl_renderer_read_output(r0, a, &sa) == TL_OK);
                TL_CHECK(tl_renderer_render(r1, NULL, NULL) == TL_OK && tl_renderer_read_output(r1, b, &sb) == TL_OK);
                TL_CHECK(tl_renderer_render(r2, NULL, NULL) == TL_OK && tl_renderer_read_output(r2, c, &sc) == TL_OK);
                size_t differ = 0, brighter = 0;
                for (size_t i = 0; i < n; i++) {
                    differ += a[i] != b[i];
                    brighter += c[i] > a[i];
                }
                TL_CHECK_EQ_U(differ, 0);
                TL_CHECK(brighter > 0);
                tl_frame_plan p;
                TL_CHECK(tl_renderer_get_plan(r2, &p) == TL_OK && plan_has_pass(&p, TL_PASS_BLOOM));
            }
            tl_renderer_destroy(r0);
            tl_renderer_destroy(r1);
            tl_renderer_destroy(r2);
        }
    free(a);
    free(b);
    free(c);
    tl_scene_destroy(s);
}

/* An application pass before bloom that replaces HDR with a test image (a blit from a float
 * texture of the same size). */
typedef struct hdr_source {
    const GladGLContext *gl;
    GLuint texture, fbo;
    uint32_t w, h;
} hdr_source;

static void hdr_source_execute(void *user, const tl_app_pass_context *ctx)
{
    hdr_source *src = (hdr_source *)user;
    src->gl->BlitNamedFramebuffer(src->fbo, ctx->framebuffer, 0, 0, (GLint)src->w, (GLint)src->h, 0, 0, (GLint)src->w,
                                  (GLint)src->h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

static GLADapiproc fixture_load(void *user, const char *name)
{
    return (GLADapiproc)tl_context_get_proc_address((tl_context *)user, name);
}

/* The source texture and framebuffer; 0, counted as a test failure, when rgba is NULL (its
 * allocation failed) or GL fails. */
static int hdr_source_make(hdr_source *src, GladGLContext *gl, uint32_t w, uint32_t h, const float *rgba)
{
    char msg[256];
    memset(src, 0, sizeof *src);
    if (!rgba || tl__gl_load(gl, fixture_load, g_ctx, msg, sizeof msg) != TL_OK) {
        if (rgba) fprintf(stderr, "glad: %s\n", msg);
        tl_test_failures++;
        return 0;
    }
    src->gl = gl;
    src->w = w;
    src->h = h;
    gl->CreateTextures(GL_TEXTURE_2D, 1, &src->texture);
    gl->TextureStorage2D(src->texture, 1, GL_RGBA32F, (GLsizei)w, (GLsizei)h);
    gl->TextureSubImage2D(src->texture, 0, 0, 0, (GLsizei)w, (GLsizei)h, GL_RGBA, GL_FLOAT, rgba);
    gl->CreateFramebuffers(1, &src->fbo);
    gl->NamedFramebufferTexture(src->fbo, GL_COLOR_ATTACHMENT0, src->texture, 0);
    if (gl->CheckNamedFramebufferStatus(src->fbo, GL_READ_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) return 1;
    tl_test_failures++;
    return 0;
}

static void hdr_source_free(hdr_source *src)
{
    if (!src->gl) return;
    src->gl->DeleteFramebuffers(1, &src->fbo);
    src->gl->DeleteTextures(1, &src->texture);
}

/* A renderer whose HDR, just before the bloom pass, is `rgba` (w x h); HDR and bloom kept. */
static tl_renderer *bloom_renderer(const tl_scene *s, uint32_t w, uint32_t h, tl_bloom_desc bloom, hdr_source *src)
{
    tl_app_pass_desc ap = {.name = "test-image", .before = "bloom", .writes = BIT(TL_TARGET_HDR),
                           .execute = hdr_source_execute, .user = src};
    return tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.width = w, .height = h, .options.fxaa = TL_FXAA_OFF, .options.bloom = bloom,
                     .options.keep_targets = BIT(TL_TARGET_HDR) | BIT(TL_TARGET_BLOOM)},
        .scene = s, .passes = &ap, .pass_count = 1, .frames = 1});
}

/* Threshold 0: four times the sum of the half-size bloom image is the sum of HDR (the 13-tap
 * downsample and the tent upsample keep the mean, the blends are convex). The image lies far from
 * the borders (clamp-to-edge would add mass there). Every written level is converted to FP16, by
 * rounding (relative 2^-11) or truncation (2^-10: GL leaves the mode open, llvmpipe's sums come out
 * low), on a path of at most 2 levels - 1 writes, all terms non-negative: the relative error of the
 * sum is at most (1 + 2^-10)^(2 levels - 1) - 1, plus float arithmetic in the shaders
 * (at most 13 taps of 24-bit products per step: 2 levels x 16 x 2^-24). The taps fall on texel
 * corners, where the bilinear weights (1/4) are exact. */
TL_TEST(bloom_chain_conserves_energy_threshold_zero)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_scene *s = small_scene();
    if (!s) return;
    const uint32_t w = 256, h = 256, levels = 3;
    float *img = calloc((size_t)w * h * 4, sizeof *img);
    uint32_t seed = 12345u;
    for (uint32_t y = 96; img && y < 160; y++)
        for (uint32_t x = 96; x < 160; x++)
            for (int k = 0; k < 3; k++) {
                seed = seed * 1664525u + 1013904223u;
                img[4 * ((size_t)y * w + x) + k] = (float)(seed >> 24) * 0.25f; /* 0..63.75, exact in FP16 */
            }
    GladGLContext gl;
    hdr_source src;
    if (!hdr_source_make(&src, &gl, w, h, img)) {
        free(img);
        tl_scene_destroy(s);
        return;
    }
    tl_renderer *r = bloom_renderer(s, w, h, (tl_bloom_desc){.enabled = 1, .threshold = -1, .knee = -1, .levels = levels}, &src);
    if (r) {
        size_t nh = 0, nb = 0;
        float *hdr = read_target(r, TL_TARGET_HDR, &nh), *bl = read_target(r, TL_TARGET_BLOOM, &nb);
        TL_CHECK_EQ_U(nh, (size_t)w * h);
        TL_CHECK_EQ_U(nb, (size_t)(w / 2) * (h / 2));
        double tol = pow(1.0 + ldexp(1.0, -10), 2.0 * levels - 1.0) - 1.0 + 2.0 * levels * 16.0 * ldexp(1.0, -24);
        for (int k = 0; hdr && bl && k < 3; k++) {
            double sh = 0, sb = 0;
            for (size_t i = 0; i < nh; i++) sh += hdr[4 * i + k];
            for (size_t i = 0; i < nb; i++) sb += bl[4 * i + k];
            double rel = fabs(4.0 * sb - sh) / sh;
            printf("channel %d: HDR sum %.6g, 4 x bloom sum %.6g, relative error %.3g (bound %.3g)\n", k, sh, 4.0 * sb,
                   rel, tol);
            TL_CHECK(sh > 0);
            TL_CHECK_LE(rel, tol);
        }
        free(hdr);
        free(bl);
        tl_renderer_destroy(r);
    }
    hdr_source_free(&src);
    free(img);
    tl_scene_destroy(s);
}

/* The centroid of the bloom image (level 0, in HDR pixels) and its sum, channel 0. */
static void centroid(const float *b, uint32_t bw, uint32_t bh, double *cx, double *cy, double *sum)
{
    double sx = 0, sy = 0, s = 0;
    for (uint32_t y = 0; y < bh; y++)
        for (uint32_t x = 0; x < bw; x++) {
            double v = b[4 * ((size_t)y * bw + x)];
            s += v;
            sx += v * (2.0 * x + 1.0); /* a level-0 texel centre in HDR pixels */
            sy += v * (2.0 * y + 1.0);
        }
    *cx = sx / s;
    *cy = sy / s;
    *sum = s;
}

/* A 2x2 block at the centre of a 64x64 image is mirror-symmetric about the centre in x, in y and
 * across the diagonal, and so is every level of the chain: the bloom image must be too, within the
 * FP16 rounding of its values (mirrored pixels are computed by mirrored, not identical, sums:
 * 2^-10 relative per written level). A single pixel elsewhere, far from the borders, keeps its
 * centroid within one HDR pixel (a level-0 texel is two; the response is not a mirror image of
 * itself there). */
TL_TEST(bloom_bright_pixel_spreads_symmetrically_without_shift)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_scene *s = small_scene();
    if (!s) return;
    for (int single = 0; single < 2; single++) {
        /* the single pixel far from the borders, whose clamp-to-edge would pull the centroid inwards */
        const uint32_t w = single ? 256 : 64, h = w, levels = single ? 3 : 5;
        float *img = calloc((size_t)w * h * 4, sizeof *img);
        const uint32_t px = single ? 121 : 31, py = single ? 138 : 31;
        for (uint32_t y = py; img && y <= py + (single ? 0u : 1u); y++)
            for (uint32_t x = px; x <= px + (single ? 0u : 1u); x++)
                for (int k = 0; k < 3; k++) img[4 * ((size_t)y * w + x) + k] = 1000.0f;
        GladGLContext gl;
        hdr_source src;
        if (!hdr_source_make(&src, &gl, w, h, img)) {
            free(img);
            break;
        }
        tl_renderer *r = bloom_renderer(s, w, h, (tl_bloom_desc){.enabled = 1, .threshold = -1, .levels = levels}, &src);
        size_t nb = 0;
        float *b = r ? read_target(r, TL_TARGET_BLOOM, &nb) : NULL;
        const uint32_t bw = w / 2, bh = h / 2;
        if (b && nb == (size_t)bw * bh) {
            double cx, cy, sum, worst = 0, tol = levels * 2.0 * ldexp(1.0, -10);
            centroid(b, bw, bh, &cx, &cy, &sum);
            double ex = px + (single ? 0.5 : 1.0), ey = py + (single ? 0.5 : 1.0);
            printf("%s: centroid (%.4f, %.4f), expected (%.1f, %.1f)\n", single ? "single pixel" : "centre block", cx, cy,
                   ex, ey);
            TL_CHECK(sum > 0);
            TL_CHECK_LE(fabs(cx - ex), single ? 1.0 : 1e-3);
            TL_CHECK_LE(fabs(cy - ey), single ? 1.0 : 1e-3);
            for (uint32_t y = 0; !single && y < bh; y++)
                for (uint32_t x = 0; x < bw; x++) {
                    double v = b[4 * ((size_t)y * bw + x)];
                    double m[3] = {b[4 * ((size_t)y * bw + (bw - 1 - x))], b[4 * ((size_t)(bh - 1 - y) * bw + x)],
                                   b[4 * ((size_t)x * bw + y)]};
                    for (int k = 0; k < 3; k++) {
                        double d = fabs(v - m[k]) / fmax(fmax(v, m[k]), 1e-30);
                        if (d > worst) worst = d;
                    }
                }
            if (!single) {
                printf("largest relative difference between mirrored pixels %.3g (bound %.3g)\n", worst, tol);
                TL_CHECK_LE(worst, tol);
            }
        } else {
            tl_test_failures++;
        }
        free(b);
        tl_renderer_destroy(r);
        hdr_source_free(&src);
        free(img);
    }
    tl_scene_destroy(s);
}

static size_t non_finite(const float *p, size_t n)
{
    size_t bad = 0;
    for (size_t i = 0; i < 4 * n; i++) bad += !isfinite(p[i]);
    return bad;
}

/* HDR at the FP16 maximum everywhere, on a 1x1, a 7x3 and a 64x36 target, threshold 0, intensity
 * 1: bloom values finite and at most the maximum, and the output saturated white, not black. */
TL_TEST_FULL(bloom_finite_at_fp16_max_and_on_tiny_targets)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    tl_scene *s = small_scene();
    if (!s) return;
    static const uint32_t sizes[][2] = {{1, 1}, {7, 3}, {64, 36}};
    for (size_t i = 0; i < 3; i++) {
        uint32_t w = sizes[i][0], h = sizes[i][1];
        size_t n = (size_t)w * h;
        float *img = malloc(n * 4 * sizeof *img);
        for (size_t k = 0; img && k < 4 * n; k++) img[k] = 65504.0f;
        GladGLContext gl;
        hdr_source src;
        if (!hdr_source_make(&src, &gl, w, h, img)) {
            free(img);
            break;
        }
        tl_renderer *r = bloom_renderer(s, w, h, (tl_bloom_desc){.enabled = 1, .threshold = -1, .intensity = 1, .levels = 8},
                                        &src);
        if (r) {
            size_t nb = 0;
            float *b = read_target(r, TL_TARGET_BLOOM, &nb);
            TL_CHECK_EQ_U(nb, (size_t)((w + 1) / 2) * ((h + 1) / 2));
            TL_CHECK_EQ_U(b ? non_finite(b, nb) : 1, 0);
            float most = 0;
            for (size_t k = 0; b && k < nb; k++) most = fmaxf(most, b[4 * k]);
            TL_CHECK_LE(most, 65504.0);
            TL_CHECK(most > 60000.0f);
            uint8_t *out = malloc(n * 4);
            size_t size = n * 4, dark = 0;
            TL_CHECK(out && tl_renderer_read_output(r, out, &size) == TL_OK);
            for (size_t k = 0; out && k < n; k++) dark += out[4 * k] != 255 || out[4 * k + 1] != 255 || out[4 * k + 2] != 255;
            TL_CHECK_EQ_U(dark, 0);
            free(out);
            free(b);
            tl_renderer_destroy(r);
        }
        hdr_source_free(&src);
        free(img);
    }
    /* the crypt on tiny targets, every mode, bloom with SSAO, fog and DoF: finite HDR and bloom */
    for (size_t i = 0; i < 2; i++)
        for (int m = 0; m < K_MODES; m++) {
            uint32_t w = sizes[i][0], h = sizes[i][1];
            tl_renderer *r = renderer((tl_renderer_desc){.options.mode = k_modes[m], .width = w, .height = h,
                                                         .options.keep_targets = BIT(TL_TARGET_HDR) | BIT(TL_TARGET_BLOOM),
                                                         .options.ssao = {.enabled = 1, .method = TL_SSAO_DISC},
                                                         .options.fog = {.enabled = 1, .mode = TL_FOG_DISTANCE},
                                                         .options.dof = {.enabled = 1},
                                                         .options.bloom = {.enabled = 1, .threshold = -1}},
                                      s);
            if (!r) continue;
            TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
            size_t nh = 0, nb = 0;
            float *hdr = read_target(r, TL_TARGET_HDR, &nh), *b = read_target(r, TL_TARGET_BLOOM, &nb);
            TL_CHECK_EQ_U(hdr ? non_finite(hdr, nh) : 1, 0);
            TL_CHECK_EQ_U(b ? non_finite(b, nb) : 1, 0);
            free(hdr);
            free(b);
            tl_renderer_destroy(r);
        }
    tl_scene_destroy(s);
}
