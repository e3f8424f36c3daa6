/* MSAA (tl_renderer_options.msaa, docs/antialiasing.md): off plans today's frame byte for byte; the
 * plan's multisampled targets, their bytes and its refusals; a lit triangle over a flat background
 * resolves to the triangle's analytic coverage of each edge pixel within 1/samples, and every
 * interior pixel equals the one-sample frame within FP16 rounding, in thin-lpp (the material pass
 * multisampled over the 1x light buffer) and forward, with volumes and with tiles; per-sample edges
 * of a depth step alone (same normal, same material) classified and lit per sample; switching MSAA
 * at run time and resizing; the crypt's figures.
 * The triangle case was seen to fail under two mutations: every fragment taking its own pixel's
 * light texel (a resolved pixel off its covered sample positions by 0.28) and the tone map
 * averaging radiance before the curve (0.24). */
#include "tl_test.h"

#include <math.h>

#include "gl/gl.h"
#include "render_fixture.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

enum { W = 160, H = 90 };

/* ---- the plan ------------------------------------------------------------------------------------ */

static const tl_render_mode modes[4] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD};

TL_TEST(msaa_off_plans_todays_frame)
{
    tl_scene_feature_set f = {.point_lights = 40, .directional_lights = 1, .has_specular = 1, .has_alpha_blend = 1,
                              .alpha_blend_objects = 1};
    for (int m = 0; m < 4; m++)
        for (uint32_t off = 0; off < 2; off++) {
            tl_frame_plan a, b;
            tl_renderer_desc d = {.width = 1281, .height = 721, .options.mode = modes[m]};
            TL_CHECK(tl_frame_plan_build(&d, &f, &a) == TL_OK);
            d.options.msaa = off; /* 0 and 1: off */
            TL_CHECK(tl_frame_plan_build(&d, &f, &b) == TL_OK);
            TL_CHECK(memcmp(&a, &b, sizeof a) == 0); /* 0 bytes differ */
            TL_CHECK_EQ_U(a.msaa, 1u);
            TL_CHECK(!(a.targets & TL_TARGET_BIT(TL_TARGET_DEPTH_MSAA)));
            TL_CHECK(!(a.targets & TL_TARGET_BIT(TL_TARGET_MSAA_EDGES)));
            /* the method alone changes nothing while MSAA is off */
            for (int l = 0; l < TL_MSAA_LIGHTING_COUNT_; l++) {
                d.options.msaa_lighting = (tl_msaa_lighting)l;
                TL_CHECK(tl_frame_plan_build(&d, &f, &b) == TL_OK);
                TL_CHECK(memcmp(&a, &b, sizeof a) == 0);
            }
            for (int t = 0; t < TL_TARGET_COUNT; t++) TL_CHECK(!(a.targets & TL_TARGET_BIT(t)) || a.target_info[t].samples == 1);
        }
}

static int has_pass(const tl_frame_plan *p, tl_pass pass)
{
    for (size_t i = 0; i < p->pass_count; i++)
        if (p->passes[i].pass == pass) return 1;
    return 0;
}

/* Per-sample edges (thin-deferred, fat: the default there, and by name; thin-lpp by name): the
 * whole G-buffer (thin-lpp: and its light buffer), depth and HDR at n samples, the one-sample edge
 * mask, the classify and per-sample light passes, with volumes and tiles; no depth.msaa. */
static void check_sample_edges_plan(const tl_scene_feature_set *f, uint32_t n, tl_render_mode mode)
{
    const uint32_t fat = TL_TARGET_BIT(TL_TARGET_FAT_POSITION) | TL_TARGET_BIT(TL_TARGET_FAT_NORMAL) |
                         TL_TARGET_BIT(TL_TARGET_FAT_ALBEDO) | TL_TARGET_BIT(TL_TARGET_FAT_MATERIAL),
                   lpp = TL_TARGET_BIT(TL_TARGET_RT0) | TL_TARGET_BIT(TL_TARGET_LIGHT_DIFFUSE) |
                         TL_TARGET_BIT(TL_TARGET_LIGHT_SPECULAR);
    const uint32_t gbuffer = mode == TL_MODE_FAT        ? fat
                             : mode == TL_MODE_THIN_LPP ? lpp
                                                        : TL_TARGET_BIT(TL_TARGET_RT0) | TL_TARGET_BIT(TL_TARGET_RT1);
    for (int k = 0; k < 6; k++) { /* volumes, tiles (fragment), tiles (compute); by default and by name */
        tl_frame_plan p;
        tl_renderer_desc d = {.width = 1281, .height = 721, .options.msaa = n, .options.mode = mode};
        d.options.light_strategy = k % 3 ? TL_LIGHT_STRATEGY_TILED : TL_LIGHT_STRATEGY_VOLUMES;
        d.options.tiled_shading = k % 3 == 2 ? TL_TILED_SHADING_COMPUTE : TL_TILED_SHADING_FRAGMENT;
        int named = k >= 3 || mode == TL_MODE_THIN_LPP;
        d.options.msaa_lighting = named ? TL_MSAA_LIGHTING_SAMPLE_EDGES : TL_MSAA_LIGHTING_DEFAULT;
        TL_CHECK(tl_frame_plan_build(&d, f, &p) == TL_OK);
        TL_CHECK_EQ_U(p.msaa, n);
        TL_CHECK(strstr(p.msaa_reason, "per-sample edges") != NULL);
        TL_CHECK((p.targets & gbuffer) == gbuffer);
        for (int t = 0; t < TL_TARGET_COUNT; t++)
            if ((gbuffer | TL_TARGET_BIT(TL_TARGET_DEPTH) | TL_TARGET_BIT(TL_TARGET_HDR)) & TL_TARGET_BIT(t))
                TL_CHECK_EQ_U(p.target_info[t].samples, n);
        TL_CHECK(p.targets & TL_TARGET_BIT(TL_TARGET_MSAA_EDGES));
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_MSAA_EDGES].samples, 1u);
        TL_CHECK(!(p.targets & TL_TARGET_BIT(TL_TARGET_DEPTH_MSAA)));
        /* the compute tiled pass lights the edge samples in its own dispatch */
        TL_CHECK(has_pass(&p, TL_PASS_MSAA_CLASSIFY) && has_pass(&p, TL_PASS_LIGHTS_SAMPLES) == (k % 3 != 2));
        TL_CHECK(has_pass(&p, k % 3 ? TL_PASS_LIGHTS_TILED : TL_PASS_LIGHTS));
        TL_CHECK(has_pass(&p, TL_PASS_MATERIAL) == (mode == TL_MODE_THIN_LPP) && !has_pass(&p, TL_PASS_DEPTH_PREPASS));
        char text[8192];
        tl_frame_plan_format(&p, text, sizeof text);
        TL_CHECK(strstr(text, "msaa: ") && strstr(text, "per-sample edges") && strstr(text, "msaa.edges"));
    }
}

