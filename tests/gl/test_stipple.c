/* Transparency through the light buffer (Inferred Lighting's stipple; docs/frame.md, "2d.
 * Transparency through the light buffer"): the planner stipples only what fits and plans today's
 * frame without blended materials; one pane and three overlapping panes over a lit plane match the
 * forward mode's full-resolution transparency within a bound derived per pixel; more than three
 * blended objects plan forward; odd sizes render without GL errors; and the figures (time and
 * error of both methods on the crypt behind glass) are printed.
 *
 * The bound. Both filters (shaders/stipple_gather.glsl) return a convex combination of the light at
 * G-buffer samples of the same surface within two pixels (weights >= 0, normalised), or light the
 * fragment itself from its object's lights as forward does. So each component of the final colour
 * (the opaque plane, and each pane's alpha x lit colour) is off by at most the range of that
 * component over the pixels it covers among the 5x5 around it, and the panes in front only scale it
 * by (1 - alpha) <= 1.
 * The components come from forward renders of the plane alone and of each pane alone over a black
 * plane; bound = sum of their 5x5 ranges + (2^-7 |reference| + 10^-4). The last term is the
 * precision both frames share: FP16 rounding of the light sum, HDR and three blends in each frame
 * (8 x 2^-11) plus the octahedral normal's 0.04 degrees in n.l up to 80 degrees of incidence
 * (tan 80 x 6.9e-4 = 3.9e-3), together under 2^-7; 10^-4 where a light's window reaches 0.
 * Mutations: an opaque pixel keeping the sample a layer took fails (worst ratio 42); dropping the
 * depth weight passes (0.15: the plane's and the panes' normals differ), and so does dropping the
 * depth and the normal weights together (0.38): at the panes' edges the light of the plane and of
 * the pane are close in this scene, so the bound does not hold the same-surface weights to account. */
#include "tl_test.h"

#include <math.h>
#include <time.h>

#include "render_fixture.h"
#include "thinlight/metrics.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

/* ---- a plane and panes ------------------------------------------------------------------------ */

enum { MAX_QUADS = 6, W = 160, H = 90 };

typedef struct glass_scene {
    tl_vertex v[4 * MAX_QUADS];
    uint32_t idx[6 * MAX_QUADS];
    tl_object obj[MAX_QUADS];
    tl_material mat[MAX_QUADS];
    tl_light light[4];
    tl_scene s;
} glass_scene;

/* A quad from corner o along edges a and b (counter-clockwise seen from where a x b points). */
static void add_quad(glass_scene *g, const float o[3], const float a[3], const float b[3], const tl_material *m)
{
    size_t q = g->s.object_count;
    float n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int i = 0; i < 4; i++) {
        tl_vertex *x = &g->v[4 * q + (size_t)i];
        memset(x, 0, sizeof *x);
        float u = (i == 1 || i == 2) ? 1.0f : 0.0f, w = i >= 2 ? 1.0f : 0.0f;
        for (int k = 0; k < 3; k++) {
            x->position[k] = o[k] + u * a[k] + w * b[k];
            x->normal[k] = n[k] / len;
        }
    }
    static const uint32_t t[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++) g->idx[6 * q + (size_t)i] = (uint32_t)(4 * q) + t[i];
    g->mat[q] = *m;
    g->obj[q] = (tl_object){.first_index = (uint32_t)(6 * q), .index_count = 6, .material = (uint32_t)q};
    g->s.object_count++;
    g->s.material_count++;
    g->s.vertex_count += 4;
    g->s.index_count += 6;
}

/* A diffuse plane under three point lights and a directional one; `panes` glass panes (0..5)
 * between it and the camera, overlapping on screen; `only` >= 0 keeps pane `only` alone; a black
 * plane with `black_plane`. */
