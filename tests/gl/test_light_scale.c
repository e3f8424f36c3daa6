/* The light scale (tl_renderer_options.light_scale, docs/frame.md "Light at reduced resolution"):
 * scale 1 renders the same bytes as no option in every mode and strategy, and other modes ignore
 * the scale; a flat lit plane at 1/2 and 1/4 matches scale 1 within the FP16 bound; a box on a
 * floor has no light bleeding across its depth step; a one-pixel pole is lit; odd sizes render
 * without GL errors with reduced targets rounded up; a resize reallocates them; light-upsample's
 * full-size light buffer is a CPU run of the upsample's weights within one FP16 step, or the light of
 * scale 1 where it re-lights; the material pass is scale 1's (its reads and programs).
 * Each was seen to fail under a mutation: tl__light_shift ignoring the mode (scale 1 and other
 * modes, the plan test); the upsample's weights left unnormalised (flat plane: 0.28 > 2^-9); the
 * depth weight dropped (box: edge error 2.6 against 0.05 inside; pole: all 80 pixels dark at 1/2);
 * the reduction keeping the farthest sample with reversed Z (pole: every pixel re-lit); reduced
 * sizes rounded down (odd sizes, resize). */
#include "tl_test.h"

#include <math.h>

#include "render_fixture.h"
#include "thinlight/codec.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

static const float scales[3] = {1.0f, 0.5f, 0.25f};

/* ---- a scene of boxes ----------------------------------------------------------------------------- */

enum { MAX_BOXES = 48 };
typedef struct boxes {
    tl_vertex v[24 * MAX_BOXES];
    uint32_t idx[36 * MAX_BOXES];
    tl_object obj[MAX_BOXES];
    tl_material mat[2];
    tl_light light[4];
    tl_scene s;
} boxes;

/* A box centred at c with half-extents e, its faces counter-clockwise seen from outside. */
static void add_box(boxes *b, const float c[3], const float e[3], uint32_t material)
{
    static const float n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    size_t o = b->s.object_count, v0 = b->s.vertex_count, i0 = b->s.index_count;
    for (int f = 0; f < 6; f++) {
        int a = f / 2, p = (a + 1) % 3, q = (a + 2) % 3;
        float s = n[f][a];
        static const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int i = 0; i < 4; i++) {
            tl_vertex *x = &b->v[v0 + (size_t)f * 4 + (size_t)i];
            memset(x, 0, sizeof *x);
            x->position[a] = c[a] + s * e[a];
            x->position[p] = c[p] + corners[i][0] * e[p];
            x->position[q] = c[q] + corners[i][1] * e[q] * s;
            memcpy(x->normal, n[f], sizeof x->normal);
        }
        static const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
        for (int i = 0; i < 6; i++) b->idx[i0 + (size_t)f * 6 + (size_t)i] = (uint32_t)(v0 + (size_t)f * 4) + t[i];
    }
    memset(&b->obj[o], 0, sizeof b->obj[o]);
    b->obj[o].first_index = (uint32_t)i0;
    b->obj[o].index_count = 36;
    b->obj[o].material = material;
    b->s.vertex_count += 24;
    b->s.index_count += 36;
    b->s.object_count++;
}

static void boxes_init(boxes *b, const float eye[3], const float at[3])
{
    memset(b, 0, sizeof *b);
    b->s.vertices = b->v;
    b->s.indices = b->idx;
    b->s.objects = b->obj;
    b->s.materials = b->mat;
    b->s.lights = b->light;
    b->mat[0] = (tl_material){.albedo = {0.7f, 0.6f, 0.5f}};                         /* diffuse only */
    b->mat[1] = (tl_material){.albedo = {0.4f, 0.5f, 0.7f}, .specular = {0.04f, 0.04f, 0.04f}, .gloss = 0.5f};
    b->s.material_count = 2;
    memcpy(b->s.camera.position, eye, 3 * sizeof(float));
    memcpy(b->s.camera.target, at, 3 * sizeof(float));
    b->s.camera.near_z = 0.1f;
    b->s.camera.far_z = 100.0f;
}

enum { W = 160, H = 90 };

/* One frame of `s` at scale `k` (ambient off: HDR is the lights alone); NULL when it failed. */
static tl_renderer *render_at(const tl_scene *s, float k, uint32_t w, uint32_t h, tl_light_strategy strategy,
                              tl_depth_format depth)
{
    tl_renderer_desc d = {.width = w, .height = h};
    d.options.depth_format = depth;
    d.options.light_scale = k;
    d.options.light_strategy = strategy;
    d.options.ambient[0] = d.options.ambient[1] = d.options.ambient[2] = -1.0f;
    tl_renderer *r = tl_test_render_once(s, d);
    TL_CHECK(r != NULL);
    return r;
}

/* The light strategy of the tests below: each runs with volumes and with tiles (the fix-up differs:
 * the material pass re-lights over the object's list, or over its tile's). */
static tl_light_strategy g_strategy = TL_LIGHT_STRATEGY_VOLUMES;
static const char *strategy_name(void) { return g_strategy == TL_LIGHT_STRATEGY_TILED ? "tiled" : "volumes"; }

static float *hdr_at(const tl_scene *s, float k, tl_depth_format depth)
{
    tl_renderer *r = render_at(s, k, W, H, g_strategy, depth);
    float *p = r ? tl_test_read_target(r, TL_TARGET_HDR, (size_t)W * H) : NULL;
    tl_renderer_destroy(r);
    TL_CHECK(p != NULL);
    return p;
}

/* The largest channel difference relative to the reference's value, or to `floor` where that is
 * smaller (where a light fades to exactly 0 at its range a relative error means nothing). */
static double rel_err_floor(const float *a, const float *b, size_t i, double floor)
{
    double m = 0.0;
    for (int c = 0; c < 3; c++) {
        double e = fabs((double)a[4 * i + c] - b[4 * i + c]) / fmax(fabs((double)b[4 * i + c]), floor);
        if (e > m) m = e;
    }
    return m;
}

static double rel_err(const float *a, const float *b, size_t i) { return rel_err_floor(a, b, i, 1e-3); }

/* ---- scale 1 is today's frame ----------------------------------------------------------------- */

static int output_of(const tl_scene *s, tl_render_mode mode, tl_light_strategy st, float k, uint8_t *out)
{
    tl_renderer_desc d = {.width = W, .height = H};
    d.options.mode = mode;
    d.options.light_strategy = st;
    d.options.light_scale = k;
    tl_renderer *r = tl_test_render_once(s, d);
    size_t size = (size_t)W * H * 4;
    int ok = r && tl_renderer_read_output(r, out, &size) == TL_OK;
    tl_renderer_destroy(r);
    return ok;
}