TL_TEST(msaa_plan_targets_and_refusals)
{
    tl_scene_feature_set f = {.point_lights = 40, .directional_lights = 1, .has_specular = 1};
    const size_t px = (size_t)1281 * 721;
    for (uint32_t n = 2; n <= 8; n *= 2) {
        tl_frame_plan p;
        tl_renderer_desc d = {.width = 1281, .height = 721, .options.msaa = n};
        TL_CHECK(tl_frame_plan_build(&d, &f, &p) == TL_OK);
        TL_CHECK_EQ_U(p.msaa, n);
        /* thin-lpp: G-buffer and light buffer at one sample; HDR and the material pass's depth at n */
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_HDR].samples, n);
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_HDR].bytes, px * 8u * n);
        TL_CHECK(p.targets & TL_TARGET_BIT(TL_TARGET_DEPTH_MSAA));
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_DEPTH_MSAA].samples, n);
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_DEPTH_MSAA].bytes, px * 4u * n);
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_DEPTH].samples, 1u);
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_RT0].samples, 1u);
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_LIGHT_DIFFUSE].samples, 1u);
        TL_CHECK(has_pass(&p, TL_PASS_DEPTH_PREPASS) && has_pass(&p, TL_PASS_MATERIAL));
        /* no multisampled target shares memory with a one-sample one */
        for (int t = 0; t < TL_TARGET_COUNT; t++)
            for (int u = 0; u < TL_TARGET_COUNT; u++)
                if ((p.targets & TL_TARGET_BIT(t)) && (p.targets & TL_TARGET_BIT(u)) &&
                    p.target_info[t].block == p.target_info[u].block)
                    TL_CHECK(p.target_info[t].samples == p.target_info[u].samples);
        char text[8192];
        tl_frame_plan_format(&p, text, sizeof text);
        TL_CHECK(strstr(text, "depth.msaa") && strstr(text, "samples") && strstr(text, "msaa: "));
        /* forward: its own depth is multisampled */
        d.options.mode = TL_MODE_FORWARD;
        TL_CHECK(tl_frame_plan_build(&d, &f, &p) == TL_OK);
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_DEPTH].samples, n);
        TL_CHECK_EQ_U(p.target_info[TL_TARGET_HDR].samples, n);
        TL_CHECK(!(p.targets & TL_TARGET_BIT(TL_TARGET_DEPTH_MSAA)));
        /* thin-lpp's material pass asked for by name is the default's plan */
        tl_frame_plan q;
        d.options.mode = TL_MODE_THIN_LPP;
        TL_CHECK(tl_frame_plan_build(&d, &f, &p) == TL_OK);
        d.options.msaa_lighting = TL_MSAA_LIGHTING_MATERIAL_PASS;
        TL_CHECK(tl_frame_plan_build(&d, &f, &q) == TL_OK);
        TL_CHECK(memcmp(&p, &q, sizeof p) == 0);
        d.options.msaa_lighting = TL_MSAA_LIGHTING_DEFAULT;
        check_sample_edges_plan(&f, n, TL_MODE_THIN_LPP);
        check_sample_edges_plan(&f, n, TL_MODE_THIN_DEFERRED);
        check_sample_edges_plan(&f, n, TL_MODE_FAT);
    }
    /* planned without, and said why: a method a mode lacks, per-sample edges with a reduced light
     * buffer, a reduced light buffer, effects */
    tl_renderer_desc refused[9] = {
        {.options.mode = TL_MODE_FAT, .options.msaa_lighting = TL_MSAA_LIGHTING_MATERIAL_PASS},
        {.options.mode = TL_MODE_VISIBILITY, .options.msaa_lighting = TL_MSAA_LIGHTING_MATERIAL_PASS},
        {.options.mode = TL_MODE_THIN_DEFERRED, .options.msaa_lighting = TL_MSAA_LIGHTING_MATERIAL_PASS},
        {.options.msaa_lighting = TL_MSAA_LIGHTING_SAMPLE_EDGES, .options.light_scale = 0.5f},
        {.options.mode = TL_MODE_FORWARD, .options.msaa_lighting = TL_MSAA_LIGHTING_SAMPLE_EDGES},
        {.options.mode = TL_MODE_FAT, .options.ssao = {.enabled = 1, .method = TL_SSAO_DISC}},
        {.options.light_scale = 0.5f}, {.options.ssao = {.enabled = 1, .method = TL_SSAO_DISC}}, {.options.bloom.enabled = 1}};
    for (int i = 0; i < 9; i++) {
        tl_frame_plan p, off;
        refused[i].options.msaa = 4;
        TL_CHECK(tl_frame_plan_build(&refused[i], &f, &p) == TL_OK);
        TL_CHECK_EQ_U(p.msaa, 1u);
        TL_CHECK(strstr(p.msaa_reason, "asked, but") != NULL);
        /* a downgrade: listed with what was asked and why (logged and printed from the list) */
        TL_CHECK_EQ_U(p.downgrade_count, 1);
        TL_CHECK(!strcmp(p.downgrades[0].option, "msaa") && !strcmp(p.downgrades[0].asked, "4") &&
                 !strcmp(p.downgrades[0].planned, "1") && strstr(p.msaa_reason, p.downgrades[0].reason));
        refused[i].options.msaa = 0;
        TL_CHECK(tl_frame_plan_build(&refused[i], &f, &off) == TL_OK);
        memset(p.msaa_reason, 0, sizeof p.msaa_reason);
        memset(p.downgrades, 0, sizeof p.downgrades);
        p.downgrade_count = 0;
        TL_CHECK(memcmp(&p, &off, sizeof p) == 0);
    }
    tl_frame_plan p;
    const uint32_t bad[3] = {3, 16, 5};
    for (int i = 0; i < 3; i++)
        TL_CHECK(tl_frame_plan_build(&(tl_renderer_desc){.options.msaa = bad[i]}, &f, &p) == TL_ERROR_INVALID_ARGUMENT);
}

/* ---- a lit triangle over a flat background ---------------------------------------------------------- */

typedef struct tri_scene {
    tl_vertex v[7];
    uint32_t idx[9];
    tl_object obj[2];
    tl_material mat[2];
    tl_light light;
    tl_scene s;
    double sx[3], sy[3]; /* the triangle's corners in pixels (x right, y up from the bottom row) */
} tri_scene;

static const double FOV = 1.0471975511965976; /* 60 degrees */

/* View space (camera at the origin looking down -Z) of pixel position (x, y) at depth z. */
static void unproject(double x, double y, double z, float out[3])
{
    double t = tan(FOV / 2.0), aspect = (double)W / H;
    out[0] = (float)((2.0 * x / W - 1.0) * -z * t * aspect);
    out[1] = (float)((2.0 * y / H - 1.0) * -z * t);
    out[2] = (float)z;
}

