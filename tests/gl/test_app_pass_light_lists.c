/* An application pass that declares TL_TARGET_LIGHT_LISTS as a read gets the tile headers' storage
 * buffer (renderer.h, tl_app_pass_context.textures): the light-cull pass's per-tile counts, which
 * a viewer draws as lights per tile. The headers it reads inside the frame must agree with the
 * counters the renderer reports for that frame. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tl_test.h"

#include "gl/gl.h"
#include "thinlight/codec.h"
#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

#include "render_fixture.h"

#define BIT(t) TL_TARGET_BIT(t)

typedef struct lists_pass {
    const GladGLContext *gl;
    unsigned calls;
    uint32_t name;     /* what textures[TL_TARGET_LIGHT_LISTS] held */
    int is_buffer;
    GLint64 size;      /* the buffer's size in bytes */
    uint32_t *headers; /* a copy of the headers read inside the pass */
    size_t tiles;
} lists_pass;

static void lists_execute(void *user, const tl_app_pass_context *ctx)
{
    lists_pass *p = (lists_pass *)user;
    const GladGLContext *gl = p->gl;
    p->calls++;
    p->name = ctx->textures[TL_TARGET_LIGHT_LISTS];
    p->is_buffer = p->name && gl->IsBuffer(p->name);
    if (!p->is_buffer) return;
    gl->GetNamedBufferParameteri64v(p->name, GL_BUFFER_SIZE, &p->size);
    size_t bytes = 16 + 8 * p->tiles;
    if ((size_t)p->size < bytes) return;
    gl->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl->GetNamedBufferSubData(p->name, 0, (GLsizeiptr)bytes, p->headers); /* a test may wait */
}

static GLADapiproc fixture_load(void *user, const char *name)
{
    return (GLADapiproc)tl_context_get_proc_address((tl_context *)user, name);
}

/* Tiled, in every mode (Forward+ included): the pass sees a buffer of the documented layout, every
 * count is at most the scene's local lights, and the counts of tiles that kept their lists add up to
 * the entries the frame's statistics report. With light volumes there are no lists: the name is 0. */
TL_TEST(app_pass_reads_tile_light_lists)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    GladGLContext gl;
    char msg[256];
    if (tl__gl_load(&gl, fixture_load, g_ctx, msg, sizeof msg) != TL_OK) {
        fprintf(stderr, "glad: %s\n", msg);
        tl_test_failures++;
        return;
    }
    tl_scene *s = NULL;
    TL_CHECK(tl_scene_create_default(&(tl_default_scene_desc){.point_lights = 48, .detail = 1}, &s) == TL_OK);
    if (!s) return;
    size_t local = 0;
    for (size_t i = 0; i < s->light_count; i++) local += s->lights[i].type != TL_LIGHT_DIRECTIONAL;
    for (int mode = TL_MODE_THIN_LPP; mode < TL_MODE_COUNT_; mode++) {
        tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
            .renderer = {.options = {.mode = (tl_render_mode)mode, .light_strategy = TL_LIGHT_STRATEGY_TILED}, .width = 160,
                         .height = 96},
            .scene = s});
        if (!r) continue;
        tl_frame_plan plan;
        TL_CHECK(tl_renderer_get_plan(r, &plan) == TL_OK);
        lists_pass p = {.gl = &gl, .tiles = (size_t)plan.tiles_x * plan.tiles_y};
        p.headers = calloc(4 + 2 * p.tiles, sizeof *p.headers);
        tl_app_pass_desc ap = {.name = "lists", .before = "tonemap", .reads = BIT(TL_TARGET_LIGHT_LISTS),
                               .writes = BIT(TL_TARGET_HDR), .execute = lists_execute, .user = &p};
        TL_CHECK(p.headers && p.tiles > 0 && tl_renderer_add_pass(r, &ap) == TL_OK);
        tl_frame_stats st;
        TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_OK); /* with statistics: the counters are read back */
        TL_CHECK(tl_renderer_wait(r, &st) == TL_OK);
        TL_CHECK(p.calls == 1 && p.is_buffer && (size_t)p.size >= 16 + 8 * p.tiles);
        uint64_t sum = 0;
        size_t lit = 0, overflowed = 0, bad = 0;
        for (size_t t = 0; p.is_buffer && t < p.tiles; t++) {
            uint32_t first = p.headers[4 + 2 * t], count = p.headers[4 + 2 * t + 1];
            bad += count > local;
            if (first == 0xFFFFFFFFu) overflowed++;
            else sum += count;
            lit += count > 0;
        }
        printf("%s: %zu tiles, %zu with lights, %zu overflowed, %llu entries (stats %llu)\n",
               tl_render_mode_name((tl_render_mode)mode), p.tiles, lit, overflowed, (unsigned long long)sum,
               (unsigned long long)st.light_list_entries);
        TL_CHECK_EQ_U(bad, 0);
        TL_CHECK(lit > 0);
        TL_CHECK_EQ_U(overflowed, st.tile_overflows);
        if (!overflowed) TL_CHECK_EQ_U(sum, st.light_list_entries);
        TL_CHECK_EQ_U(p.headers[0], st.light_list_entries);
        free(p.headers);
        tl_renderer_destroy(r);
    }
    /* light volumes: the plan has no lists, the read is dropped and the name is 0 */
    tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){
        .renderer = {.options = {.mode = TL_MODE_THIN_LPP, .light_strategy = TL_LIGHT_STRATEGY_VOLUMES}, .width = 160,
                     .height = 96},
        .scene = s});
    if (r) {
        lists_pass p = {.gl = &gl, .name = 1};
        tl_app_pass_desc ap = {.name = "lists", .before = "tonemap", .reads = BIT(TL_TARGET_LIGHT_LISTS),
                               .writes = BIT(TL_TARGET_HDR), .execute = lists_execute, .user = &p};
        TL_CHECK(tl_renderer_add_pass(r, &ap) == TL_OK);
        TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
        TL_CHECK(p.calls == 1 && p.name == 0);
        tl_renderer_destroy(r);
    }
    tl_scene_destroy(s);
}