TL_TEST(light_scale_one_same_bytes_in_every_mode_and_strategy)
{
    if (!ensure_context()) return;
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 24, .detail = 1}, &s) == TL_OK);
    if (!s) return;
    static uint8_t base[W * H * 4], other[W * H * 4];
    const tl_render_mode modes[5] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD,
                                     TL_MODE_VISIBILITY};
    const tl_light_strategy strategies[2] = {TL_LIGHT_STRATEGY_VOLUMES, TL_LIGHT_STRATEGY_TILED};
    for (int m = 0; m < 5; m++)
        for (int k = 0; k < 2; k++) {
            TL_CHECK(output_of(s, modes[m], strategies[k], 0.0f, base));
            TL_CHECK(output_of(s, modes[m], strategies[k], 1.0f, other));
            TL_CHECK(memcmp(base, other, sizeof base) == 0);
            if (modes[m] == TL_MODE_THIN_LPP) continue;
            /* other modes plan and render as with scale 1 */
            TL_CHECK(output_of(s, modes[m], strategies[k], 0.25f, other));
            TL_CHECK(memcmp(base, other, sizeof base) == 0);
        }
    tl_scene_destroy(s);
}

TL_TEST(light_scale_plan_reduced_targets_and_refusals)
{
    tl_scene_feature_set f = {.point_lights = 40, .directional_lights = 1, .has_specular = 1};
    tl_frame_plan none, one, half;
    TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.width = 1281, .height = 721}, &f, &none) == TL_OK);
    TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.width = 1281, .height = 721, .options.light_scale = 1.0f}, &f,
                                 &one) == TL_OK);
    TL_CHECK(memcmp(&none, &one, sizeof none) == 0); /* 0 bytes differ */
    TL_CHECK(!(one.targets & (TL_TARGET_BIT(TL_TARGET_LIGHT_DEPTH) | TL_TARGET_BIT(TL_TARGET_LIGHT_RT0))));
    for (int k = 1; k < 3; k++)
        for (int tiled = 0; tiled < 2; tiled++) {
        tl_renderer_desc d = {.width = 1281, .height = 721, .options.light_scale = scales[k]};
        d.options.light_strategy = tiled ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES;
        TL_CHECK(tl_frame_plan_build(&d, &f, &half) == TL_OK);
        TL_CHECK(half.light_strategy == d.options.light_strategy);
        /* the fix-up's buffer: the re-lit count only (light-upsample re-lights the pixels itself,
         * from the tile lists with either strategy); tiles are counted in the frame's pixels: twice
         * the option's side (16 texels of the light buffer at 1/2, 8 at 1/4) */
        TL_CHECK(half.targets & TL_TARGET_BIT(TL_TARGET_LIGHT_FIXUP));
        TL_CHECK_EQ_U(half.target_info[TL_TARGET_LIGHT_FIXUP].bytes, 16u);
        TL_CHECK(half.targets & TL_TARGET_BIT(TL_TARGET_LIGHT_LISTS));
        TL_CHECK_EQ_U(half.tile_size, 32u);
        TL_CHECK_EQ_U(half.tiles_x, (1281u + 31u) / 32u);
        TL_CHECK(half.light_scale == scales[k]);
        /* the light pass writes the reduced buffer, light-upsample the full-size one the material
         * pass reads as at scale 1 */
        uint32_t rw = (1281u + (1u << k) - 1u) >> k, rh = (721u + (1u << k) - 1u) >> k;
        const tl_target_id reduced[4] = {TL_TARGET_LIGHT_DEPTH, TL_TARGET_LIGHT_RT0, TL_TARGET_LIGHT_REDUCED_DIFFUSE,
                                         TL_TARGET_LIGHT_REDUCED_SPECULAR};
        for (int t = 0; t < 4; t++) {
            const tl_plan_target *ti = &half.target_info[reduced[t]];
            TL_CHECK(half.targets & TL_TARGET_BIT(reduced[t]));
            TL_CHECK_EQ_U(ti->width, rw);
            TL_CHECK_EQ_U(ti->height, rh);
            TL_CHECK_EQ_U(ti->bytes, (size_t)rw * rh * (t < 2 ? 4u : 8u));
        }
        for (tl_target_id t = TL_TARGET_LIGHT_DIFFUSE; t <= TL_TARGET_LIGHT_SPECULAR; t++) {
            TL_CHECK_EQ_U(half.target_info[t].width, 1281u);
            TL_CHECK_EQ_U(half.target_info[t].height, 721u);
        }
        printf("scale %.2f, %s: %u B/px allocated (scale 1: %u)\n", (double)scales[k], tiled ? "tiled" : "volumes",
               half.allocated_bytes_per_pixel, one.allocated_bytes_per_pixel);
        int reduce = 0, upsample = 0;
        for (size_t i = 0; i < half.pass_count; i++) {
            reduce += half.passes[i].pass == TL_PASS_LIGHT_REDUCE;
            upsample += half.passes[i].pass == TL_PASS_LIGHT_UPSAMPLE;
        }
        TL_CHECK(reduce == 1 && upsample == 1);
        char text[8192];
        tl_frame_plan_format(&half, text, sizeof text);
        TL_CHECK(strstr(text, "light-reduce") && strstr(text, "light scale: "));
        /* another mode plans exactly as scale 1, and says why */
        tl_frame_plan fat1, fatk;
        tl_renderer_desc fd = {.width = 1281, .height = 721, .options.mode = TL_MODE_FAT};
        TL_CHECK(tl_frame_plan_build(&fd, &f, &fat1) == TL_OK);
        fd.options.light_scale = scales[k];
        TL_CHECK(tl_frame_plan_build(&fd, &f, &fatk) == TL_OK);
        TL_CHECK(strstr(fatk.light_scale_reason, "thin-lpp") != NULL);
        memset(fatk.light_scale_reason, 0, sizeof fatk.light_scale_reason);
        TL_CHECK(fatk.downgrade_count == 1 && !strcmp(fatk.downgrades[0].option, "light_scale")); /* a downgrade */
        memset(fatk.downgrades, 0, sizeof fatk.downgrades);
        fatk.downgrade_count = 0;
        TL_CHECK(memcmp(&fat1, &fatk, sizeof fat1) == 0);
    }
    const float bad[4] = {0.3f, 2.0f, -0.5f, NAN};
    for (int i = 0; i < 4; i++)
        TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.options.light_scale = bad[i]}, &f, &half) ==
                 TL_ERROR_INVALID_ARGUMENT);
    if (!ensure_context()) return;
    tl_renderer_desc d = {.width = 16, .height = 16, .options.light_scale = 0.3f,
                          .get_proc_address = tl_context_proc_loader, .get_proc_address_user = g_ctx};
    tl_renderer *r = NULL;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_ERROR_INVALID_ARGUMENT);
    d.options.light_scale = 0.5f;
    TL_CHECK(tl_renderer_create(&d, &r) == TL_OK);
    if (!r) return;
    tl_renderer_options o = d.options;
    o.light_scale = 0.75f;
    TL_CHECK(tl_renderer_set_options(r, &o) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(strstr(tl_renderer_last_error(r), "options.light_scale") != NULL);
    tl_renderer_destroy(r);
}