static void tri_scene_init(tri_scene *t)
{
    memset(t, 0, sizeof *t);
    /* corners off the pixel grid, edges of several slopes, counter-clockwise on screen */
    const double sx[3] = {20.3, 141.6, 63.15}, sy[3] = {9.7, 31.2, 80.85};
    static const double bx[4] = {-2, W + 2, W + 2, -2}, by[4] = {-2, -2, H + 2, H + 2};
    for (int i = 0; i < 4; i++) { /* the background quad at z = -10 */
        unproject(bx[i], by[i], -10.0, t->v[i].position);
        t->v[i].normal[2] = 1.0f;
    }
    for (int i = 0; i < 3; i++) {
        t->sx[i] = sx[i];
        t->sy[i] = sy[i];
        unproject(sx[i], sy[i], -5.0, t->v[4 + i].position);
        /* a shading normal tilted away from the light: the triangle's light differs from the
         * background's (2 x 0.6 against 2), so a sample lit with the other surface's texel shows */
        t->v[4 + i].normal[0] = 0.8f;
        t->v[4 + i].normal[2] = 0.6f;
    }
    static const uint32_t idx[9] = {0, 1, 2, 0, 2, 3, 4, 5, 6};
    memcpy(t->idx, idx, sizeof idx);
    t->obj[0] = (tl_object){.first_index = 0, .index_count = 6, .material = 0};
    t->obj[1] = (tl_object){.first_index = 6, .index_count = 3, .material = 1};
    t->mat[0] = (tl_material){.albedo = {0.1f, 0.1f, 0.1f}};
    t->mat[1] = (tl_material){.albedo = {0.8f, 0.8f, 0.8f}};
    t->light = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {0, 0, -1}, .color = {2, 2, 2}};
    t->s = (tl_scene){.vertices = t->v, .vertex_count = 7, .indices = t->idx, .index_count = 9, .objects = t->obj,
                      .object_count = 2, .materials = t->mat, .material_count = 2, .lights = &t->light, .light_count = 1};
    t->s.camera = (tl_camera){.target = {0, 0, -1}, .fov_y = (float)FOV, .near_z = 0.5f, .far_z = 50.0f};
}

/* The area of pixel (i, j) inside the triangle: the pixel square clipped by each edge's half-plane. */
static double coverage(const tri_scene *t, int i, int j)
{
    double px[16], py[16], qx[16], qy[16];
    size_t n = 4;
    const double cx[4] = {i, i + 1, i + 1, i}, cy[4] = {j, j, j + 1, j + 1};
    memcpy(px, cx, sizeof cx);
    memcpy(py, cy, sizeof cy);
    for (int e = 0; e < 3; e++) {
        double ax = t->sx[e], ay = t->sy[e], bx = t->sx[(e + 1) % 3], by = t->sy[(e + 1) % 3];
        size_t m = 0;
        for (size_t k = 0; k < n; k++) {
            size_t l = (k + 1) % n;
            double dk = (bx - ax) * (py[k] - ay) - (by - ay) * (px[k] - ax);
            double dl = (bx - ax) * (py[l] - ay) - (by - ay) * (px[l] - ax);
            if (dk >= 0) qx[m] = px[k], qy[m++] = py[k];
            if ((dk >= 0) != (dl >= 0)) {
                double s = dk / (dk - dl);
                qx[m] = px[k] + s * (px[l] - px[k]);
                qy[m++] = py[k] + s * (py[l] - py[k]);
            }
        }
        memcpy(px, qx, m * sizeof *px);
        memcpy(py, qy, m * sizeof *py);
        n = m;
    }
    double a = 0.0;
    for (size_t k = 0; k < n; k++) a += px[k] * py[(k + 1) % n] - px[(k + 1) % n] * py[k];
    return fabs(a) / 2.0;
}

/* The context's sample positions for n samples (within the pixel, y up), from a multisampled
 * framebuffer; 0 when they cannot be read. */
static GLADapiproc load_proc(void *user, const char *name) { return (GLADapiproc)tl_context_get_proc_address(user, name); }

static int sample_positions(uint32_t n, float pos[8][2])
{
    GladGLContext gl;
    char msg[256];
    if (tl__gl_load(&gl, load_proc, g_ctx, msg, sizeof msg) != TL_OK) return 0;
    tl__target t;
    GLuint fbo = 0;
    if (tl__target_create(&gl, &(tl__target_desc){"test.samples", GL_RGBA8, 4, 4, n}, &t, msg, sizeof msg) != TL_OK) return 0;
    const tl__target *c = &t;
    int ok = tl__framebuffer_create(&gl, "test.samples", &c, 1, NULL, &fbo, msg, sizeof msg) == TL_OK;
    GLint bound = 0;
    gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    for (uint32_t i = 0; ok && i < n; i++) gl.GetMultisamplefv(GL_SAMPLE_POSITION, i, pos[i]);
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, (GLuint)bound);
    tl__framebuffer_destroy(&gl, &fbo);
    tl__target_destroy(&gl, &t);
    return ok;
}

/* The fraction of pixel (i, j)'s sample positions inside the triangle. */
static double sampled_coverage(const tri_scene *t, int i, int j, uint32_t n, float pos[8][2])
{
    uint32_t in = 0;
    for (uint32_t k = 0; k < n; k++) {
        double x = i + pos[k][0], y = j + pos[k][1];
        int inside = 1;
        for (int e = 0; e < 3; e++) {
            double ax = t->sx[e], ay = t->sy[e], bx = t->sx[(e + 1) % 3], by = t->sy[(e + 1) % 3];
            inside &= (bx - ax) * (y - ay) - (by - ay) * (x - ax) >= 0.0;
        }
        in += (uint32_t)inside;
    }
    return (double)in / n;
}