/* ---- every tile's count against a CPU cull -------------------------------------------------------
 *
 * light_cull.comp.glsl run again in double on the read-back depth, for every tile and local light:
 * the tile's depth bounds, its four side planes, its bounding sphere and its 2.5D depth mask (32
 * slices), the light's sphere (a spot's bounding sphere and its cone against the tile's sphere).
 * Each comparison is decided only when it holds by more than the float error of its operands (the
 * view transform, the planes and the linearised depth: 64 float roundings of the magnitudes
 * involved, and one float step of each window depth, which the texel fetch may round the other
 * way); an undecided one counts both ways. So every tile has a count of lights that surely pass and
 * of lights that may. The GPU then drops the lights that reach none of the tile's 4 x 4 blocks (each
 * block's box between its own depth bounds), so its list must hold at most the lights that may pass
 * and at least those that surely reach the surface of a pixel of the tile. A light kept at 1.03 of
 * its range moves some tile above; one culled at 0.97, or a lost block, below. As a check of the CPU
 * cull itself, every light that surely reaches the surface of some pixel of a tile (its range; a
 * spot's cone too) must surely pass for that tile. */

typedef enum tri { TRI_NO, TRI_YES, TRI_MAYBE } tri;

static tri tri_and(tri a, tri b)
{
    return a == TRI_NO || b == TRI_NO ? TRI_NO : a == TRI_YES && b == TRI_YES ? TRI_YES : TRI_MAYBE;
}
static tri tri_or(tri a, tri b)
{
    return a == TRI_YES || b == TRI_YES ? TRI_YES : a == TRI_NO && b == TRI_NO ? TRI_NO : TRI_MAYBE;
}
static tri tri_not(tri a) { return a == TRI_MAYBE ? TRI_MAYBE : a == TRI_YES ? TRI_NO : TRI_YES; }
/* x > 0, with x known within e */
static tri tri_pos(double x, double e) { return x > e ? TRI_YES : x < -e ? TRI_NO : TRI_MAYBE; }

#define FLOAT_ROUNDINGS (64.0 * 0x1.0p-24)

typedef struct cull_view {
    float view[16], proj[16];
    uint32_t w, h, tile, tiles_x, tiles_y;
    float clear;
    const float *depth; /* DEPTH read back: window depth, distance */
    tl_projection pr;
} cull_view;

/* Distance along -z of window depth d, and its error radius (one float step of d, roundings). */
static double cull_distance(const cull_view *v, float d, double *e)
{
    double z = -(double)tl_depth_linearize(&v->pr, d);
    double a = -(double)tl_depth_linearize(&v->pr, nextafterf(d, 2.0f));
    double b = -(double)tl_depth_linearize(&v->pr, nextafterf(d, -1.0f));
    *e = fmax(fabs(a - z), fabs(b - z)) + FLOAT_ROUNDINGS * z;
    return z;
}