static void glass_init(glass_scene *g, int panes, int only, int black_plane)
{
    memset(g, 0, sizeof *g);
    g->s.vertices = g->v;
    g->s.indices = g->idx;
    g->s.objects = g->obj;
    g->s.materials = g->mat;
    g->s.lights = g->light;
    const tl_material plane = {.albedo = {0.7f, 0.6f, 0.5f}}, black = {.albedo = {-1.0f, -1.0f, -1.0f}};
    add_quad(g, (const float[3]){-10.0f, 0.0f, 10.0f}, (const float[3]){20.0f, 0.0f, 0.0f},
             (const float[3]){0.0f, 0.0f, -20.0f}, black_plane ? &black : &plane);
    for (int i = 0; i < panes; i++) {
        if (only >= 0 && i != only) continue;
        tl_material glass = {.albedo = {0.2f + 0.2f * (float)i, 0.6f, 0.5f - 0.1f * (float)i}, .alpha = 0.4f,
                             .flags = TL_MATERIAL_ALPHA_BLEND};
        float x = -1.6f + 0.45f * (float)i, z = 2.4f - 0.5f * (float)i;
        add_quad(g, (const float[3]){x, 0.15f + 0.1f * (float)i, z}, (const float[3]){2.2f, 0.0f, 0.0f},
                 (const float[3]){0.0f, 1.6f, 0.0f}, &glass);
    }
    g->light[0] = (tl_light){.type = TL_LIGHT_POINT, .position = {-1.2f, 0.8f, 0.6f}, .color = {2.5f, 2.0f, 1.6f}, .radius = 6.0f};
    g->light[1] = (tl_light){.type = TL_LIGHT_POINT, .position = {1.8f, 0.5f, -1.5f}, .color = {0.8f, 1.4f, 2.4f}, .radius = 5.0f};
    g->light[2] = (tl_light){.type = TL_LIGHT_POINT, .position = {0.3f, 1.4f, 3.6f}, .color = {2.0f, 2.0f, 2.0f}, .radius = 5.0f};
    g->light[3] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {0.3f, -1.0f, -0.4f}, .color = {0.3f, 0.3f, 0.35f}};
    g->s.light_count = 4;
    g->s.camera = (tl_camera){.position = {0.0f, 2.2f, 6.5f}, .target = {0.0f, 0.6f, 0.0f}, .near_z = 0.1f, .far_z = 100.0f};
}

/* HDR of one frame (ambient off), malloc'd; NULL when it failed. */
static float *hdr_of(const tl_scene *s, tl_render_mode mode, tl_transparency t, tl_plan_pass *passes, size_t *npasses)
{
    tl_renderer_desc d = {.width = W, .height = H};
    d.options.mode = mode;
    d.options.transparency = t;
    d.options.ambient[0] = d.options.ambient[1] = d.options.ambient[2] = -1.0f;
    tl_renderer *r = tl_test_render_once(s, d);
    float *p = r ? tl_test_read_target(r, TL_TARGET_HDR, (size_t)W * H) : NULL;
    tl_frame_plan plan;
    if (r && passes && tl_renderer_get_plan(r, &plan) == TL_OK) {
        memcpy(passes, plan.passes, plan.pass_count * sizeof *passes);
        *npasses = plan.pass_count;
    }
    tl_renderer_destroy(r);
    TL_CHECK(p != NULL);
    return p;
}

/* Adds the range of image `c` over the pixels it covers (not black) among the 5x5 around every
 * pixel to `bound`: the filters take samples of the same surface only. */
static void add_range(const float *c, double *bound)
{
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            for (int ch = 0; ch < 3; ch++) {
                double lo = INFINITY, hi = -INFINITY;
                for (int dy = -2; dy <= 2; dy++)
                    for (int dx = -2; dx <= 2; dx++) {
                        int qx = x + dx, qy = y + dy;
                        if (qx < 0 || qy < 0 || qx >= W || qy >= H) continue;
                        const float *px = &c[4 * ((size_t)qy * W + (size_t)qx)];
                        if (px[0] <= 0.0f && px[1] <= 0.0f && px[2] <= 0.0f) continue;
                        double v = px[ch];
                        lo = fmin(lo, v);
                        hi = fmax(hi, v);
                    }
                if (hi >= lo) bound[3 * ((size_t)y * W + (size_t)x) + (size_t)ch] += hi - lo;
            }
}

/* With TL_TEST_IMAGE_DIR set: `name`.ppm, HDR tone-mapped as x / (1 + x), rows top-down; with
 * `ref`, the difference scaled by `gain` instead. For looking at, never compared. */