/* The header once said a reduced light buffer uses the volumes strategy; the planner keeps the
 * strategy of scale 1: auto's choice by the local lights' count, or the one asked for. */
TL_TEST(light_scale_auto_strategy_as_at_scale_one)
{
    const size_t locals[4] = {1, 31, 32, 200}; /* either side of auto's crossover (32 local lights) */
    for (int k = 1; k < 3; k++)
        for (int i = 0; i < 4; i++) {
            tl_scene_feature_set f = {.point_lights = locals[i] - locals[i] / 4, .spot_lights = locals[i] / 4,
                                      .directional_lights = 1, .has_specular = 1};
            tl_frame_plan one, reduced;
            tl_renderer_desc d = {.width = 320, .height = 180};
            TL_CHECK(tl_frame_plan_build(&d, &f, &one) == TL_OK);
            d.options.light_scale = scales[k];
            TL_CHECK(tl_frame_plan_build(&d, &f, &reduced) == TL_OK);
            tl_light_strategy want = locals[i] >= 32 ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES;
            TL_CHECK(one.light_strategy == want && reduced.light_strategy == want);
            TL_CHECK(strcmp(one.strategy_reason, reduced.strategy_reason) == 0);
            /* tile lists with either strategy: light-upsample re-lights its pixels from them */
            TL_CHECK(reduced.targets & TL_TARGET_BIT(TL_TARGET_LIGHT_LISTS));
            TL_CHECK_EQ_U(reduced.tile_size, 32u);
            printf("scale %.2f, %zu local lights: %s (%s)\n", (double)scales[k], locals[i],
                   tl_light_strategy_name(reduced.light_strategy), reduced.strategy_reason);
        }
}

/* ---- a flat lit plane ----------------------------------------------------------------------------
 * A directional light on a Lambertian plane: the light is the same at every pixel, so the upsample
 * must return it unchanged. Both frames round the light sum to FP16 (a relative half-ulp, 2^-11) and
 * HDR to FP16 (2^-11 again); the upsample's normalised weights of equal values add fp32 rounding
 * only (2^-23 each): |a - b| <= (2 + 2) 2^-11 |b| = 2^-9 |b|. */
TL_TEST(light_scale_flat_plane_matches_scale_one)
{
    if (!ensure_context()) return;
    boxes *b = calloc(1, sizeof *b);
    if (!b) return;
    boxes_init(b, (const float[3]){0.0f, 3.0f, 6.0f}, (const float[3]){0.0f, 0.0f, 0.0f});
    add_box(b, (const float[3]){0.0f, -0.5f, 0.0f}, (const float[3]){40.0f, 0.5f, 40.0f}, 0);
    b->light[0] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {0.3f, -1.0f, -0.2f}, .color = {2.0f, 1.8f, 1.5f}};
    b->s.light_count = 1;
    for (int st = 0; st < 2; st++) {
    g_strategy = st ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES;
    float *ref = hdr_at(&b->s, 1.0f, TL_DEPTH_FORMAT_DEFAULT);
    for (int k = 1; ref && k < 3; k++) {
        float *got = hdr_at(&b->s, scales[k], TL_DEPTH_FORMAT_DEFAULT);
        double worst = 0.0;
        size_t lit = 0;
        for (size_t i = 0; got && i < (size_t)W * H; i++) {
            if (ref[4 * i] <= 0.0f) continue; /* the sky beyond the plane */
            lit++;
            double e = rel_err(got, ref, i);
            if (e > worst) worst = e;
        }
        printf("flat plane, %s, scale %g: %zu lit pixels, largest relative difference %.3g (bound 2^-9 = %.3g)\n",
               strategy_name(), (double)scales[k], lit, worst, ldexp(1.0, -9));
        TL_CHECK(lit > (size_t)W * H / 2);
        TL_CHECK_LE(worst, ldexp(1.0, -9));
        free(got);
    }
    free(ref);
    }
    free(b);
}

/* ---- a box on a floor --------------------------------------------------------------------------
 * A point light beside a box lights the box's top and the floor differently, and both have the same
 * normal: only the depth weight tells them apart. Edge pixels (a depth step of more than 5 % within
 * 4 pixels) must not be worse than twice the largest error inside the surfaces (the interpolation
 * of a smooth field), plus the FP16 bound: no light of one surface bleeds onto the other. Errors
 * are relative to the reference, or to 2 % of its brightest value where it is darker. */
static int edge_pixel(const float *depth, size_t x, size_t y)
{
    double z = depth[4 * (y * W + x) + 1];
    for (int dy = -4; dy <= 4; dy++)
        for (int dx = -4; dx <= 4; dx++) {
            long qx = (long)x + dx, qy = (long)y + dy;
            if (qx < 0 || qy < 0 || qx >= W || qy >= H) continue;
            double q = depth[4 * ((size_t)qy * W + (size_t)qx) + 1];
            if (fabs(q - z) > 0.05 * fmin(q, z)) return 1;
        }
    return 0;
}

static void box_on_floor(boxes *b)
{
    boxes_init(b, (const float[3]){0.0f, 4.0f, 5.0f}, (const float[3]){0.0f, 0.3f, 0.0f});
    add_box(b, (const float[3]){0.0f, -0.5f, 0.0f}, (const float[3]){40.0f, 0.5f, 40.0f}, 0);
    add_box(b, (const float[3]){0.0f, 0.5f, 0.0f}, (const float[3]){0.6f, 0.5f, 0.6f}, 1);
    b->light[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {1.2f, 2.2f, 1.2f}, .color = {6.0f, 5.0f, 4.0f},
                             .radius = 9.0f};
    b->light[1] = (tl_light){.type = TL_LIGHT_POINT, .position = {-1.8f, 1.6f, 1.5f}, .color = {1.0f, 2.0f, 3.0f},
                             .radius = 8.0f};
    b->s.light_count = 2;
}