/* The slices pixel or sphere distance `dist` may fall in (the shader's tl_slice): bits. */
static uint32_t slice_bits(double dist, double e, double zmin, double ezmin, double scale, double escale)
{
    double v = (dist - zmin) * scale, ev = (e + ezmin) * scale + fabs(dist - zmin) * escale + 32.0 * FLOAT_ROUNDINGS;
    uint32_t bits = 0;
    for (double t = v - ev;; t = floor(t) + 1.0) {
        double c = fmin(fmax(t > v + ev ? v + ev : t, 0.0), 31.0);
        bits |= 1u << (uint32_t)c;
        if (t >= v + ev) break;
    }
    return bits;
}

typedef struct cull_tile {
    int empty;
    double zmin, zmax, ezmin, ezmax, scale, escale;
    double planes[4][3];
    double sphere[4];
    uint32_t mask_sure, mask_maybe;
} cull_tile;

static void tile_setup(const cull_view *v, uint32_t tx, uint32_t ty, cull_tile *t)
{
    memset(t, 0, sizeof *t);
    uint32_t x0 = tx * v->tile, y0 = ty * v->tile, x1 = x0 + v->tile, y1 = y0 + v->tile;
    if (x1 > v->w) x1 = v->w;
    if (y1 > v->h) y1 = v->h;
    int reversed = v->clear == 0.0f;
    float nearest = reversed ? -1.0f : 2.0f, farthest = reversed ? 2.0f : -1.0f;
    size_t pixels = 0;
    for (uint32_t y = y0; y < y1; y++)
        for (uint32_t x = x0; x < x1; x++) {
            float d = v->depth[4 * ((size_t)y * v->w + x)];
            if (d == v->clear) continue;
            nearest = reversed ? fmaxf(nearest, d) : fminf(nearest, d);
            farthest = reversed ? fminf(farthest, d) : fmaxf(farthest, d);
            pixels++;
        }
    t->empty = pixels == 0;
    if (t->empty) return;
    t->zmin = cull_distance(v, nearest, &t->ezmin);
    t->zmax = cull_distance(v, farthest, &t->ezmax);
    double range = fmax(t->zmax - t->zmin, 1e-6 * fmax(t->zmax, 1.0));
    t->scale = 32.0 / range;
    t->escale = t->scale * (t->ezmin + t->ezmax) / range;
    const float iw = 1.0f / (float)v->w, ih = 1.0f / (float)v->h;
    double n0x = (float)x0 * iw * 2.0f - 1.0f, n1x = (float)x1 * iw * 2.0f - 1.0f;
    double n0y = (float)y0 * ih * 2.0f - 1.0f, n1y = (float)y1 * ih * 2.0f - 1.0f;
    const float *m = v->proj;
    double raw[4][3] = {{m[0], 0.0, m[8] + n0x}, {-m[0], 0.0, -(m[8] + n1x)},
                        {0.0, m[5], m[9] + n0y}, {0.0, -m[5], -(m[9] + n1y)}};
    for (int i = 0; i < 4; i++) {
        double l = sqrt(raw[i][0] * raw[i][0] + raw[i][1] * raw[i][1] + raw[i][2] * raw[i][2]);
        for (int k = 0; k < 3; k++) t->planes[i][k] = raw[i][k] / l;
    }
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < 8; i++) {
        double nx = i & 1 ? n1x : n0x, ny = i & 2 ? n1y : n0y, dist = i & 4 ? t->zmax : t->zmin;
        double p[3] = {dist * (nx + m[8]) / m[0], dist * (ny + m[9]) / m[5], -dist};
        for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], p[k]), hi[k] = fmax(hi[k], p[k]);
    }
    double r2 = 0.0;
    for (int k = 0; k < 3; k++) {
        t->sphere[k] = 0.5 * (lo[k] + hi[k]);
        r2 += (hi[k] - t->sphere[k]) * (hi[k] - t->sphere[k]);
    }
    t->sphere[3] = sqrt(r2);
    for (uint32_t y = y0; y < y1; y++)
        for (uint32_t x = x0; x < x1; x++) {
            float d = v->depth[4 * ((size_t)y * v->w + x)];
            if (d == v->clear) continue;
            double e, dist = cull_distance(v, d, &e);
            uint32_t b = slice_bits(dist, e, t->zmin, t->ezmin, t->scale, t->escale);
            t->mask_maybe |= b;
            if (!(b & (b - 1))) t->mask_sure |= b;
        }
}