static double srgb_decode(uint8_t v)
{
    double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

typedef struct frame {
    uint8_t out[W * H * 4];
    float *hdr;
    double relit, edges; /* relit_fraction (material pass), msaa_edge_fraction (per-sample edges) */
    uint32_t samples;    /* tl_frame_plan.msaa: the samples the targets have (a count the context has) */
} frame;

/* How the lights are gathered: volumes, or tiles with the fragment or the compute light pass. */
typedef struct lit_by {
    tl_light_strategy st;
    tl_tiled_shading shading;
} lit_by;
static const lit_by by_volumes = {TL_LIGHT_STRATEGY_VOLUMES, TL_TILED_SHADING_FRAGMENT},
                    by_tiles = {TL_LIGHT_STRATEGY_TILED, TL_TILED_SHADING_FRAGMENT},
                    by_tiles_compute = {TL_LIGHT_STRATEGY_TILED, TL_TILED_SHADING_COMPUTE};

static int render_frame(const tl_scene *s, tl_render_mode mode, lit_by by, uint32_t msaa, tl_msaa_lighting how, frame *f)
{
    tl_renderer_desc d = {.width = W, .height = H};
    d.options.msaa_lighting = how;
    d.options.mode = mode;
    d.options.light_strategy = by.st;
    d.options.tiled_shading = by.shading;
    d.options.msaa = msaa;
    d.options.fxaa = TL_FXAA_OFF;
    d.options.ambient[0] = d.options.ambient[1] = d.options.ambient[2] = -1.0f;
    tl_renderer *r = tl_test_render_once(s, d);
    size_t size = sizeof f->out;
    tl_frame_plan plan;
    int ok = r && tl_renderer_read_output(r, f->out, &size) == TL_OK && tl_renderer_get_plan(r, &plan) == TL_OK;
    f->samples = ok ? plan.msaa : 0;
    f->hdr = ok ? tl_test_read_target(r, TL_TARGET_HDR, (size_t)W * H) : NULL;
    tl_frame_stats st_out; /* the count of a frame waited for */
    int waited = ok && tl_renderer_render(r, NULL, &st_out) == TL_OK && tl_renderer_wait(r, &st_out) == TL_OK;
    f->relit = waited ? st_out.relit_fraction : 0.0;
    f->edges = waited ? st_out.msaa_edge_fraction : 0.0;
    tl_renderer_destroy(r);
    return ok && f->hdr;
}

/* Whether every pixel within one pixel of (i, j) has coverage exactly 0 or exactly 1 alike. */
static int interior(const tri_scene *t, int i, int j)
{
    double c0 = coverage(t, i, j);
    if (c0 != 0.0 && c0 != 1.0) return 0;
    for (int y = j - 1; y <= j + 1; y++)
        for (int x = i - 1; x <= i + 1; x++)
            if (x >= 0 && y >= 0 && x < W && y < H && coverage(t, x, y) != c0) return 0;
    return 1;
}

/* Edge pixels: the resolved coverage (from the tone-mapped linear output between the two surfaces'
 * interior values) against the analytic area; interior pixels: HDR against the one-sample frame. */
static void check_triangle(tl_render_mode mode, lit_by by, uint32_t n, int light_only, tl_msaa_lighting how)
{
    static tri_scene t;
    tri_scene_init(&t);
    /* light_only: both surfaces of one albedo, so an edge pixel's mix is the two lights' alone */
    if (light_only) {
        t.mat[0].albedo[0] = t.mat[0].albedo[1] = t.mat[0].albedo[2] = 0.3f;
        t.mat[1] = t.mat[0];
    }
    static frame one, ms;
    if (!render_frame(&t.s, mode, by, 1, TL_MSAA_LIGHTING_DEFAULT, &one) || !render_frame(&t.s, mode, by, n, how, &ms)) {
        TL_CHECK(!"rendered");
        free(one.hdr), free(ms.hdr), one.hdr = ms.hdr = NULL;
        return;
    }
    /* the samples the frame has: n, or the next count the context has (llvmpipe: 2 gives 4) */
    TL_CHECK(ms.samples >= n);
    n = ms.samples;
    float pos[8][2];
    TL_CHECK(sample_positions(n, pos));
    double lin_in = -1.0, lin_out = -1.0, worst_edge = 0.0, worst_sampled = 0.0, worst_interior = 0.0;
    size_t edges = 0, inside = 0;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            if (!interior(&t, i, j)) continue;
            size_t k = (size_t)j * W + (size_t)i;
            double *l = coverage(&t, i, j) > 0.5 ? &lin_in : &lin_out;
            if (*l < 0.0) *l = srgb_decode(ms.out[4 * k + 1]);
            for (int c = 0; c < 3; c++) {
                double a = ms.hdr[4 * k + (size_t)c], b = one.hdr[4 * k + (size_t)c];
                double e = fabs(a - b) / fmax(fabs(b), 1e-3);
                if (e > worst_interior) worst_interior = e;
            }
            inside++;
        }
    /* one 8-bit step of the output, in coverage: the steepest sRGB step between the two values */
    double step = (srgb_decode(255) - srgb_decode(254)) / fabs(lin_in - lin_out);
    /* partial: edge pixels with sample positions on both sides; mixed: those resolved strictly
     * between the two surfaces' values, by more than a step */
    size_t partial = 0, mixed = 0;
    for (int j = 0; j < H; j++)
        for (int i = 0; i < W; i++) {
            double c = coverage(&t, i, j);
            if (c <= 0.0 || c >= 1.0) continue;
            size_t k = (size_t)j * W + (size_t)i;
            double got = (srgb_decode(ms.out[4 * k + 1]) - lin_out) / (lin_in - lin_out);
            if (fabs(got - c) > worst_edge) worst_edge = fabs(got - c);
            double sc = sampled_coverage(&t, i, j, n, pos);
            if (fabs(got - sc) > worst_sampled) worst_sampled = fabs(got - sc);
            partial += sc > 0.0 && sc < 1.0;
            mixed += sc > 0.0 && sc < 1.0 && got > step && got < 1.0 - step;
            edges++;
        }
    printf("%s/%s%s msaa %u%s%s: %zu edge pixels (%zu with samples on both sides, %zu mixed), worst |resolved - analytic coverage| %.3f (1/samples "
           "%.3f), |resolved - covered sample positions| %.4f (one 8-bit step %.4f); %zu interior pixels, worst "
           "relative HDR difference %.2g; re-lit %.2f %%, per-sample edges %.2f %%\n",
           tl_render_mode_name(mode), tl_light_strategy_name(by.st), by.shading == TL_TILED_SHADING_COMPUTE ? " (compute)" : "", n, how == TL_MSAA_LIGHTING_SAMPLE_EDGES ? " per-sample edges" : "",
           light_only ? " (light only)" : "", edges, partial, mixed,
           worst_edge, 1.0 / n, worst_sampled, step, inside, worst_interior, 100.0 * ms.relit, 100.0 * ms.edges);
    TL_CHECK(fabs(lin_in - lin_out) > (light_only ? 0.1 : 0.3) && edges > 200 && inside > (size_t)W * H / 2);
    /* a pixel with samples on both surfaces is a mix of both (its samples lit apart), not either alone */
    TL_CHECK(partial > 50 && mixed == partial);
    /* those pixels, and no other, lit per sample (msaa-classify's count; visibility classifies no
     * edges: its resolve shades each triangle of a pixel once, whatever samples it covers) */
    if (how == TL_MSAA_LIGHTING_SAMPLE_EDGES && mode != TL_MODE_VISIBILITY) {
        double classified = ms.edges * W * H;
        TL_CHECK(classified > partial - 0.5 && classified < partial + 0.5);
    }
    /* every sample has its own surface's colour: the resolve is the covered positions' share */
    TL_CHECK_LE(worst_sampled, step);
    /* two positions sample a corner pixel's area coarsely (0.68 measured); from 4 on, 1/samples holds */
    if (n >= 4) TL_CHECK_LE(worst_edge, 1.0 / n + step);
    TL_CHECK_LE(worst_interior, 1.0 / 1024.0); /* FP16: both round to a half ulp, 2^-11 each */
    free(one.hdr);
    free(ms.hdr);
    one.hdr = ms.hdr = NULL;
}