TL_TEST(light_scale_box_on_floor_no_bleeding)
{
    if (!ensure_context()) return;
    boxes *b = calloc(1, sizeof *b);
    if (!b) return;
    box_on_floor(b);
    /* reversed D32F keeps the largest depth of a block: the same nearest surface */
    const tl_depth_format formats[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    for (int run = 0; run < 4; run++) {
        int fmt = run & 1;
        g_strategy = run >> 1 ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES;
        tl_renderer *r1 = render_at(&b->s, 1.0f, W, H, g_strategy, formats[fmt]);
        float *ref = r1 ? tl_test_read_target(r1, TL_TARGET_HDR, (size_t)W * H) : NULL;
        float *depth = r1 ? tl_test_read_target(r1, TL_TARGET_DEPTH, (size_t)W * H) : NULL;
        tl_renderer_destroy(r1);
        TL_CHECK(ref && depth);
        for (int k = 1; ref && depth && k < 3; k++) {
            float *got = hdr_at(&b->s, scales[k], formats[fmt]);
            double edge = 0.0, inside = 0.0, peak = 0.0;
            size_t edges = 0;
            for (size_t i = 0; i < (size_t)W * H * 4; i++) peak = fmax(peak, ref[i]);
            for (size_t y = 0; got && y < H; y++)
                for (size_t x = 0; x < W; x++) {
                    size_t i = y * W + x;
                    if (!(depth[4 * i + 1] < 90.0f) || ref[4 * i] + ref[4 * i + 1] + ref[4 * i + 2] < 0.01f) continue;
                    double e = rel_err_floor(got, ref, i, 0.02 * peak); /* 2 % of the brightest value at least */
                    if (edge_pixel(depth, x, y)) {
                        edges++;
                        if (e > edge) edge = e;
                    } else if (e > inside) {
                        inside = e;
                    }
                }
            printf("box on a floor, %s, %s, scale %g: %zu edge pixels, largest relative error %.4f on edges, %.4f inside\n",
                   fmt ? "D32F reversed" : "D24", strategy_name(), (double)scales[k], edges, edge, inside);
            TL_CHECK(edges > 100);
            TL_CHECK_LE(edge, 2.0 * inside + ldexp(1.0, -9));
            free(got);
        }
        free(ref);
        free(depth);
    }
    free(b);
}

/* ---- light-upsample against a CPU run of the upsample -------------------------------------------
 * The upsample's weights (docs/frame.md, "Light at reduced resolution") evaluated in double from the
 * targets a frame kept: the reduced depth, RT0, offsets and light, the frame's depth (its linear
 * distance; the plane's slope as the smaller one-sided difference, as the pass takes it) and RT0.
 * A pixel is expected upsampled where its credible weight is at least 0.5 + 2^-10, re-lit below
 * 0.5 - 2^-10, and either way in between (the weights' float evaluation decides there). */
typedef struct upsample_ref {
    uint32_t w, h, rw, rh, k;
    float *depth, *rt0, *ldepth, *lrt0, *loffset, *lred; /* read back from the frame */
    int reversed;
} upsample_ref;

enum { UP_UPSAMPLED = 0, UP_RELIT = 1, UP_EITHER = 2, UP_BACKGROUND = 3 };

static int up_read(upsample_ref *u, tl_renderer *r)
{
    size_t n = (size_t)u->w * u->h, m = (size_t)u->rw * u->rh;
    u->depth = tl_test_read_target(r, TL_TARGET_DEPTH, n);
    u->rt0 = tl_test_read_target(r, TL_TARGET_RT0, n);
    u->ldepth = tl_test_read_target(r, TL_TARGET_LIGHT_DEPTH, m);
    u->lrt0 = tl_test_read_target(r, TL_TARGET_LIGHT_RT0, m);
    u->loffset = tl_test_read_target(r, TL_TARGET_LIGHT_OFFSET, m);
    u->lred = tl_test_read_target(r, TL_TARGET_LIGHT_REDUCED_DIFFUSE, m);
    return u->depth && u->rt0 && u->ldepth && u->lrt0 && u->loffset && u->lred;
}

static void up_free(upsample_ref *u)
{
    free(u->depth);
    free(u->rt0);
    free(u->ldepth);
    free(u->lrt0);
    free(u->loffset);
    free(u->lred);
}

static int up_background(const upsample_ref *u, float window) { return window == (u->reversed ? 0.0f : 1.0f); }

/* The view depth of frame pixel (x, y) (< 0), or 1 for the background and outside the frame. */
static double up_z(const upsample_ref *u, long x, long y)
{
    if (x < 0 || y < 0 || x >= (long)u->w || y >= (long)u->h) return 1.0;
    const float *d = &u->depth[4 * ((size_t)y * u->w + (size_t)x)];
    return up_background(u, d[0]) ? 1.0 : -(double)d[1];
}

static int up_same_normal(const float *a, const float *b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

/* Pixel (x, y): its class, and the upsampled diffuse light where it has one. `power`: the normal
 * term's (the lobe's for specular frames, clamped to 16 .. 256; 16 otherwise). */
static int up_pixel(const upsample_ref *u, long x, long y, int specular, double out[3])
{
    double z = up_z(u, x, y);
    if (z > 0.0) return UP_BACKGROUND;
    double k = (double)u->k, rx = (x + 0.5) / k - 0.5, ry = (y + 0.5) / k - 0.5;
    long bx = (long)floor(rx), by = (long)floor(ry);
    double fx = rx - bx, fy = ry - by;
    const float *n = &u->rt0[4 * ((size_t)y * u->w + (size_t)x)];
    double wb[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy}, w[4], total = 0.0;
    size_t q[4];
    for (int j = 0; j < 4; j++) {
        long qx = bx + (j & 1), qy = by + (j >> 1);
        qx = qx < 0 ? 0 : qx >= (long)u->rw ? (long)u->rw - 1 : qx;
        qy = qy < 0 ? 0 : qy >= (long)u->rh ? (long)u->rh - 1 : qy;
        q[j] = (size_t)qy * u->rw + (size_t)qx;
    }
    int inside = bx >= 0 && by >= 0 && bx + 1 < (long)u->rw && by + 1 < (long)u->rh;
    unsigned flags = (unsigned)(u->loffset[4 * q[0]] * 255.0f + 0.5f);
    if (inside && (flags & 32u) && up_same_normal(&u->lrt0[4 * q[0]], n)) {
        for (int j = 0; j < 4; j++) w[j] = wb[j];
        total = 1.0;
    } else {
        double zl = up_z(u, x - 1, y), zr = up_z(u, x + 1, y), zd = up_z(u, x, y - 1), zu = up_z(u, x, y + 1);
        double ax = zl < 0 ? z - zl : 1e30, bxd = zr < 0 ? zr - z : 1e30, ay = zd < 0 ? z - zd : 1e30, by_ = zu < 0 ? zu - z : 1e30;
        double dzx = fabs(ax) < fabs(bxd) ? ax : bxd, dzy = fabs(ay) < fabs(by_) ? ay : by_;
        if (fabs(dzx) >= 1e29) dzx = 0.0;
        if (fabs(dzy) >= 1e29) dzy = 0.0;
        double power = 16.0;
        if (specular) power = fmin(fmax(tl_gloss_to_specular_power(n[3]), 16.0), 256.0);
        double tol = 0.01 * fabs(z) + 0.5 * k * (fabs(dzx) + fabs(dzy));
        for (int j = 0; j < 4; j++) {
            w[j] = 0.0;
            const float *ld = &u->ldepth[4 * q[j]];
            if (up_background(u, ld[0])) continue;
            unsigned off = (unsigned)(u->loffset[4 * q[j]] * 255.0f + 0.5f) & 31u;
            long qx = (long)(q[j] % u->rw), qy = (long)(q[j] / u->rw);
            double cx = off == 16u ? (qx + 0.5) * k : (double)(qx * (long)u->k + (long)(off & 3u)) + 0.5;
            double cy = off == 16u ? (qy + 0.5) * k : (double)(qy * (long)u->k + (long)(off >> 2)) + 0.5;
            double predicted = z + dzx * (cx - (x + 0.5)) + dzy * (cy - (y + 0.5));
            double wz = fmin(fmax(1.0 - fabs(-(double)ld[1] - predicted) / tol, 0.0), 1.0);
            const float *t = &u->lrt0[4 * q[j]];
            double dot = (double)t[0] * n[0] + (double)t[1] * n[1] + (double)t[2] * n[2];
            double wn = up_same_normal(t, n) ? 1.0 : pow(fmin(fmax(dot, 0.0), 1.0), power);
            w[j] = wb[j] * wz * wn;
            total += w[j];
        }
    }
    for (int c = 0; c < 3; c++) {
        out[c] = 0.0;
        for (int j = 0; j < 4; j++) out[c] += w[j] * u->lred[4 * q[j] + (size_t)c];
        out[c] /= total > 0.0 ? total : 1.0;
    }
    const double band = ldexp(1.0, -10);
    return total >= 0.5 + band ? UP_UPSAMPLED : total < 0.5 - band ? UP_RELIT : UP_EITHER;
}

/* The classes of a frame at scale `k` kept whole (tl_test_render_once keeps every target). */
static int *up_classes(tl_renderer *r, uint32_t w, uint32_t h, int shift, int reversed, int specular)
{
    upsample_ref u = {.w = w, .h = h, .k = 1u << shift, .rw = (w + (1u << shift) - 1) >> shift,
                      .rh = (h + (1u << shift) - 1) >> shift, .reversed = reversed};
    int *cls = calloc((size_t)w * h, sizeof *cls);
    if (cls && up_read(&u, r))
        for (long y = 0; y < (long)h; y++)
            for (long x = 0; x < (long)w; x++) {
                double l[3];
                cls[(size_t)y * w + (size_t)x] = up_pixel(&u, x, y, specular, l);
            }
    else {
        free(cls);
        cls = NULL;
    }
    up_free(&u);
    TL_CHECK(cls != NULL);
    return cls;
}

/* Whether light-upsample weighs normals with the lobe's power: its frame has specular materials. */
static int up_specular(const tl_renderer *r)
{
    tl_frame_plan p;
    if (tl_renderer_get_plan(r, &p) != TL_OK) return 0;
    for (size_t i = 0; i < p.program_count; i++)
        if (p.programs[i].pass == TL_PASS_LIGHT_UPSAMPLE)
            return strstr(p.programs[i].defines, "TL_SPECULAR_EXACT") || strstr(p.programs[i].defines, "TL_SPECULAR_COMPACT");
    return 0;
}

/* The box on a floor (below) with both strategies and depth conventions at 1/2 and 1/4: every pixel
 * of the full-size light buffer light-upsample wrote is the CPU's upsample of the reduced one within
 * one FP16 step (2^-10 relative: its own rounding of an fp32 sum, and the weights' float
 * evaluation), or, where no texel is credible, the light the light pass wrote at scale 1 within
 * 2^-9 (both round to FP16; the volumes' blending rounds once per light); the re-lit count lies
 * between the pixels surely re-lit and those with the ones within the band. This is the material
 * pass's upsample of 0.2.x, which it replaced (the same weights, rounded to FP16 once more). */
static void box_on_floor(boxes *b);

TL_TEST(light_scale_upsample_pass_matches_cpu_upsample)
{
    if (!ensure_context()) return;
    boxes *b = calloc(1, sizeof *b);
    if (!b) return;
    box_on_floor(b);
    const tl_depth_format formats[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    for (int run = 0; run < 4; run++) {
        int fmt = run & 1;
        g_strategy = run >> 1 ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES;
        tl_renderer *r1 = render_at(&b->s, 1.0f, W, H, g_strategy, formats[fmt]);
        float *ref = r1 ? tl_test_read_target(r1, TL_TARGET_LIGHT_DIFFUSE, (size_t)W * H) : NULL;
        tl_renderer_destroy(r1);
        for (int k = 1; ref && k < 3; k++) {
            tl_renderer *r = render_at(&b->s, scales[k], W, H, g_strategy, formats[fmt]);
            tl_frame_stats st;
            memset(&st, 0, sizeof st);
            int ok = r && tl_renderer_render(r, NULL, &st) == TL_OK && tl_renderer_wait(r, &st) == TL_OK;
            upsample_ref u = {.w = W, .h = H, .k = 1u << k, .rw = (W + (1u << k) - 1) >> k,
                              .rh = (H + (1u << k) - 1) >> k, .reversed = fmt};
            float *got = ok ? tl_test_read_target(r, TL_TARGET_LIGHT_DIFFUSE, (size_t)W * H) : NULL;
            TL_CHECK(ok && got && up_read(&u, r));
            int specular = r ? up_specular(r) : 0;
            tl_renderer_destroy(r);
            size_t count[4] = {0, 0, 0, 0}, bad = 0;
            double worst_up = 0.0, worst_relit = 0.0, peak = 0.0;
            for (size_t i = 0; got && i < (size_t)W * H * 4; i++) peak = fmax(peak, ref[i]);
            for (long y = 0; got && u.lred && y < H; y++)
                for (long x = 0; x < W; x++) {
                    size_t i = (size_t)y * W + (size_t)x;
                    double l[3], e_up = 0.0, e_relit = 0.0;
                    int c = up_pixel(&u, x, y, specular, l);
                    count[c]++;
                    if (c == UP_BACKGROUND) continue;
                    for (int ch = 0; ch < 3; ch++) {
                        double floor_ = 1e-3 * peak, g = got[4 * i + (size_t)ch];
                        e_up = fmax(e_up, fabs(g - l[ch]) / fmax(fabs(l[ch]), floor_));
                        e_relit = fmax(e_relit, fabs(g - ref[4 * i + (size_t)ch]) / fmax(fabs((double)ref[4 * i + (size_t)ch]), floor_));
                    }
                    if (c == UP_UPSAMPLED) worst_up = fmax(worst_up, e_up);
                    if (c == UP_RELIT) worst_relit = fmax(worst_relit, e_relit);
                    bad += c == UP_EITHER && e_up > ldexp(1.0, -10) && e_relit > ldexp(1.0, -9);
                }
            printf("box on a floor, %s, %s, scale %g: %zu upsampled (worst %.3g of 2^-10), %zu re-lit (worst %.3g of "
                   "2^-9), %zu within the band, %zu background; relit_pixels %llu\n",
                   fmt ? "D32F reversed" : "D24", strategy_name(), (double)scales[k], count[UP_UPSAMPLED], worst_up,
                   count[UP_RELIT], worst_relit, count[UP_EITHER], count[UP_BACKGROUND], (unsigned long long)st.relit_pixels);
            TL_CHECK(count[UP_UPSAMPLED] > (size_t)W * H / 2 && count[UP_RELIT] > 0);
            TL_CHECK_LE(worst_up, ldexp(1.0, -10));
            TL_CHECK_LE(worst_relit, ldexp(1.0, -9));
            TL_CHECK_EQ_U(bad, 0);
            TL_CHECK(st.relit_pixels >= count[UP_RELIT] && st.relit_pixels <= count[UP_RELIT] + count[UP_EITHER]);
            up_free(&u);
            free(got);
        }
        free(ref);
    }
    free(b);
}

/* The material pass at a light scale below 1 is scale 1's: the same reads and the same programs. */
TL_TEST(light_scale_material_pass_is_scale_ones)
{
    tl_scene_feature_set f = {.point_lights = 40, .spot_lights = 4, .directional_lights = 1, .has_specular = 1};
    for (int tiled = 0; tiled < 2; tiled++) {
        tl_renderer_desc d = {.width = 320, .height = 180};
        d.options.light_strategy = tiled ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES;
        tl_frame_plan one, reduced;
        TL_CHECK(tl_frame_plan_build(&d, &f, &one) == TL_OK);
        for (int k = 1; k < 3; k++) {
            d.options.light_scale = scales[k];
            TL_CHECK(tl_frame_plan_build(&d, &f, &reduced) == TL_OK);
            int programs = 0, passes = 0;
            for (size_t i = 0; i < one.program_count; i++)
                for (size_t j = 0; j < reduced.program_count; j++)
                    if (one.programs[i].pass == TL_PASS_MATERIAL && reduced.programs[j].pass == TL_PASS_MATERIAL &&
                        one.programs[i].slot == reduced.programs[j].slot) {
                        TL_CHECK(strcmp(one.programs[i].defines, reduced.programs[j].defines) == 0);
                        programs++;
                    }
            for (size_t i = 0; i < one.pass_count; i++)
                for (size_t j = 0; j < reduced.pass_count; j++)
                    if (one.passes[i].pass == TL_PASS_MATERIAL && reduced.passes[j].pass == TL_PASS_MATERIAL) {
                        TL_CHECK(one.passes[i].reads == reduced.passes[j].reads);
                        TL_CHECK(one.passes[i].writes == reduced.passes[j].writes);
                        passes++;
                    }
            TL_CHECK(programs >= 1 && passes == 1);
        }
    }
}

/* ---- a one-pixel pole ------------------------------------------------------------------------------
 * A pole about one pixel wide in front of a wall that no light reaches: at every scale and with
 * both depth conventions each pixel the pole covers at scale 1 is lit, at least half as bright as
 * at scale 1, and at most half of them by the fix-up (the reduction keeps the nearest sample). */
TL_TEST(light_scale_thin_pole_is_lit)
{
    if (!ensure_context()) return;
    boxes *b = calloc(1, sizeof *b);
    if (!b) return;
    boxes_init(b, (const float[3]){0.0f, 0.0f, 0.0f}, (const float[3]){0.0f, 0.0f, -1.0f});
    /* 60 degrees over 90 rows at 5 m: 2 * 5 * tan(30 deg) / 90 = 0.064 m a pixel */
    add_box(b, (const float[3]){0.013f, 0.0f, -5.0f}, (const float[3]){0.034f, 3.0f, 0.034f}, 0);
    add_box(b, (const float[3]){0.0f, 0.0f, -15.5f}, (const float[3]){30.0f, 30.0f, 0.5f}, 0);
    b->light[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {0.3f, 0.0f, -4.0f}, .color = {4.0f, 4.0f, 4.0f},
                             .radius = 3.0f};
    b->s.light_count = 1;
    for (int run = 0; run < 4; run++) {
        int fmt = run & 1;
        g_strategy = run >> 1 ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES;
        tl_depth_format df = fmt ? TL_DEPTH_FORMAT_D32F_REVERSED : TL_DEPTH_FORMAT_D24;
        float *ref = hdr_at(&b->s, 1.0f, df);
        for (int k = 1; ref && k < 3; k++) {
            tl_renderer *r = render_at(&b->s, scales[k], W, H, g_strategy, df);
            float *got = r ? tl_test_read_target(r, TL_TARGET_HDR, (size_t)W * H) : NULL;
            int *cls = r ? up_classes(r, W, H, k, fmt, up_specular(r)) : NULL;
            tl_renderer_destroy(r);
            size_t pole = 0, dark = 0, relit = 0;
            for (size_t i = 0; got && cls && i < (size_t)W * H; i++) {
                if (ref[4 * i] < 0.01f) continue;
                pole++;
                dark += got[4 * i] < 0.5f * ref[4 * i];
                relit += cls[i] != UP_UPSAMPLED; /* re-lit, or maybe (the CPU's upsample) */
            }
            free(cls);
            printf("one-pixel pole, %s, %s, scale %g: %zu pole pixels, %zu dark, %zu re-lit\n",
                   fmt ? "D32F reversed" : "D24", strategy_name(), (double)scales[k], pole, dark, relit);
            TL_CHECK(pole >= H / 2 && pole < 3 * H);
            TL_CHECK_EQ_U(dark, 0);
            /* the reduction keeps the pole (the nearest sample), so most of it is upsampled, not re-lit */
            TL_CHECK_LE(2 * relit, pole);
            free(got);
        }
        free(ref);
    }
    free(b);
}

/* ---- the re-lit count over half the frame -------------------------------------------------------
 * A comb: 40 slats two pixels wide, two pixels apart, in front of a wall, both lit by one point
 * light. At 1/4 every 4x4 block holds slat and wall; the reduction keeps the slats (nearest), so
 * every wall pixel between them is re-lit: about half the frame. For both strategies and both
 * scales: tl_frame_stats.relit_pixels lies between the pixels the CPU's upsample surely re-lights and
 * those with the ones within its band (light-upsample's weights), relit_fraction is it over the
 * pixels, and a surely re-lit pixel matches scale 1 within 4 FP16 roundings (2^-9 relative: both
 * round the light sum and HDR). */
TL_TEST(light_scale_relit_count_half_the_frame)
{
    if (!ensure_context()) return;
    boxes *b = calloc(1, sizeof *b);
    if (!b) return;
    boxes_init(b, (const float[3]){0.0f, 0.0f, 0.0f}, (const float[3]){0.0f, 0.0f, -1.0f});
    /* 0.064 m a pixel at 5 m (the pole's figure): slats 0.128 m wide every 0.256 m */
    for (int i = 0; i < 40; i++)
        add_box(b, (const float[3]){-5.12f + 0.256f * (float)i + 0.064f, 0.0f, -5.0f}, (const float[3]){0.064f, 5.0f, 0.05f}, 0);
    add_box(b, (const float[3]){0.0f, 0.0f, -10.5f}, (const float[3]){30.0f, 30.0f, 0.5f}, 0);
    b->light[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {0.3f, 0.2f, -3.0f}, .color = {6.0f, 6.0f, 6.0f},
                             .radius = 12.0f};
    b->s.light_count = 1;
    for (int st = 0; st < 2; st++) {
        g_strategy = st ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES;
        float *ref = hdr_at(&b->s, 1.0f, TL_DEPTH_FORMAT_DEFAULT);
        for (int k = 0; ref && k < 3; k++) {
            tl_renderer *r = render_at(&b->s, scales[k], W, H, g_strategy, TL_DEPTH_FORMAT_DEFAULT);
            tl_frame_stats stats;
            memset(&stats, 0, sizeof stats);
            int ok = r && tl_renderer_render(r, NULL, &stats) == TL_OK && tl_renderer_wait(r, &stats) == TL_OK;
            TL_CHECK(ok);
            float *got = ok ? tl_test_read_target(r, TL_TARGET_HDR, (size_t)W * H) : NULL;
            int *cls = ok && k ? up_classes(r, W, H, k, 0, up_specular(r)) : NULL;
            tl_renderer_destroy(r);
            if (!got) continue;
            size_t relit = 0, band = 0;
            double worst = 0.0;
            for (size_t i = 0; cls && i < (size_t)W * H; i++) {
                band += cls[i] == UP_EITHER;
                if (cls[i] != UP_RELIT) continue;
                relit++;
                double e = rel_err(got, ref, i);
                if (e > worst) worst = e;
            }
            free(cls);
            printf("comb, %s, scale %g: %zu pixels re-lit, %zu within the band (stats: %llu, %.4f of the frame), "
                   "largest relative error of a re-lit pixel %.3g\n",
                   strategy_name(), (double)scales[k], relit, band, (unsigned long long)stats.relit_pixels,
                   stats.relit_fraction, worst);
            TL_CHECK(stats.relit_pixels >= relit && stats.relit_pixels <= relit + band);
            if (g_strategy == TL_LIGHT_STRATEGY_VOLUMES) { /* the volumes' pairs, not light-cull's (it runs for the fix-up) */
                uint64_t fragments = 0;
                for (int t = 0; t < TL_LIGHT_TYPE_COUNT_; t++) fragments += stats.light_fragments[t];
                TL_CHECK(stats.light_pairs == fragments && fragments > 0);
            }
            TL_CHECK(fabs(stats.relit_fraction - (double)stats.relit_pixels / (W * H)) < 1e-12);
            if (k == 0) TL_CHECK_EQ_U(stats.relit_pixels, 0);
            if (k == 2) TL_CHECK(relit > (size_t)W * H / 4); /* far more than an edge's pixels */
            TL_CHECK_LE(worst, ldexp(1.0, -9));
            free(got);
        }
        free(ref);
    }
    free(b);
}

/* ---- the tiled pass as a compute pass ------------------------------------------------------------
 * At a reduced scale the compute variant of the tiled light pass dispatches over the light buffer's
 * texels and reads the tile of their block: the same light buffer as the fragment variant, so the
 * same HDR, bit for bit, at an odd size too (boxes, two point lights and a spot). */
TL_TEST(light_scale_tiled_compute_matches_fragment)
{
    if (!ensure_context()) return;
    boxes *b = calloc(1, sizeof *b);
    if (!b) return;
    boxes_init(b, (const float[3]){0.0f, 4.0f, 5.0f}, (const float[3]){0.0f, 0.3f, 0.0f});
    add_box(b, (const float[3]){0.0f, -0.5f, 0.0f}, (const float[3]){40.0f, 0.5f, 40.0f}, 0);
    add_box(b, (const float[3]){0.0f, 0.5f, 0.0f}, (const float[3]){0.6f, 0.5f, 0.6f}, 1);
    add_box(b, (const float[3]){1.5f, 0.3f, -1.0f}, (const float[3]){0.3f, 0.3f, 0.3f}, 1);
    b->light[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {1.2f, 2.2f, 1.2f}, .color = {6.0f, 5.0f, 4.0f},
                             .radius = 9.0f};
    b->light[1] = (tl_light){.type = TL_LIGHT_POINT, .position = {-1.8f, 1.6f, 1.5f}, .color = {1.0f, 2.0f, 3.0f},
                             .radius = 8.0f};
    b->light[2] = (tl_light){.type = TL_LIGHT_SPOT, .position = {0.0f, 3.0f, 0.0f}, .direction = {0.0f, -1.0f, 0.0f},
                             .color = {3.0f, 3.0f, 3.0f}, .radius = 6.0f, .cos_inner = 0.92f, .cos_outer = 0.82f};
    b->s.light_count = 3;
    const uint32_t sizes[2][2] = {{160, 90}, {37, 23}};
    for (int z = 0; z < 2; z++)
        for (int k = 1; k < 3; k++) {
            float *hdr[2] = {NULL, NULL};
            size_t n = (size_t)sizes[z][0] * sizes[z][1];
            for (int c = 0; c < 2; c++) {
                tl_renderer_desc d = {.width = sizes[z][0], .height = sizes[z][1]};
                d.options.light_scale = scales[k];
                d.options.light_strategy = TL_LIGHT_STRATEGY_TILED;
                d.options.tiled_shading = c ? TL_TILED_SHADING_COMPUTE : TL_TILED_SHADING_FRAGMENT;
                tl_renderer *r = tl_test_render_once(&b->s, d);
                hdr[c] = r ? tl_test_read_target(r, TL_TARGET_HDR, n) : NULL;
                TL_CHECK(hdr[c] != NULL);
                tl_renderer_destroy(r);
            }
            if (hdr[0] && hdr[1]) TL_CHECK(memcmp(hdr[0], hdr[1], n * 4 * sizeof(float)) == 0);
            free(hdr[0]);
            free(hdr[1]);
        }
    free(b);
}

/* ---- odd sizes, resizing ---------------------------------------------------------------------- */

TL_TEST_FULL(light_scale_odd_sizes_render_without_gl_errors)
{
    if (!ensure_context()) return;
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 8, .detail = 1}, &s) == TL_OK);
    if (!s) return;
    const uint32_t sizes[3][2] = {{1, 1}, {7, 3}, {1281, 721}};
    for (int z = 0; z < 3; z++)
        for (int run = 0; run < 6; run++) {
            int k = run % 3;
            tl_light_strategy strategy = run / 3 ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES;
            tl_renderer *r = render_at(s, scales[k], sizes[z][0], sizes[z][1], strategy, TL_DEPTH_FORMAT_DEFAULT);
            tl_frame_plan p;
            if (!r || tl_renderer_get_plan(r, &p) != TL_OK) {
                TL_CHECK(!"render or plan");
                tl_renderer_destroy(r);
                continue;
            }
            uint32_t rw = (sizes[z][0] + (1u << k) - 1u) >> k, rh = (sizes[z][1] + (1u << k) - 1u) >> k;
            /* the light pass's buffer (reduced), and light-upsample's at the frame's size */
            tl_target_id light = k ? TL_TARGET_LIGHT_REDUCED_DIFFUSE : TL_TARGET_LIGHT_DIFFUSE;
            TL_CHECK_EQ_U(p.target_info[light].width, rw);
            TL_CHECK_EQ_U(p.target_info[light].height, rh);
            TL_CHECK_EQ_U(p.target_info[TL_TARGET_LIGHT_DIFFUSE].width, sizes[z][0]);
            size_t size = 0; /* the reduced targets read back at their own size */
            TL_CHECK(tl_renderer_read_target(r, light, NULL, &size) == TL_OK);
            TL_CHECK_EQ_U(size, (size_t)rw * rh * 4 * sizeof(float));
            if (k) {
                float *d = tl_test_read_target(r, TL_TARGET_LIGHT_DEPTH, (size_t)rw * rh);
                TL_CHECK(d != NULL);
                free(d);
            }
            tl_renderer_destroy(r);
        }
    tl_scene_destroy(s);
}