/* A light in view space, as tl__view_light and the shader see it. */
typedef struct cull_light {
    int spot;
    double c[3], r, d[3], cos_outer, e; /* e: error radius of positions and distances */
} cull_light;

static void light_to_view(const cull_view *v, const tl_light *l, cull_light *o)
{
    const float *m = v->view;
    double mag = 0.0, dir[3] = {l->direction[0], l->direction[1], l->direction[2]};
    double dl = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    for (int k = 0; k < 3; k++) {
        o->c[k] = (double)m[k] * l->position[0] + (double)m[4 + k] * l->position[1] + (double)m[8 + k] * l->position[2] +
                  m[12 + k];
        o->d[k] = ((double)m[k] * dir[0] + (double)m[4 + k] * dir[1] + (double)m[8 + k] * dir[2]) / dl;
        mag += fabs(l->position[k]) + fabs(m[12 + k]);
    }
    o->spot = l->type == TL_LIGHT_SPOT;
    o->r = l->radius;
    o->cos_outer = l->cos_outer;
    o->e = FLOAT_ROUNDINGS * (mag + o->r + 1.0);
}

/* tl_sphere_in_tile for centre c, radius r (error radius e). */
static tri sphere_in_tile(const cull_tile *t, const double c[3], double r, double e)
{
    tri in = TRI_YES;
    for (int i = 0; i < 4; i++) {
        double d = t->planes[i][0] * c[0] + t->planes[i][1] * c[1] + t->planes[i][2] * c[2];
        in = tri_and(in, tri_not(tri_pos(-r - d, e))); /* !(d < -r) */
    }
    double zn = -c[2] + r, zf = -c[2] - r;
    in = tri_and(in, tri_and(tri_not(tri_pos(t->zmin - zn, e + t->ezmin)), tri_not(tri_pos(zf - t->zmax, e + t->ezmax))));
    if (in == TRI_NO) return TRI_NO;
    uint32_t s0 = slice_bits(zf, e, t->zmin, t->ezmin, t->scale, t->escale);
    uint32_t s1 = slice_bits(zn, e, t->zmin, t->ezmin, t->scale, t->escale);
    int lo0 = __builtin_ctz(s0), hi0 = 31 - __builtin_clz(s0), lo1 = __builtin_ctz(s1), hi1 = 31 - __builtin_clz(s1);
    uint32_t maybe = 0, sure = 0;
    for (int b = lo0; b <= hi1; b++) maybe |= 1u << b;
    for (int b = hi0; b <= lo1; b++) sure |= 1u << b;
    tri mask = (sure & t->mask_sure) ? TRI_YES : (maybe & t->mask_maybe) ? TRI_MAYBE : TRI_NO;
    return tri_and(in, mask);
}

/* tl_cone_meets_sphere against the tile's bounding sphere. */
static tri cone_meets_tile(const cull_tile *t, const cull_light *l)
{
    double cos_a = l->cos_outer, v[3], len2 = 0.0, along = 0.0;
    if (cos_a <= 0.0) return TRI_YES;
    for (int k = 0; k < 3; k++) {
        v[k] = t->sphere[k] - l->c[k];
        len2 += v[k] * v[k];
        along += v[k] * l->d[k];
    }
    double sin_a = sqrt(fmax(1.0 - cos_a * cos_a, 0.0));
    double closest = cos_a * sqrt(fmax(len2 - along * along, 0.0)) - along * sin_a;
    double e = l->e + (t->ezmax + t->ezmin) * 2.0 + FLOAT_ROUNDINGS * (sqrt(len2) + t->sphere[3]);
    tri closer = tri_pos(closest - t->sphere[3], e), beyond = tri_pos(along - (t->sphere[3] + l->r), e);
    tri behind = tri_pos(-t->sphere[3] - along, e);
    tri any = tri_or(closer, tri_or(beyond, behind)); /* closest > s.w || along > reach || along < -s.w */
    return tri_not(any);
}

static tri light_in_tile(const cull_tile *t, const cull_light *l)
{
    if (!l->spot) return sphere_in_tile(t, l->c, l->r, l->e);
    double co = fmax(l->cos_outer, 0.05), half = 0.5 * l->r, base = l->r * sqrt(1.0 - co * co) / co;
    double br = fmax(sqrt(half * half + base * base), l->r), c[3];
    for (int k = 0; k < 3; k++) c[k] = l->c[k] + l->d[k] * half;
    return tri_and(sphere_in_tile(t, c, br, l->e), cone_meets_tile(t, l));
}