static uint32_t max_samples(void)
{
    /* the most a context of this kind allows among 2, 4 and 8: the first that plans and renders */
    uint32_t best = 1;
    tri_scene *t = malloc(sizeof *t);
    if (!t) return best;
    tri_scene_init(t);
    for (uint32_t n = 2; n <= 8; n *= 2) {
        tl_renderer_desc d = {.width = 8, .height = 8, .options.msaa = n, .options.mode = TL_MODE_FORWARD,
                              .get_proc_address = tl_context_proc_loader, .get_proc_address_user = g_ctx};
        tl_renderer *r = NULL;
        int ok = tl_renderer_create(&d, &r) == TL_OK && tl_renderer_set_scene(r, &t->s) == TL_OK &&
                 tl_renderer_render(r, NULL, NULL) == TL_OK;
        if (!ok && r) TL_CHECK(strstr(tl_renderer_last_error(r), "GL_MAX_SAMPLES") != NULL); /* the limit, named */
        tl_renderer_destroy(r);
        if (!ok) break;
        best = n;
    }
    free(t);
    return best;
}

TL_TEST(msaa_triangle_edge_coverage_and_interior_pixels)
{
    if (!ensure_context()) return;
    uint32_t top = max_samples();
    printf("samples the context allows: %u\n", top);
    TL_CHECK(top >= 4); /* llvmpipe: 4 */
    for (uint32_t n = 2; n <= top; n *= 2)
        for (int k = 0; k < 2; k++) {
            lit_by by = k ? by_tiles : by_volumes;
            check_triangle(TL_MODE_THIN_LPP, by, n, 0, TL_MSAA_LIGHTING_DEFAULT);
            check_triangle(TL_MODE_FORWARD, by, n, 0, TL_MSAA_LIGHTING_DEFAULT);
        }
}

/* MSAA with per-sample lighting on edges (thin-lpp, thin-deferred, fat; visibility shades each
 * triangle of a pixel once, at its first sample where it covers some): the same coverage and interior
 * checks, and the edge pixels of two surfaces that differ only in their light resolve to the mix
 * of both lights (a pixel lit once, from one surface, would be either alone); volumes and the
 * fragment tiled pass here, the compute tiled pass in its own test below. */
static void check_sample_edges(lit_by by)
{
    uint32_t top = max_samples();
    const tl_render_mode modes4[4] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_VISIBILITY};
    for (uint32_t n = 2; n <= top; n *= 2)
        for (int m = 0; m < 4; m++) {
            if (modes4[m] == TL_MODE_VISIBILITY && by.st != TL_LIGHT_STRATEGY_TILED) continue; /* tiles only */
            check_triangle(modes4[m], by, n, 0, TL_MSAA_LIGHTING_SAMPLE_EDGES);
            check_triangle(modes4[m], by, n, 1, TL_MSAA_LIGHTING_SAMPLE_EDGES);
        }
}

TL_TEST(msaa_sample_edges_triangle_coverage_and_per_sample_light)
{
    if (!ensure_context()) return;
    check_sample_edges(by_volumes);
    check_sample_edges(by_tiles);
}

TL_TEST(msaa_sample_edges_compute_tiled_triangle_coverage_and_per_sample_light)
{
    if (!ensure_context()) return;
    check_sample_edges(by_tiles_compute);
}

/* ---- the tile lists' depth bounds ------------------------------------------------------------------ */

/* The samples a target asked for `n` really has in this context (GL_SAMPLES of a framebuffer). */
static uint32_t context_samples(uint32_t n)
{
    GladGLContext gl;
    char msg[256];
    if (tl__gl_load(&gl, load_proc, g_ctx, msg, sizeof msg) != TL_OK) return 0;
    tl__target t;
    GLuint fbo = 0;
    if (tl__target_create(&gl, &(tl__target_desc){"test.samples", GL_RGBA16F, 4, 4, n}, &t, msg, sizeof msg) != TL_OK)
        return 0;
    const tl__target *c = &t;
    GLint samples = 0, bound = 0;
    if (tl__framebuffer_create(&gl, "test.samples", &c, 1, NULL, &fbo, msg, sizeof msg) == TL_OK) {
        gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
        gl.GetIntegerv(GL_SAMPLES, &samples);
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, (GLuint)bound);
    }
    tl__framebuffer_destroy(&gl, &fbo);
    tl__target_destroy(&gl, &t);
    return (uint32_t)samples;
}

enum { STRIPS = 5 };

typedef struct strip_scene {
    tl_vertex v[4 + 4 * STRIPS];
    uint32_t idx[6 + 6 * STRIPS];
    tl_object obj[2];
    tl_material mat[1];
    tl_light light;
    tl_scene s;
    int rows[STRIPS]; /* the pixel row each strip crosses */
} strip_scene;

/* A far wall (z = -30) and, near the camera (z = -2), one thin strip across the width in each tile
 * row, so thin that of each pixel's samples it covers only sample `s` (a band of rows j + y_s +- d
 * with no other sample's y inside); a point light in front of the strips reaches them and not the
 * wall. Where the tile culling's depth bounds leave sample s out, a tile's depth range is the
 * wall's alone and the light is culled from it: the strips' samples go dark. */
static int strip_scene_init(strip_scene *t, float pos[8][2], uint32_t n, uint32_t s)
{
    memset(t, 0, sizeof *t);
    double half = 1.0;
    for (uint32_t k = 0; k < n; k++)
        if (k != s) half = fmin(half, fabs((double)pos[k][1] - pos[s][1]) / 2.0);
    if (!(half > 1e-3)) return 0; /* another sample at the same height: not a band of sample s alone */
    half *= 0.8;
    static const double bx[4] = {-2, W + 2, W + 2, -2}, by[4] = {-2, -2, H + 2, H + 2};
    for (int i = 0; i < 4; i++) {
        unproject(bx[i], by[i], -30.0, t->v[i].position);
        t->v[i].normal[2] = 1.0f;
    }
    static const uint32_t quad[6] = {0, 1, 2, 0, 2, 3};
    for (int q = 0; q <= STRIPS; q++) {
        for (int i = 0; i < 6; i++) t->idx[6 * q + i] = (uint32_t)(4 * q) + quad[i];
        if (q == 0) continue;
        int row = 8 + 16 * (q - 1);
        t->rows[q - 1] = row;
        const double y0 = row + pos[s][1] - half, y1 = row + pos[s][1] + half, sy[4] = {y0, y0, y1, y1};
        for (int i = 0; i < 4; i++) {
            unproject(bx[i], sy[i], -2.0, t->v[4 * q + i].position);
            t->v[4 * q + i].normal[2] = 1.0f;
        }
    }
    t->obj[0] = (tl_object){.first_index = 0, .index_count = 6};
    t->obj[1] = (tl_object){.first_index = 6, .index_count = 6 * STRIPS};
    t->mat[0] = (tl_material){.albedo = {0.8f, 0.8f, 0.8f}};
    t->light = (tl_light){.type = TL_LIGHT_POINT, .position = {0, 0, -1.5f}, .color = {4, 4, 4}, .radius = 3};
    t->s = (tl_scene){.vertices = t->v, .vertex_count = 4 + 4 * STRIPS, .indices = t->idx, .index_count = 6 + 6 * STRIPS,
                      .objects = t->obj, .object_count = 2, .materials = t->mat, .material_count = 1,
                      .lights = &t->light, .light_count = 1};
    t->s.camera = (tl_camera){.target = {0, 0, -1}, .fov_y = (float)FOV, .near_z = 0.5f, .far_z = 50.0f};
    return 1;
}