TL_TEST(light_scale_resize_changes_reduced_targets)
{
    if (!ensure_context()) return;
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 8, .detail = 1}, &s) == TL_OK);
    if (!s) return;
    tl_renderer *r = render_at(s, 0.25f, 160, 90, TL_LIGHT_STRATEGY_DEFAULT, TL_DEPTH_FORMAT_DEFAULT);
    tl_renderer *fresh = render_at(s, 0.25f, 163, 95, TL_LIGHT_STRATEGY_DEFAULT, TL_DEPTH_FORMAT_DEFAULT);
    tl_frame_plan p;
    if (r && fresh && tl_renderer_get_plan(r, &p) == TL_OK) {
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_LIGHT_DEPTH].width, 40);
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_LIGHT_DEPTH].height, 23);
        TL_CHECK(tl_renderer_resize(r, 163, 95) == TL_OK);
        TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK && tl_renderer_wait(r, NULL) == TL_OK);
        TL_CHECK(tl_renderer_get_plan(r, &p) == TL_OK);
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_LIGHT_DEPTH].width, 41);
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_LIGHT_DEPTH].height, 24);
        size_t size = 0;
        TL_CHECK(tl_renderer_read_target(r, TL_TARGET_LIGHT_RT0, NULL, &size) == TL_OK);
        TL_CHECK_EQ_U(size, (size_t)41 * 24 * 4 * sizeof(float));
        static uint8_t a[163 * 95 * 4], c[163 * 95 * 4];
        size_t na = sizeof a, nc = sizeof c;
        TL_CHECK(tl_renderer_read_output(r, a, &na) == TL_OK && tl_renderer_read_output(fresh, c, &nc) == TL_OK);
        TL_CHECK(memcmp(a, c, sizeof a) == 0); /* as a renderer made at that size */
    }
    tl_renderer_destroy(r);
    tl_renderer_destroy(fresh);
    tl_scene_destroy(s);
}