/* Whether the light surely reaches the surface at some pixel of the tile. */
static int reaches_tile(const cull_view *v, uint32_t tx, uint32_t ty, const cull_light *l)
{
    for (uint32_t y = ty * v->tile; y < (ty + 1) * v->tile && y < v->h; y++)
        for (uint32_t x = tx * v->tile; x < (tx + 1) * v->tile && x < v->w; x++) {
            float d = v->depth[4 * ((size_t)y * v->w + x)];
            if (d == v->clear) continue;
            float ndc_x = ((float)x + 0.5f) / (float)v->w * 2.0f - 1.0f;
            float ndc_y = ((float)y + 0.5f) / (float)v->h * 2.0f - 1.0f;
            float p[3];
            tl_view_position_from_depth(&v->pr, ndc_x, ndc_y, d, p);
            double q[3] = {p[0] - l->c[0], p[1] - l->c[1], p[2] - l->c[2]};
            double dist = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
            double margin = 1e-3 * l->r; /* far beyond a D24 position's error at these distances */
            if (dist >= l->r - margin) continue;
            if (l->spot && (q[0] * l->d[0] + q[1] * l->d[1] + q[2] * l->d[2]) / dist <= l->cos_outer + 1e-3) continue;
            return 1;
        }
    return 0;
}

typedef struct cull_pass {
    const GladGLContext *gl;
    float view[16], proj[16];
    uint32_t *headers;
    size_t tiles;
    int ok;
} cull_pass;

static void cull_execute(void *user, const tl_app_pass_context *ctx)
{
    cull_pass *p = (cull_pass *)user;
    memcpy(p->view, ctx->view->view, sizeof p->view);
    memcpy(p->proj, ctx->view->projection, sizeof p->proj);
    uint32_t name = ctx->textures[TL_TARGET_LIGHT_LISTS];
    GLint64 size = 0;
    if (name) p->gl->GetNamedBufferParameteri64v(name, GL_BUFFER_SIZE, &size);
    p->ok = name && (size_t)size >= 16 + 8 * p->tiles;
    if (!p->ok) return;
    p->gl->MemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    p->gl->GetNamedBufferSubData(name, 0, (GLsizeiptr)(16 + 8 * p->tiles), p->headers);
}

typedef struct cull_result {
    size_t tiles, sure_entries, maybe_entries, reached_entries, gpu_entries, below, above, unreached;
} cull_result;

static void compare_tiles(const cull_view *v, const tl_scene *s, const uint32_t *headers, cull_result *res)
{
    for (uint32_t ty = 0; ty < v->tiles_y; ty++)
        for (uint32_t tx = 0; tx < v->tiles_x; tx++) {
            cull_tile t;
            tile_setup(v, tx, ty, &t);
            size_t sure = 0, maybe = 0, reached = 0, index = (size_t)ty * v->tiles_x + tx;
            uint32_t got = headers[4 + 2 * index + 1];
            for (size_t i = 0; !t.empty && i < s->light_count; i++) {
                if (s->lights[i].type == TL_LIGHT_DIRECTIONAL) continue;
                cull_light l;
                light_to_view(v, &s->lights[i], &l);
                tri in = light_in_tile(&t, &l);
                int reaches = reaches_tile(v, tx, ty, &l);
                sure += in == TRI_YES;
                maybe += in != TRI_NO;
                reached += (size_t)reaches;
                if (in != TRI_YES && reaches) res->unreached++;
            }
            /* the GPU keeps a light the tile's frustum keeps only where it may reach one of the tile's
             * blocks (light_cull.comp.glsl): between the lights that surely reach a pixel and the
             * lights the frustum test may keep */
            if (got < reached || got > maybe) {
                if (res->below + res->above < 4)
                    printf("    tile (%u, %u): %u lights in its list, %zu surely reach a pixel, the CPU cull keeps %zu at "
                           "most\n", tx, ty, got, reached, maybe);
                res->below += got < reached;
                res->above += got > maybe;
            }
            res->reached_entries += reached;
            res->tiles++;
            res->sure_entries += sure;
            res->maybe_entries += maybe;
            res->gpu_entries += got;
        }
}