static void write_ppm(const char *name, const float *hdr, const float *ref, double gain)
{
    const char *dir = getenv("TL_TEST_IMAGE_DIR");
    if (!dir || !hdr) return;
    char path[512];
    snprintf(path, sizeof path, "%s/%s.ppm", dir, name);
    FILE *f = fopen(path, "wb");
    if (!f) return;
    fprintf(f, "P6\n%d %d\n255\n", W, H);
    for (int y = H - 1; y >= 0; y--)
        for (int x = 0; x < W; x++)
            for (int c = 0; c < 3; c++) {
                size_t i = 4 * ((size_t)y * W + (size_t)x) + (size_t)c;
                double v = ref ? gain * fabs((double)hdr[i] - ref[i]) : pow(hdr[i] / (1.0 + hdr[i]), 1.0 / 2.2);
                fputc((int)(255.0 * fmin(fmax(v, 0.0), 1.0) + 0.5), f);
            }
    fclose(f);
}

static int has_pass(const tl_plan_pass *p, size_t n, tl_pass id)
{
    for (size_t i = 0; i < n; i++)
        if (p[i].pass == id) return 1;
    return 0;
}

/* Stipple against the forward mode, `panes` panes: every pixel within its bound. */
static void check_against_forward(int panes)
{
    if (!ensure_context()) return;
    glass_scene *g = calloc(1, sizeof *g);
    double *bound = calloc((size_t)W * H * 3, sizeof *bound);
    if (!g || !bound) {
        free(g);
        free(bound);
        return;
    }
    tl_plan_pass passes[TL_PLAN_MAX_PASSES];
    size_t np = 0;
    glass_init(g, panes, -1, 0);
    float *ref = hdr_of(&g->s, TL_MODE_FORWARD, TL_TRANSPARENCY_DEFAULT, NULL, NULL);
    float *got = hdr_of(&g->s, TL_MODE_THIN_LPP, TL_TRANSPARENCY_STIPPLE, passes, &np);
    TL_CHECK(has_pass(passes, np, TL_PASS_STIPPLE) && has_pass(passes, np, TL_PASS_STIPPLE_RESOLVE));
    TL_CHECK(!has_pass(passes, np, TL_PASS_TRANSPARENT));
    for (int c = -1; c < panes; c++) { /* the plane alone, then each pane alone over a black plane */
        glass_init(g, c < 0 ? 0 : panes, c, c >= 0);
        float *part = hdr_of(&g->s, TL_MODE_FORWARD, TL_TRANSPARENCY_DEFAULT, NULL, NULL);
        if (part) add_range(part, bound);
        free(part);
    }
    double worst = 0.0, sum = 0.0;
    size_t covered = 0;
    for (size_t i = 0; ref && got && i < (size_t)W * H; i++)
        for (int ch = 0; ch < 3; ch++) {
            double r = ref[4 * i + (size_t)ch], e = fabs((double)got[4 * i + (size_t)ch] - r);
            double b = bound[3 * i + (size_t)ch] + ldexp(fabs(r), -7) + 1e-4;
            worst = fmax(worst, e / b);
            sum += e;
        }
    for (size_t i = 0; ref && i < (size_t)W * H; i++) covered += ref[4 * i] > 0.0f;
    char name[64];
    snprintf(name, sizeof name, "stipple_%d_forward", panes);
    write_ppm(name, ref, NULL, 0.0);
    snprintf(name, sizeof name, "stipple_%d_stipple", panes);
    write_ppm(name, got, NULL, 0.0);
    snprintf(name, sizeof name, "stipple_%d_error_x100", panes);
    write_ppm(name, got, ref, 100.0);
    printf("%d pane%s over a lit plane, %dx%d: mean error %.3g, worst error / bound %.3f (%zu lit pixels)\n", panes,
           panes == 1 ? "" : "s", W, H, sum / (3.0 * W * H), worst, covered);
    TL_CHECK(covered > (size_t)W * H / 2);
    TL_CHECK_LE(worst, 1.0);
    free(ref);
    free(got);
    free(bound);
    free(g);
}

TL_TEST(transparency_stipple_one_pane_matches_forward) { check_against_forward(1); }

TL_TEST(transparency_stipple_three_layers_match_forward) { check_against_forward(3); }

/* ---- the planner ---------------------------------------------------------------------------------- */