/* With MSAA the tile lists bound every sample's depth, for every count asked: a count the context
 * lacks (llvmpipe: 2) plans the count its targets really have (4), so the culling, the resolve and
 * every sample loop count the same samples. Forward+ and thin-lpp's tiles against the same frame
 * lit by volumes (forward: per-object lists), HDR resolved over every sample: the strips, seen by
 * the last sample alone, lit alike. Before: asked 2, the targets had 4 samples and the culling read
 * 2, so the strips' light was culled (Forward+ darker on every strip row). */
TL_TEST(msaa_tile_depth_bounds_cover_every_sample)
{
    if (!ensure_context()) return;
    uint32_t top = max_samples();
    static strip_scene t;
    const tl_render_mode modes2[2] = {TL_MODE_FORWARD, TL_MODE_THIN_LPP};
    for (uint32_t asked = 2; asked <= top; asked *= 2) {
        uint32_t real = context_samples(asked);
        float pos[8][2];
        TL_CHECK(real >= asked && real <= 8 && sample_positions(real, pos));
        if (!(real >= asked && real <= 8) || !strip_scene_init(&t, pos, real, real - 1)) {
            TL_CHECK(!"a band of the last sample alone");
            continue;
        }
        for (int m = 0; m < 2; m++) {
            static frame tiled, volumes;
            int ok = render_frame(&t.s, modes2[m], by_tiles, asked, TL_MSAA_LIGHTING_DEFAULT, &tiled) &&
                     render_frame(&t.s, modes2[m], by_volumes, asked, TL_MSAA_LIGHTING_DEFAULT, &volumes);
            TL_CHECK(ok);
            if (!ok) {
                free(tiled.hdr), free(volumes.hdr), tiled.hdr = volumes.hdr = NULL;
                continue;
            }
            /* on the strip rows: how much light the volumes give, and how much of it the tiles lose */
            double lit = 0.0, worst = 0.0;
            size_t dark = 0, pixels = 0;
            for (int q = 0; q < STRIPS; q++)
                for (int i = 0; i < W; i++) {
                    size_t k = (size_t)t.rows[q] * W + (size_t)i;
                    double a = tiled.hdr[4 * k + 1], b = volumes.hdr[4 * k + 1];
                    lit = fmax(lit, b);
                    worst = fmax(worst, fabs(a - b) / fmax(b, 1e-3));
                    dark += a < 0.5 * b;
                    pixels++;
                }
            printf("%s msaa %u asked, %u planned (the targets have %u): strip rows lit up to %.3f by volumes; tiles: "
                   "%zu of %zu pixels below half of it, worst relative difference %.2g\n",
                   tl_render_mode_name(modes2[m]), asked, tiled.samples, real, lit, dark, pixels, worst);
            TL_CHECK_EQ_U(tiled.samples, real);
            TL_CHECK_EQ_U(volumes.samples, real);
            TL_CHECK(lit > 0.05); /* the strips' sample carries light the culling can lose */
            TL_CHECK_EQ_U(dark, 0);
            TL_CHECK_LE(worst, 1.0 / 256.0);
            free(tiled.hdr), free(volumes.hdr), tiled.hdr = volumes.hdr = NULL;
        }
    }
}

/* ---- an edge of depth alone ------------------------------------------------------------------------- */

/* The triangle raised over its background with nothing else different: both face the camera (normal
 * +Z), one material, lit by a point light 2 m behind the camera, 7 m from the triangle's plane and
 * 12 m from the background's (its light about 3 times the background's). parts: 1 the background at z = -10
 * (4: moved to z = -5, the triangle's plane over the whole frame), 2 the triangle at z = -5. */
static void depth_scene_init(tri_scene *t, int parts)
{
    static const double bx[4] = {-2, W + 2, W + 2, -2}, by[4] = {-2, -2, H + 2, H + 2};
    tri_scene_init(t);
    for (int i = 0; i < 4; i++) unproject(bx[i], by[i], parts & 4 ? -5.0 : -10.0, t->v[i].position);
    for (int i = 4; i < 7; i++) t->v[i].normal[0] = 0.0f, t->v[i].normal[2] = 1.0f;
    t->mat[0] = (tl_material){.albedo = {0.5f, 0.5f, 0.5f}};
    t->obj[1].material = 0;
    t->s.material_count = 1;
    t->light = (tl_light){.type = TL_LIGHT_POINT, .position = {0.3f, -0.2f, 2.0f}, .color = {40, 40, 40},
                          .radius = 40.0f};
    if (!(parts & 2)) t->s.object_count = 1, t->s.index_count = 6;
}

/* The frame's 8-bit output and, with per-sample edges, its msaa.edges target (R: 1 marked). */
static int render_depth_frame(const tl_scene *s, tl_render_mode mode, lit_by by, uint32_t msaa, uint8_t *out,
                              float **edges)
{
    tl_renderer_desc d = {.width = W, .height = H};
    d.options.mode = mode;
    d.options.light_strategy = by.st;
    d.options.tiled_shading = by.shading;
    d.options.msaa = msaa;
    d.options.msaa_lighting = msaa > 1 ? TL_MSAA_LIGHTING_SAMPLE_EDGES : TL_MSAA_LIGHTING_DEFAULT;
    d.options.fxaa = TL_FXAA_OFF;
    d.options.ambient[0] = d.options.ambient[1] = d.options.ambient[2] = -1.0f;
    tl_renderer *r = tl_test_render_once(s, d);
    size_t size = (size_t)W * H * 4;
    int ok = r && tl_renderer_read_output(r, out, &size) == TL_OK;
    if (ok && edges) ok = (*edges = tl_test_read_target(r, TL_TARGET_MSAA_EDGES, (size_t)W * H)) != NULL;
    tl_renderer_destroy(r);
    return ok;
}

/* The continuous 8-bit sRGB code of linear v. */
static double srgb_encode8(double v)
{
    v = fmin(fmax(v, 0.0), 1.0);
    return 255.0 * (v <= 0.0031308 ? 12.92 * v : 1.055 * pow(v, 1.0 / 2.4) - 0.055);
}