/* The crypt with point and spot lights, tiled, in every mode, D24 and reversed D32F, every tile size. */
TL_TEST(tile_light_counts_match_cpu_cull)
{
    if (!ensure_context()) { tl_test_failures++; return; }
    GladGLContext gl;
    char msg[256];
    if (tl__gl_load(&gl, fixture_load, g_ctx, msg, sizeof msg) != TL_OK) {
        fprintf(stderr, "glad: %s\n", msg);
        tl_test_failures++;
        return;
    }
    tl_scene *s = NULL;
    const tl_default_scene_desc sd = {.point_lights = 96, .spot_lights = 24, .detail = 1};
    TL_CHECK(tl_scene_create_default(&sd, &s) == TL_OK);
    if (!s) return;
    const struct { tl_render_mode mode; tl_depth_format depth; uint32_t tile; } runs[] = {
        {TL_MODE_THIN_LPP, TL_DEPTH_FORMAT_D24, 8},  {TL_MODE_THIN_LPP, TL_DEPTH_FORMAT_D24, 16},
        {TL_MODE_THIN_LPP, TL_DEPTH_FORMAT_D24, 32}, {TL_MODE_THIN_LPP, TL_DEPTH_FORMAT_D32F_REVERSED, 16},
        {TL_MODE_FAT, TL_DEPTH_FORMAT_D24, 16},      {TL_MODE_FORWARD, TL_DEPTH_FORMAT_D24, 16},
        {TL_MODE_VISIBILITY, TL_DEPTH_FORMAT_D24, 16},
    };
    for (size_t k = 0; k < sizeof runs / sizeof runs[0]; k++) {
        tl_renderer_desc d = {.options.mode = runs[k].mode, .options.light_strategy = TL_LIGHT_STRATEGY_TILED,
                              .width = 160, .height = 96,
                              .options.depth_format = runs[k].depth, .options.tile_size = runs[k].tile,
                              .options.keep_targets = TL_TARGETS_ALL};
        tl_renderer *r = tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .scene = s});
        if (!r) continue;
        tl_frame_plan plan;
        TL_CHECK(tl_renderer_get_plan(r, &plan) == TL_OK);
        cull_pass p = {.gl = &gl, .tiles = (size_t)plan.tiles_x * plan.tiles_y};
        p.headers = calloc(4 + 2 * p.tiles, sizeof *p.headers);
        tl_app_pass_desc ap = {.name = "lists", .before = "tonemap", .reads = BIT(TL_TARGET_LIGHT_LISTS),
                               .writes = BIT(TL_TARGET_HDR), .execute = cull_execute, .user = &p};
        tl_frame_stats st;
        TL_CHECK(p.headers && tl_renderer_add_pass(r, &ap) == TL_OK);
        TL_CHECK(tl_renderer_render(r, NULL, &st) == TL_OK && tl_renderer_wait(r, &st) == TL_OK);
        float *depth = malloc((size_t)d.width * d.height * 4 * sizeof *depth);
        size_t size = (size_t)d.width * d.height * 4 * sizeof *depth;
        TL_CHECK(p.ok && depth && tl_renderer_read_target(r, TL_TARGET_DEPTH, depth, &size) == TL_OK);
        /* a tile whose list overflowed (the first frame at 8 px) still has its count in its header */
        if (p.ok && depth) {
            cull_view v = {.w = d.width, .h = d.height, .tile = plan.tile_size, .tiles_x = plan.tiles_x,
                           .tiles_y = plan.tiles_y, .clear = runs[k].depth == TL_DEPTH_FORMAT_D32F_REVERSED ? 0.0f : 1.0f,
                           .depth = depth};
            memcpy(v.view, p.view, sizeof v.view);
            memcpy(v.proj, p.proj, sizeof v.proj);
            memcpy(v.pr.m, p.proj, sizeof v.pr.m);
            v.pr.format = runs[k].depth;
            cull_result res = {0};
            compare_tiles(&v, s, p.headers, &res);
            printf("%-9s %-13s %2u px tiles: %zu tiles, %zu list entries (CPU cull: %zu sure, %zu at most; %zu surely "
                   "reach a pixel); %zu tiles below, %zu above; %zu lights reaching a tile not surely kept\n",
                   tl_render_mode_name(d.options.mode), tl_depth_format_name(d.options.depth_format), plan.tile_size,
                   res.tiles, res.gpu_entries, res.sure_entries, res.maybe_entries, res.reached_entries, res.below,
                   res.above, res.unreached);
            TL_CHECK(res.sure_entries > 0);
            TL_CHECK_EQ_U(res.below, 0);
            TL_CHECK_EQ_U(res.above, 0);
            TL_CHECK_EQ_U(res.unreached, 0);
        }
        free(depth);
        free(p.headers);
        tl_renderer_destroy(r);
    }
    tl_scene_destroy(s);
}