TL_TEST(transparency_stipple_plan_rules)
{
    tl_scene_feature_set f = {.point_lights = 40, .directional_lights = 1, .has_specular = 1, .has_textures = 1};
    tl_frame_plan base, other;
    const tl_transparency ts[3] = {TL_TRANSPARENCY_DEFAULT, TL_TRANSPARENCY_FORWARD, TL_TRANSPARENCY_STIPPLE};
    /* no blended material: today's frame whatever the option, 0 bytes differ */
    TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.width = 1280, .height = 720}, &f, &base) == TL_OK);
    for (int t = 0; t < 3; t++) {
        TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.width = 1280, .height = 720, .options.transparency = ts[t]}, &f,
                                     &other) == TL_OK);
        TL_CHECK(memcmp(&base, &other, sizeof base) == 0);
    }
    TL_CHECK(!(base.targets & TL_TARGET_BIT(TL_TARGET_OPAQUE_DEPTH)));
    /* one to three blended objects: the stipple's passes and its 4 B/px */
    f.has_alpha_blend = 1;
    for (size_t n = 1; n <= 4; n++) {
        f.alpha_blend_objects = n;
        tl_frame_plan p, fwd;
        TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.width = 1280, .height = 720}, &f, &p) == TL_OK);
        TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.width = 1280, .height = 720,
                                                         .options.transparency = TL_TRANSPARENCY_FORWARD},
                                     &f, &fwd) == TL_OK);
        int stippled = has_pass(p.passes, p.pass_count, TL_PASS_STIPPLE);
        TL_CHECK(stippled == (n <= 3));
        TL_CHECK(has_pass(p.passes, p.pass_count, TL_PASS_TRANSPARENT) == (n > 3));
        TL_CHECK(p.transparency == (n <= 3 ? TL_TRANSPARENCY_STIPPLE : TL_TRANSPARENCY_FORWARD));
        TL_CHECK(fwd.transparency == TL_TRANSPARENCY_FORWARD && has_pass(fwd.passes, fwd.pass_count, TL_PASS_TRANSPARENT));
        char text[8192];
        tl_frame_plan_format(&p, text, sizeof text);
        if (n <= 3) {
            TL_CHECK_EQ_U(p.target_bytes_per_pixel[TL_TARGET_OPAQUE_DEPTH], 4);
            TL_CHECK_EQ_U(p.allocated_bytes_per_pixel, fwd.allocated_bytes_per_pixel + 4);
            TL_CHECK(strstr(text, "stipple-depth") && strstr(text, "stipple-blend") && strstr(text, "opaque.depth") &&
                     strstr(text, "transparency: stipple"));
        } else {
            TL_CHECK(strstr(p.transparency_reason, "4 blended objects > 3") != NULL);
            TL_CHECK(strstr(text, "transparency: forward") && !strstr(text, "opaque.depth"));
            /* the fallback is exactly the forward frame but for the reason */
            memset(p.transparency_reason, 0, sizeof p.transparency_reason);
            memset(fwd.transparency_reason, 0, sizeof fwd.transparency_reason);
            TL_CHECK(memcmp(&p, &fwd, sizeof p) == 0);
        }
    }
    /* what falls back, and says why */
    f.alpha_blend_objects = 2;
    struct { tl_renderer_options o; const char *why; } cases[] = {
        {{.light_scale = 0.5f}, "collapse"},
        {{.mode = TL_MODE_FAT}, "thin-lpp"},
        {{.mode = TL_MODE_FORWARD, .transparency = TL_TRANSPARENCY_STIPPLE}, "stipple asked, but"},
        {{.fog = {.enabled = 1, .mode = TL_FOG_DISTANCE}}, "fog"},
        {{.transparency = TL_TRANSPARENCY_FORWARD}, "forced"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        tl_frame_plan p;
        TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.width = 64, .height = 64, .options = cases[i].o}, &f, &p) == TL_OK);
        TL_CHECK(p.transparency == TL_TRANSPARENCY_FORWARD && !has_pass(p.passes, p.pass_count, TL_PASS_STIPPLE));
        TL_CHECK(strstr(p.transparency_reason, cases[i].why) != NULL);
    }
    tl_scene_feature_set dark = f;
    dark.point_lights = dark.directional_lights = 0;
    TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.width = 64, .height = 64}, &dark, &other) == TL_OK);
    TL_CHECK(other.transparency == TL_TRANSPARENCY_FORWARD);
    tl_scene_feature_set uncounted = f; /* made by hand: blended, but how many is unknown */
    uncounted.alpha_blend_objects = 0;
    TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.width = 64, .height = 64}, &uncounted, &other) == TL_OK);
    TL_CHECK(other.transparency == TL_TRANSPARENCY_FORWARD && strstr(other.transparency_reason, "not counted"));
    TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.options.transparency = TL_TRANSPARENCY_COUNT_}, &f, &other) ==
             TL_ERROR_INVALID_ARGUMENT);
    tl_transparency t;
    TL_CHECK(tl_transparency_from_name("stipple", &t) == TL_OK && t == TL_TRANSPARENCY_STIPPLE);
    TL_CHECK(strcmp(tl_transparency_name(TL_TRANSPARENCY_DEFAULT), "auto") == 0);
    TL_CHECK(tl_transparency_from_name("dither", &t) == TL_ERROR_INVALID_ARGUMENT);
}