static double srgb_decode_c(double code) /* a continuous code, clamped to 0..255 */
{
    double c = fmin(fmax(code, 0.0), 255.0) / 255.0;
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

/* The least and the largest code of channel c over pixel k's 3 x 3 neighbourhood: the light at a
 * point within half a pixel of k's centre (a sample's) lies between them (one plane, one point
 * light: a smooth field, near linear over a pixel). */
static void code_range(const uint8_t *out, size_t k, int c, double r[2])
{
    int i = (int)(k % W), j = (int)(k / W);
    r[0] = 255.0, r[1] = 0.0;
    for (int y = j - 1; y <= j + 1; y++)
        for (int x = i - 1; x <= i + 1; x++) {
            if (x < 0 || y < 0 || x >= W || y >= H) continue;
            double v = out[4 * ((size_t)y * W + (size_t)x) + (size_t)c];
            r[0] = fmin(r[0], v), r[1] = fmax(r[1], v);
        }
}

/* The figures of one multisampled frame against the two one-sample frames. */
typedef struct depth_edge {
    size_t mixed, marked, wrong_marks, outside;
    double worst, width, apart; /* codes beyond the interval; the widest interval; the frames' least difference */
} depth_edge;

/* Per-sample edges of a depth step alone with n samples: msaa.edges marks exactly the pixels whose
 * sample positions lie on both surfaces (the geometry's, with the context's positions), and every
 * pixel resolves to its samples' mix of the two surfaces' one-sample frames (near: the triangle's
 * plane drawn alone over the frame; far: the background alone): the covered positions' share k / n
 * of near and the rest of far, mixed in linear light (each sample tone-mapped, then averaged). The
 * thin modes light a sample at its own position, so each frame's value is taken over the 3 x 3
 * pixels around (code_range); interval: those codes +- 1/2 (their rounding), the mix's relative FP16
 * step either way, the output's code +- 1/2. Interior pixels (k = 0 or n) are lit once. */
static depth_edge measure_depth_edge(const tri_scene *t, uint32_t n, float pos[8][2], const uint8_t *near,
                                     const uint8_t *far, const uint8_t *ms, const float *edges)
{
    depth_edge e = {.apart = 255.0};
    for (size_t k = 0; k < (size_t)W * H; k++) {
        double sc = sampled_coverage(t, (int)(k % W), (int)(k / W), n, pos), a[2], b[2];
        int mix = sc > 0.0 && sc < 1.0, mark = edges[4 * k] > 0.5f;
        e.mixed += (size_t)mix, e.marked += (size_t)mark, e.wrong_marks += (size_t)(mix != mark);
        for (int c = 0; c < 3; c++) {
            code_range(near, k, c, a);
            code_range(far, k, c, b);
            double lo = sc * srgb_decode_c(a[0] - 0.5) + (1.0 - sc) * srgb_decode_c(b[0] - 0.5);
            double hi = sc * srgb_decode_c(a[1] + 0.5) + (1.0 - sc) * srgb_decode_c(b[1] + 0.5);
            lo = srgb_encode8(lo * (1.0 - 1.0 / 1024.0)), hi = srgb_encode8(hi * (1.0 + 1.0 / 1024.0));
            double got = ms[4 * k + (size_t)c], beyond = fmax(lo - 0.5 - got, got - hi - 0.5);
            if (mix) e.width = fmax(e.width, hi - lo + 1.0);
            if (mix) e.apart = fmin(e.apart, fabs((double)near[4 * k + (size_t)c] - far[4 * k + (size_t)c]));
            if (beyond > 0.0) e.outside++, e.worst = fmax(e.worst, beyond);
        }
    }
    return e;
}

/* A depth step with the same normal and material on both sides (the classification by depth alone,
 * docs/antialiasing.md): thin-lpp, thin-deferred and fat, 2 and 4 samples, light volumes and the
 * compute tiled pass (which lights the edge samples itself). */
TL_TEST(msaa_sample_edges_depth_step_alone_classified_and_lit_per_sample)
{
    if (!ensure_context()) return;
    static tri_scene full, near, far;
    static uint8_t one[2][W * H * 4], ms[W * H * 4];
    depth_scene_init(&full, 3);
    depth_scene_init(&near, 6);
    depth_scene_init(&far, 1);
    const tl_render_mode modes3[3] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT};
    const lit_by bys[2] = {by_volumes, by_tiles_compute};
    for (int m = 0; m < 3; m++) {
        TL_CHECK(render_depth_frame(&near.s, modes3[m], by_volumes, 1, one[0], NULL) &&
                 render_depth_frame(&far.s, modes3[m], by_volumes, 1, one[1], NULL));
        for (uint32_t n = 2; n <= 4; n *= 2)
            for (int k = 0; k < 2; k++) {
                float pos[8][2], *edges = NULL;
                uint32_t real = context_samples(n); /* asked n, the targets have real (llvmpipe: 4 for 2) */
                TL_CHECK(real >= n && real <= 8 && sample_positions(real, pos));
                if (!render_depth_frame(&full.s, modes3[m], bys[k], n, ms, &edges)) {
                    TL_CHECK(!"rendered");
                    continue;
                }
                depth_edge e = measure_depth_edge(&full, real, pos, one[0], one[1], ms, edges);
                printf("%s/%s msaa %u per-sample edges, depth step alone: %zu pixels with samples on both surfaces, "
                       "%zu marked (%zu differ); %zu channels beyond their interval (worst by %.2f codes); on those "
                       "pixels the two frames differ by %.0f codes at least, the widest interval is %.1f\n",
                       tl_render_mode_name(modes3[m]), k ? "tiled (compute)" : "volumes", n, e.mixed, e.marked,
                       e.wrong_marks, e.outside, e.worst, e.apart, e.width);
                TL_CHECK(e.mixed > 50 && e.apart > 2.0 * e.width);
                TL_CHECK_EQ_U(e.wrong_marks, 0);
                TL_CHECK_EQ_U(e.outside, 0);
                free(edges);
            }
    }
}

/* ---- run-time switches ------------------------------------------------------------------------------ */