/* ---- the figures of docs/frame.md --------------------------------------------------------------
 * The crypt at 1280x720 (64 point lights, 8 spots, the moonlight): PSNR of the output of scale 1/2
 * and 1/4 against scale 1 and against fat, the largest 8-bit error, the fraction of pixels the
 * fix-up re-lit (tl_frame_stats.relit_fraction) and the GPU time of the third frame. Printed, not checked: llvmpipe's
 * times depend on the machine. */
typedef struct figures {
    uint8_t *out;
    double gpu_ms, light_ms, upsample_ms, material_ms, relit;
} figures;

static int crypt_frame(const tl_scene *s, tl_render_mode mode, float k, figures *f)
{
    enum { FW = 1280, FH = 720 };
    tl_renderer_desc d = {.width = FW, .height = FH};
    d.options.mode = mode;
    d.options.light_scale = k;
    tl_renderer *r = tl_test_render_once(s, d);
    tl_frame_stats st;
    memset(&st, 0, sizeof st);
    for (int i = 0; r && i < 2; i++)
        if (tl_renderer_render(r, NULL, &st) != TL_OK || tl_renderer_wait(r, &st) != TL_OK) break;
    size_t size = (size_t)FW * FH * 4;
    f->out = malloc(size);
    float *hdr = r ? tl_test_read_target(r, TL_TARGET_HDR, (size_t)FW * FH) : NULL;
    int ok = r && f->out && hdr && tl_renderer_read_output(r, f->out, &size) == TL_OK;
    f->relit = st.relit_fraction;
    f->gpu_ms = st.gpu_ms;
    f->light_ms = st.pass_ms[TL_PASS_LIGHT_REDUCE] + st.pass_ms[TL_PASS_LIGHTS] + st.pass_ms[TL_PASS_LIGHTS_TILED] +
                  st.pass_ms[TL_PASS_LIGHT_CULL];
    f->upsample_ms = st.pass_ms[TL_PASS_LIGHT_UPSAMPLE];
    f->material_ms = st.pass_ms[TL_PASS_MATERIAL];
    /* light-upsample counts pixels, each once: at most the pixels a surface covers */
    size_t covered = 0;
    for (size_t i = 0; ok && i < (size_t)FW * FH; i++) covered += hdr[4 * i + 3] > 0.0f;
    TL_CHECK(!ok || mode != TL_MODE_THIN_LPP || st.relit_pixels <= covered);
    free(hdr);
    tl_renderer_destroy(r);
    return ok;
}