/* The renderer counts the blended objects a scene draws: four panes fall back, and removing one
 * stipples again (a hidden object still counts: the plan does not change with visibility). */
TL_TEST(transparency_stipple_four_panes_fall_back_to_forward)
{
    if (!ensure_context()) return;
    glass_scene *g = calloc(1, sizeof *g);
    if (!g) return;
    glass_init(g, 4, -1, 0);
    tl_renderer_desc d = {.width = W, .height = H};
    tl_renderer *r = tl_test_render_once(&g->s, d);
    tl_frame_plan p;
    if (r && tl_renderer_get_plan(r, &p) == TL_OK) {
        TL_CHECK(p.transparency == TL_TRANSPARENCY_FORWARD && has_pass(p.passes, p.pass_count, TL_PASS_TRANSPARENT));
        printf("four panes: %s (%s)\n", tl_transparency_name(p.transparency), p.transparency_reason);
        TL_CHECK(tl_renderer_remove_object(r, 4) == TL_OK);
        TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK && tl_renderer_wait(r, NULL) == TL_OK);
        TL_CHECK(tl_renderer_get_plan(r, &p) == TL_OK);
        printf("three panes: %s (%s)\n", tl_transparency_name(p.transparency), p.transparency_reason);
        TL_CHECK(p.transparency == TL_TRANSPARENCY_STIPPLE && has_pass(p.passes, p.pass_count, TL_PASS_STIPPLE));
    } else {
        TL_CHECK(!"render or plan");
    }
    tl_renderer_destroy(r);
    free(g);
}

/* ---- odd sizes ----------------------------------------------------------------------------------- */

TL_TEST(transparency_stipple_odd_sizes_render_without_gl_errors)
{
    if (!ensure_context()) return;
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 8, .detail = 1, .glass_panes = 3}, &s) ==
             TL_OK);
    if (!s) return;
    const uint32_t sizes[4][2] = {{1, 1}, {7, 3}, {2, 2}, {33, 17}};
    const tl_depth_format depths[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    for (int z = 0; z < 4; z++)
        for (int k = 0; k < 2; k++) {
            tl_renderer_desc d = {.width = sizes[z][0], .height = sizes[z][1]};
            d.options.depth_format = depths[k];
            tl_renderer *r = tl_test_render_once(s, d);
            tl_frame_plan p;
            TL_CHECK(r != NULL && tl_renderer_get_plan(r, &p) == TL_OK && p.transparency == TL_TRANSPARENCY_STIPPLE);
            if (r) TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK && tl_renderer_wait(r, NULL) == TL_OK);
            tl_renderer_destroy(r);
        }
    tl_scene_destroy(s);
}

/* ---- the figures: the crypt behind glass ----------------------------------------------------------
 * Three overlapping panes across the nave (tl_default_scene_desc.glass_panes) with 16 to 1024 point
 * lights (and lights / 8 spots, the moonlight): the forward mode is the reference (full-resolution
 * forward transparency); thin-lpp renders the panes forward and stippled. Final images (8-bit). GPU
 * times: the three renderers take turns for ROUNDS synchronous frames after a first one, each
 * figure the median of its rounds, so a change in the machine's load falls on all three alike. A
 * measurement, not a speed test: it asserts only that the stipple stays close to the reference. */
enum { METHODS = 3, ROUNDS = 9 };

typedef struct method_run {
    tl_renderer *r;
    uint8_t *rgba;
    double ms[5][ROUNDS]; /* frame, lights, material (forward: its pre-pass and shading), transparency */
} method_run;

static double median_of(double *v, int n)
{
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && v[j - 1] > v[j]; j--) {
            double t = v[j];
            v[j] = v[j - 1];
            v[j - 1] = t;
        }
    return v[n / 2];
}