TL_TEST(msaa_set_options_and_resize_match_a_new_renderer)
{
    if (!ensure_context()) return;
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 24, .detail = 1}, &s) == TL_OK);
    if (!s) return;
    tl_renderer_desc d = {.width = W, .height = H};
    d.options.fxaa = TL_FXAA_OFF;
    tl_renderer *r = tl_test_render_once(s, d);
    static uint8_t a[W * H * 4 * 4], b[W * H * 4 * 4];
    const uint32_t steps[4][3] = {{4, W, H}, {1, W, H}, {4, 2 * W + 1, H + 3}, {2, W, H}};
    for (int i = 0; r && i < 4; i++) {
        tl_renderer_options o = d.options;
        o.msaa = steps[i][0];
        TL_CHECK(tl_renderer_set_options(r, &o) == TL_OK);
        TL_CHECK(tl_renderer_resize(r, steps[i][1], steps[i][2]) == TL_OK);
        TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
        size_t size = sizeof a, n = (size_t)steps[i][1] * steps[i][2] * 4;
        TL_CHECK(tl_renderer_read_output(r, a, &size) == TL_OK);
        tl_renderer_desc fresh = {.width = steps[i][1], .height = steps[i][2], .options = o};
        tl_renderer *q = tl_test_render_once(s, fresh);
        size = sizeof b;
        TL_CHECK(q && tl_renderer_read_output(q, b, &size) == TL_OK);
        TL_CHECK(memcmp(a, b, n) == 0);
        tl_renderer_destroy(q);
    }
    tl_renderer_destroy(r);
    tl_scene_destroy(s);
}

/* ---- the crypt ------------------------------------------------------------------------------------------ */

static double psnr8(const uint8_t *a, const uint8_t *b, size_t n, int *max)
{
    double se = 0.0;
    *max = 0;
    for (size_t i = 0; i < n; i++) {
        if (i % 4 == 3) continue;
        int d = abs((int)a[i] - (int)b[i]);
        if (d > *max) *max = d;
        se += (double)d * d;
    }
    double mse = se / ((double)n * 0.75);
    return mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : INFINITY;
}

/* thin-lpp's MSAA against forward's (the same samples, each lit exactly): the edge samples that
 * take a neighbour's light or are re-lit are the whole difference. */
TL_TEST(msaa_crypt_thin_lpp_against_forward_printed)
{
    if (!ensure_context()) return;
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(NULL, &s) == TL_OK);
    if (!s) return;
    enum { CW = 640, CH = 360 };
    static uint8_t out[4][CW * CH * 4];
    double relit = 0.0;
    for (int k = 0; k < 4; k++) {
        tl_renderer_desc d = {.width = CW, .height = CH};
        d.options.mode = k & 1 ? TL_MODE_FORWARD : TL_MODE_THIN_LPP;
        d.options.msaa = k & 2 ? 4 : 1;
        d.options.fxaa = TL_FXAA_OFF;
        tl_renderer *r = tl_test_render_once(s, d);
        size_t size = sizeof out[k];
        TL_CHECK(r && tl_renderer_read_output(r, out[k], &size) == TL_OK);
        tl_frame_stats st; /* a frame measured and waited for */
        if (r && k == 2 && tl_renderer_render(r, NULL, &st) == TL_OK && tl_renderer_wait(r, &st) == TL_OK)
            relit = st.relit_fraction;
        tl_renderer_destroy(r);
    }
    int m1, m4;
    double p1 = psnr8(out[0], out[1], sizeof out[0], &m1), p4 = psnr8(out[2], out[3], sizeof out[2], &m4);
    printf("crypt %dx%d: thin-lpp against forward: %.2f dB (max %d) at 1 sample, %.2f dB (max %d) at 4; "
           "thin-lpp msaa 4 re-lit %.2f %% of the pixels' fragments\n",
           CW, CH, p1, m1, p4, m4, 100.0 * relit);
    /* re-lit samples are lit as forward lights them: what remains is the codec's error (p1) and
     * the samples that kept a texel of a surface within half a pixel's slope and 25 degrees
     * (55.2 dB measured); the truth comparison is the bench's (docs/antialiasing.md) */
    TL_CHECK(p4 > 50.0);
    TL_CHECK(relit > 0.0 && relit < 0.15);
    tl_scene_destroy(s);
}

/* ---- the compute tiled pass against the fragment one ------------------------------------------------ */

/* The crypt with per-sample edges, lit by the fragment and by the compute tiled pass: the same
 * G-buffer, lists, lights and order of summation, so a sample's float sum differs at most by the
 * two programs' compilations, and its FP16 value by one rounding (2^-11 relative) each way; the
 * resolved HDR by 2^-10 relative, the 8-bit output by one step. */
TL_TEST_FULL(msaa_sample_edges_compute_tiled_matches_fragment_tiled)
{
    if (!ensure_context()) return;
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(NULL, &s) == TL_OK);
    if (!s) return;
    enum { CW = 320, CH = 180 };
    static uint8_t out[2][CW * CH * 4];
    const tl_render_mode modes3[3] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT};
    for (uint32_t n = 2; n <= 4; n *= 2)
        for (int m = 0; m < 3; m++) {
            float *hdr[2] = {NULL, NULL};
            double edges[2] = {0.0, 0.0};
            for (int k = 0; k < 2; k++) {
                tl_renderer_desc d = {.width = CW, .height = CH};
                d.options.mode = modes3[m];
                d.options.msaa = n;
                d.options.msaa_lighting = TL_MSAA_LIGHTING_SAMPLE_EDGES;
                d.options.light_strategy = TL_LIGHT_STRATEGY_TILED;
                d.options.tiled_shading = k ? TL_TILED_SHADING_COMPUTE : TL_TILED_SHADING_FRAGMENT;
                d.options.fxaa = TL_FXAA_OFF;
                tl_renderer *r = tl_test_render_once(s, d);
                size_t size = sizeof out[k];
                TL_CHECK(r && tl_renderer_read_output(r, out[k], &size) == TL_OK);
                hdr[k] = r ? tl_test_read_target(r, TL_TARGET_HDR, (size_t)CW * CH) : NULL;
                tl_frame_stats st;
                if (r && tl_renderer_render(r, NULL, &st) == TL_OK && tl_renderer_wait(r, &st) == TL_OK)
                    edges[k] = st.msaa_edge_fraction;
                tl_renderer_destroy(r);
            }
            double worst = 0.0;
            for (size_t i = 0; hdr[0] && hdr[1] && i < (size_t)CW * CH * 4; i++)
                if (i % 4 != 3) worst = fmax(worst, fabs(hdr[0][i] - hdr[1][i]) / fmax(fabs(hdr[0][i]), 1e-3));
            int max8;
            double p = psnr8(out[0], out[1], sizeof out[0], &max8);
            printf("crypt %dx%d %s msaa %u per-sample edges: compute against fragment tiled: %.2f dB, max %d steps, "
                   "worst relative HDR difference %.2g; edges %.2f %% and %.2f %%\n",
                   CW, CH, tl_render_mode_name(modes3[m]), n, p, max8, worst, 100.0 * edges[0], 100.0 * edges[1]);
            TL_CHECK(hdr[0] && hdr[1]);
            TL_CHECK(edges[0] > 0.01 && edges[0] == edges[1]); /* the same pixels lit per sample */
            TL_CHECK_LE(worst, 1.0 / 1024.0);
            TL_CHECK(max8 <= 1);
            free(hdr[0]);
            free(hdr[1]);
        }
    tl_scene_destroy(s);
}