static double psnr8(const uint8_t *a, const uint8_t *b, size_t n, int *max_err)
{
    double se = 0.0;
    *max_err = 0;
    for (size_t i = 0; i < n; i++) {
        if (i % 4 == 3) continue;
        int e = abs((int)a[i] - (int)b[i]);
        if (e > *max_err) *max_err = e;
        se += (double)e * e;
    }
    double mse = se / ((double)n * 0.75);
    return mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : INFINITY;
}

TL_TEST_FULL(light_scale_crypt_figures_printed)
{
    if (!ensure_context()) return;
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(NULL, &s) == TL_OK);
    if (!s) return;
    figures fat, f[3];
    memset(f, 0, sizeof f);
    TL_CHECK(crypt_frame(s, TL_MODE_FAT, 1.0f, &fat));
    for (int k = 0; k < 3; k++) TL_CHECK(crypt_frame(s, TL_MODE_THIN_LPP, scales[k], &f[k]));
    size_t n = (size_t)1280 * 720 * 4;
    printf("fat: GPU %.1f ms (light passes %.1f ms)\n", fat.gpu_ms, fat.light_ms);
    for (int k = 0; fat.out && f[0].out && k < 3; k++) {
        if (!f[k].out) continue;
        int m1, mf;
        double p1 = psnr8(f[k].out, f[0].out, n, &m1), pf = psnr8(f[k].out, fat.out, n, &mf);
        printf("thin-lpp scale %-4g: PSNR %.2f dB against scale 1 (max %d), %.2f dB against fat (max %d); "
               "re-lit %.3f %% of pixels; GPU %.1f ms (light passes %.1f ms, light-upsample %.1f ms, material %.1f ms)\n",
               (double)scales[k], p1, m1, pf, mf, 100.0 * f[k].relit, f[k].gpu_ms, f[k].light_ms, f[k].upsample_ms,
               f[k].material_ms);
        TL_CHECK(k == 0 || pf > 30.0); /* a sanity floor: the figures are in docs/frame.md */
    }
    for (int k = 0; k < 3; k++) free(f[k].out);
    free(fat.out);
    tl_scene_destroy(s);
}