static void record(method_run *m, const tl_frame_stats *st, int round)
{
    const double *p = st->pass_ms;
    m->ms[0][round] = st->gpu_ms;
    m->ms[1][round] = p[TL_PASS_LIGHTS] + p[TL_PASS_LIGHTS_TILED] + p[TL_PASS_LIGHT_CULL];
    m->ms[2][round] = p[TL_PASS_MATERIAL] + p[TL_PASS_FORWARD] + p[TL_PASS_DEPTH_PREPASS];
    m->ms[3][round] = p[TL_PASS_TRANSPARENT] + p[TL_PASS_STIPPLE_DEPTH] + p[TL_PASS_STIPPLE] + p[TL_PASS_STIPPLE_RESOLVE];
    m->ms[4][round] = p[TL_PASS_STIPPLE_RESOLVE];
}

TL_TEST_FULL(transparency_stipple_figures_printed)
{
    if (!ensure_context()) return;
    uint32_t w = 640, h = 360, counts[4] = {16, 64, 256, 1024}, ncounts = 4;
    const char *only = getenv("TL_STIPPLE_FIGURES_LIGHTS"); /* one count (4096: the crossover), 9 rounds */
    int rounds = only ? ROUNDS : 5;
    if (only) {
        counts[0] = (uint32_t)strtoul(only, NULL, 10);
        ncounts = 1;
    }
    const char *names[METHODS] = {"forward mode (reference)", "thin-lpp, forward", "thin-lpp, stipple"};
    const tl_render_mode modes[METHODS] = {TL_MODE_FORWARD, TL_MODE_THIN_LPP, TL_MODE_THIN_LPP};
    const tl_transparency ts[METHODS] = {TL_TRANSPARENCY_FORWARD, TL_TRANSPARENCY_FORWARD, TL_TRANSPARENCY_STIPPLE};
    printf("crypt, 3 glass panes, %ux%u, GPU ms (medians of %d interleaved frames); final image against the forward mode\n",
           w, h, only ? ROUNDS : 5);
    printf("%6s | %-24s | %8s %8s %9s %13s %8s | %8s %7s\n", "lights", "method", "frame", "lights", "material",
           "transparency", "(blend)", "PSNR dB", "max err");
    for (uint32_t c = 0; c < ncounts; c++) {
        tl_scene *s = NULL;
        TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = counts[c], .glass_panes = 3}, &s) ==
                 TL_OK);
        if (!s) return;
        method_run runs[METHODS];
        memset(runs, 0, sizeof runs);
        int ok = 1;
        for (int m = 0; m < METHODS; m++) {
            tl_renderer_desc d = {.width = w, .height = h};
            d.options.mode = modes[m];
            d.options.transparency = ts[m];
            d.options.synchronous_stats = 1;
            runs[m].r = tl_test_render_once(s, d);
            ok = ok && runs[m].r;
        }
        for (int k = 0; ok && k < rounds; k++)
            for (int m = 0; ok && m < METHODS; m++) {
                tl_frame_stats st;
                ok = tl_renderer_render(runs[m].r, NULL, &st) == TL_OK;
                record(&runs[m], &st, k);
            }
        TL_CHECK(ok);
        for (int m = 0; ok && m < METHODS; m++) {
            size_t size = (size_t)w * h * 4;
            runs[m].rgba = malloc(size);
            ok = runs[m].rgba && tl_renderer_read_output(runs[m].r, runs[m].rgba, &size) == TL_OK;
        }
        for (int m = 0; ok && m < METHODS; m++) {
            tl_image_error e = {0};
            tl_image_compare_u8(runs[m].rgba, runs[0].rgba, (size_t)w * h * 4, &e);
            double f[5];
            for (int q = 0; q < 5; q++) f[q] = median_of(runs[m].ms[q], rounds);
            printf("%6u | %-24s | %8.1f %8.1f %9.1f %13.1f %8.1f | %8.1f %7.0f\n", counts[c], names[m], f[0], f[1], f[2],
                   f[3], f[4], m ? e.psnr_db : INFINITY, m ? e.max_abs : 0.0);
            if (m == 2) TL_CHECK(e.psnr_db > 40.0);
        }
        for (int m = 0; m < METHODS; m++) {
            free(runs[m].rgba);
            tl_renderer_destroy(runs[m].r);
        }
        tl_scene_destroy(s);
        fflush(stdout);
    }
}
