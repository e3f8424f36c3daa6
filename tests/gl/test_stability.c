/* Extreme and stiff cases of DESIGN.md section 5 in rendered frames (OSMesa/llvmpipe): lighting
 * limits (gloss 0 and 1, grazing N.L and N.V, a light at the shaded point, radius 0 and huge,
 * 10^4 lights on one pixel, intensities at the FP16 maximum) and scene limits (no lights, no
 * geometry, 1x1 and the largest target, degenerate triangles, NaN/Inf vertices, missing
 * textures, positions at the near and far plane and along grazing rays).
 *
 * References are computed on the CPU in double from the lighting model of docs/renderer.md,
 * evaluated at the G-buffer's own decoded normal, gloss and reconstructed position, so that the
 * tolerances only have to cover the shader's float arithmetic, one depth read step and the FP16
 * store (one FP16 step per store: llvmpipe rounds FP16 render-target stores toward zero, hardware
 * usually to nearest; both are faithful). Position checks compare against analytic ray-plane
 * intersections with tolerances in depth-format steps. The key cases (FP16 limits, 10^4 lights,
 * 1x1, empty scene) run in every mode of tl_render_mode (see `modes`); the others check the
 * light buffer, which only thin-lpp has. docs/stability.md lists every case with its figures. */
#include <float.h>
#include <stdint.h>

#include "tl_test.h"

#include "thinlight/codec.h"
#include "thinlight/context.h"
#include "thinlight/renderer.h"
#include "thinlight/scene.h"

/* ---- context, renderer -------------------------------------------------------------------- */

#include "render_fixture.h"

/* The render modes the key cases (FP16 limits, 10^4 lights, 1x1, empty scene) run in; the other
 * cases check the thin light buffer, which only thin-lpp has. */
static const tl_render_mode modes[] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD};
#define MODE_COUNT (sizeof modes / sizeof modes[0])

static tl_renderer *make_renderer(tl_renderer_desc d)
{
    d.get_proc_address = tl_context_proc_loader;
    d.get_proc_address_user = g_ctx;
    if (!d.fxaa) d.fxaa = TL_FXAA_OFF;
    tl_renderer *r = NULL;
    char err[4096];
    tl_result res = tl_renderer_create(&d, &r, err, sizeof err);
    if (res != TL_OK) fprintf(stderr, "  tl_renderer_create %ux%u mode %s: %s\n", d.width, d.height,
                              tl_render_mode_name(d.mode), err);
    return r;
}

/* ---- small hand-made scenes --------------------------------------------------------------- */

#define MAX_V 256
#define MAX_I 512
#define MAX_O 8

typedef struct mini_scene {
    tl_vertex v[MAX_V];
    uint32_t idx[MAX_I];
    tl_object obj[MAX_O];
    tl_material mat[4];
    tl_texture tex[2];
    tl_light light[8];
    size_t nv, ni;
    tl_scene s;
} mini_scene;

static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

static tl_material plain_material(float albedo, float specular, float gloss)
{
    tl_material m = {.alpha = 1.0f, .albedo_texture = TL_NO_TEXTURE, .normal_texture = TL_NO_TEXTURE,
                     .metallic_roughness_texture = TL_NO_TEXTURE, .emissive_texture = TL_NO_TEXTURE,
                     .occlusion_texture = TL_NO_TEXTURE};
    for (int k = 0; k < 3; k++) {
        m.albedo[k] = albedo;
        m.specular[k] = specular;
    }
    m.gloss = gloss;
    return m;
}

/* Camera at the origin looking down -Z with +Y up: view space equals world space, so the lights
 * and surfaces below are given in view space directly. */
static void mini_init(mini_scene *m, float fov_y, float near_z, float far_z)
{
    memset(m, 0, sizeof *m);
    m->mat[0] = plain_material(0.5f, 0.25f, 0.5f);
    m->s.vertices = m->v;
    m->s.indices = m->idx;
    m->s.objects = m->obj;
    m->s.materials = m->mat;
    m->s.material_count = 1;
    m->s.lights = m->light;
    m->s.camera = (tl_camera){{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, fov_y, near_z, far_z};
}

/* Adds a quad o, o+du, o+du+dv, o+dv (counter-clockwise seen from du x dv) as a new object. */
static void add_quad(mini_scene *m, const float o[3], const float du[3], const float dv[3], uint32_t material)
{
    float n[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]};
    float l = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    uint32_t b = (uint32_t)m->nv;
    tl_object *ob = &m->obj[m->s.object_count++];
    memcpy(ob->transform, identity, sizeof identity);
    ob->first_index = (uint32_t)m->ni;
    ob->index_count = 6;
    ob->material = material;
    for (int k = 0; k < 3; k++) ob->bounds_min[k] = FLT_MAX, ob->bounds_max[k] = -FLT_MAX;
    for (int i = 0; i < 4; i++) {
        float a = (float)(i == 1 || i == 2), c = (float)(i >= 2);
        tl_vertex *x = &m->v[m->nv++];
        memset(x, 0, sizeof *x);
        for (int k = 0; k < 3; k++) {
            x->position[k] = o[k] + a * du[k] + c * dv[k];
            x->normal[k] = l > 0.0f ? n[k] / l : 0.0f;
            ob->bounds_min[k] = fminf(ob->bounds_min[k], x->position[k]);
            ob->bounds_max[k] = fmaxf(ob->bounds_max[k], x->position[k]);
        }
        x->uv[0] = a;
        x->uv[1] = c;
    }
    static const uint32_t q[6] = {0, 1, 2, 0, 2, 3};
    for (int i = 0; i < 6; i++) m->idx[m->ni++] = b + q[i];
    m->s.vertex_count = m->nv;
    m->s.index_count = m->ni;
}

/* A wall facing the camera at distance `dist`, large enough to fill a 60-degree view. */
static void add_wall(mini_scene *m, float dist, uint32_t material)
{
    float s = 2.0f * dist + 1.0f;
    add_quad(m, (float[3]){-s, -s, -dist}, (float[3]){2 * s, 0, 0}, (float[3]){0, 2 * s, 0}, material);
}

static tl_light point_light(float x, float y, float z, float radius, float r, float g, float b)
{
    return (tl_light){TL_LIGHT_POINT, {x, y, z}, {0, -1, 0}, {r, g, b}, radius, 0, 0};
}

/* ---- reading targets ---------------------------------------------------------------------- */

typedef struct frame {
    uint32_t w, h;
    float *depth, *rt0, *diffuse, *specular, *hdr;
} frame;

static void frame_free(frame *f)
{
    free(f->depth);
    free(f->rt0);
    free(f->diffuse);
    free(f->specular);
    free(f->hdr);
    memset(f, 0, sizeof *f);
}

/* Reads a target when the plan allocated it; NULL otherwise. */
static float *read_target(tl_renderer *r, tl_target_id id)
{
    uint32_t w, h;
    tl_renderer_get_size(r, &w, &h);
    size_t n = (size_t)w * h * 4;
    float *buf = malloc(n * sizeof *buf);
    if (buf && tl_renderer_read_target(r, id, buf, n) == TL_OK) return buf;
    free(buf);
    return NULL;
}

static void frame_read(tl_renderer *r, frame *f)
{
    memset(f, 0, sizeof *f);
    tl_renderer_get_size(r, &f->w, &f->h);
    f->depth = read_target(r, TL_TARGET_DEPTH);
    f->rt0 = read_target(r, TL_TARGET_RT0);
    f->diffuse = read_target(r, TL_TARGET_LIGHT_DIFFUSE);
    f->specular = read_target(r, TL_TARGET_LIGHT_SPECULAR);
    f->hdr = read_target(r, TL_TARGET_HDR);
}

/* Reads every target the plan allocated and counts non-finite values; returns the number of
 * targets read. Names the offending targets. */
static size_t count_nonfinite_all_targets(tl_renderer *r, const char *label, size_t *bad_total)
{
    uint32_t w, h;
    tl_renderer_get_size(r, &w, &h);
    size_t n = (size_t)w * h * 4, targets = 0;
    float *buf = malloc(n * sizeof *buf);
    *bad_total = 0;
    for (int t = 0; buf && t < TL_TARGET_COUNT; t++) {
        if (tl_renderer_read_target(r, (tl_target_id)t, buf, n) != TL_OK) continue;
        targets++;
        size_t bad = 0, first = 0;
        for (size_t i = 0; i < n; i++)
            if (!isfinite(buf[i])) {
                if (!bad) first = i;
                bad++;
            }
        if (bad)
            fprintf(stderr, "  %s: target %s holds %zu non-finite values (first at pixel %zu channel %zu: %g)\n",
                    label, tl_target_name((tl_target_id)t), bad, first / 4, first % 4, (double)buf[first]);
        *bad_total += bad;
    }
    free(buf);
    return targets;
}

/* ---- CPU reference of the lighting model (docs/renderer.md, shaders/lighting.glsl) ------------ */

/* The projection the renderer builds for the scene camera. */
static tl_projection projection_of(const tl_renderer_desc *d, const tl_camera *c, uint32_t w, uint32_t h)
{
    tl_projection p;
    tl_result res = tl_projection_perspective(d->depth_format, c->fov_y, (float)w / (float)h, c->near_z, c->far_z, &p);
    TL_CHECK(res == TL_OK);
    return p;
}

/* NDC of a pixel centre, computed as the light pass computes it (float). */
static void pixel_ndc(uint32_t x, uint32_t y, uint32_t w, uint32_t h, float ndc[2])
{
    ndc[0] = ((float)x + 0.5f) * (1.0f / (float)w) * 2.0f - 1.0f;
    ndc[1] = ((float)y + 0.5f) * (1.0f / (float)h) * 2.0f - 1.0f;
}

/* The G-buffer sample the light pass sees at a pixel: position reconstructed from the stored
 * depth (the DEPTH target's linear distance), decoded normal and gloss; 0 for background.
 * The light pass fetches the same depth through a texture, which may convert it to float
 * differently from the read-back (llvmpipe: by one float ULP, i.e. about one D24 code near 1), so
 * p_lo and p_hi hold the positions one such step nearer and farther. */
typedef struct gsample {
    double p[3], n[3], gloss;
    double p_lo[3], p_hi[3];
} gsample;

/* One step of a stored window depth as the light pass may see it: a float ULP of w, and at least
 * a D24 code for D24. */
static float depth_read_step(tl_depth_format f, float w)
{
    float ulp = nextafterf(w, INFINITY) - w;
    if (f == TL_DEPTH_FORMAT_D24 || f == TL_DEPTH_FORMAT_DEFAULT) ulp = fmaxf(ulp, 1.0f / 16777215.0f);
    return ulp;
}

static int gbuffer_sample(const frame *f, const tl_projection *pr, float clear_depth, uint32_t x, uint32_t y,
                          gsample *g)
{
    size_t i = ((size_t)y * f->w + x) * 4;
    if (f->depth[i] == clear_depth) return 0;
    float ndc[2];
    pixel_ndc(x, y, f->w, f->h, ndc);
    float dx = -(ndc[0] + pr->m[8]) / pr->m[0], dy = -(ndc[1] + pr->m[9]) / pr->m[5];
    float z = -f->depth[i + 1];
    g->p[0] = (double)(z * dx);
    g->p[1] = (double)(z * dy);
    g->p[2] = z;
    float w = f->depth[i], step = depth_read_step(pr->format, w);
    double zs[2] = {tl_depth_linearize(pr, w - step), tl_depth_linearize(pr, w + step)};
    double *ps[2] = {g->p_lo, g->p_hi};
    for (int k = 0; k < 2; k++) {
        ps[k][0] = zs[k] * dx;
        ps[k][1] = zs[k] * dy;
        ps[k][2] = zs[k];
    }
    for (int k = 0; k < 3; k++) g->n[k] = f->rt0 ? f->rt0[i + k] : 0.0;
    g->gloss = f->rt0 ? f->rt0[i + 3] : 0.0;
    return 1;
}

/* One light's (diffuse weight, specular weight) at position p with normal n, in double, as
 * shaders/lighting.glsl defines it (clamps at 4096 included), and an absolute error allowance for
 * the shader's float evaluation of the same expression:
 * - the windowed falloff w = 1 - x^4 is computed from a rounded x^4 (absolute error a few 2^-24),
 *   which matters where w -> 0 near the radius: 2 * 8 * 2^-24 / max(d^2, m^2) absolute;
 * - every other operation rounds at 2^-24 relative; 2^-18 covers the chain, including llvmpipe's
 *   approximate sqrt/inversesqrt;
 * - pow(N.H, n) turns an error of a few ULPs in N.H into n * 8 * 2^-24 relative (2e-3 at n = 4096). */
static void model_terms(const tl_light *l, const double p[3], const double n[3], double gloss, double out[2],
                        double err[2])
{
    double lv[3], att = 1.0, den = 1.0;
    double dir[3] = {l->direction[0], l->direction[1], l->direction[2]};
    double dl = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    for (int k = 0; k < 3; k++) dir[k] = dl > 0.0 ? dir[k] / dl : (k == 1 ? -1.0 : 0.0);
    if (l->type == TL_LIGHT_DIRECTIONAL) {
        for (int k = 0; k < 3; k++) lv[k] = -dir[k];
    } else {
        double d[3] = {l->position[0] - p[0], l->position[1] - p[1], l->position[2] - p[2]};
        double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int k = 0; k < 3; k++) lv[k] = dist > 1e-6 ? d[k] / dist : n[k];
        double r = l->radius, x = dist / r, x2 = x * x;
        double w = 1.0 - x2 * x2;
        w = w < 0.0 ? 0.0 : w > 1.0 ? 1.0 : w;
        double m = 0.01 * r;
        den = fmax(dist * dist, m * m);
        att = w * w / den;
        if (l->type == TL_LIGHT_SPOT) {
            double c = -(lv[0] * dir[0] + lv[1] * dir[1] + lv[2] * dir[2]);
            double t = (c - l->cos_outer) / fmax(l->cos_inner - l->cos_outer, 1e-4);
            t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
            att *= t * t * (3.0 - 2.0 * t);
        }
    }
    double nl = fmax(0.0, n[0] * lv[0] + n[1] * lv[1] + n[2] * lv[2]);
    double plen = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    double v[3] = {-p[0] / plen, -p[1] / plen, -p[2] / plen};
    double power = exp2(1.0 + 11.0 * fmin(fmax(gloss, 0.0), 1.0));
    double h[3] = {lv[0] + v[0], lv[1] + v[1], lv[2] + v[2]};
    double hl2 = h[0] * h[0] + h[1] * h[1] + h[2] * h[2], lobe = 0.0;
    if (hl2 >= 1e-12) {
        double nh = fmax(0.0, (n[0] * h[0] + n[1] * h[1] + n[2] * h[2]) / sqrt(hl2));
        lobe = (power + 8.0) / (8.0 * 3.14159265358979) * pow(nh, power);
    }
    double diffuse = fmin(att * nl, 4096.0);
    double spec = fmin(diffuse * lobe, 4096.0);
    double falloff_err = nl * 16.0 * 0x1.0p-24 / den;
    out[0] = diffuse;
    out[1] = spec;
    err[0] = diffuse * 0x1.0p-18 + falloff_err;
    err[1] = spec * (0x1.0p-18 + power * 8.0 * 0x1.0p-24) + falloff_err * lobe;
}

/* The model at a G-buffer sample; `err` adds how far the terms move when the position moves by
 * one depth read step (p_lo, p_hi). */
static void light_terms(const tl_light *l, const gsample *g, double out[2], double err[2])
{
    double lo[2], hi[2], e[2];
    model_terms(l, g->p, g->n, g->gloss, out, err);
    model_terms(l, g->p_lo, g->n, g->gloss, lo, e);
    model_terms(l, g->p_hi, g->n, g->gloss, hi, e);
    for (int s = 0; s < 2; s++) err[s] += fmax(fabs(lo[s] - out[s]), fabs(hi[s] - out[s]));
}

/* Float -> FP16 -> float, round to nearest even, overflow to Inf as a GPU conversion does. */
static double half_rn(double v)
{
    if (fabs(v) >= 65520.0) return v > 0 ? INFINITY : -INFINITY;
    return tl_half_to_float(tl_half_from_float((float)v));
}

/* Float -> FP16 -> float, rounded toward zero (what llvmpipe's render-target conversion does). */
static double half_rz(double v)
{
    float f = (float)v;
    if (fabsf(f) >= 65536.0f) return v > 0 ? INFINITY : -INFINITY;
    uint16_t h = tl_half_from_float(f);
    if (fabs((double)tl_half_to_float(h)) > fabs((double)f)) h = (uint16_t)(h - 1u); /* one step toward zero */
    return tl_half_to_float(h);
}

/* The spacing of FP16 values at |v| (one ULP: the most a faithful rounding, to nearest or toward
 * zero, can move a value), at least the smallest subnormal. */
static double half_ulp(double v)
{
    double a = fabs(v);
    if (a < 0x1.0p-14) return 0x1.0p-24;
    int e;
    frexp(a, &e); /* a in [2^(e-1), 2^e) */
    return ldexp(1.0, e - 1 - 10);
}

typedef struct light_check {
    size_t lit;         /* pixels with a reference above 1e-3 */
    size_t bad;         /* values beyond tolerance */
    size_t rn, rz, n;   /* single light: values equal to the reference rounded to nearest / toward zero */
    double max_ratio;   /* max |gpu - ref| / tolerance */
    double max_value;   /* largest reference value */
} light_check;

/* Compares the light buffer (diffuse RGB, specular RGB) with the sum over `lights` evaluated at
 * the G-buffer's own samples. Tolerance: the shader's float error and the depth read step per
 * light (light_terms), plus one FP16 ULP of the running sum per light (each blend stores once;
 * the store's rounding is faithful, to nearest or toward zero). Background pixels are exactly 0. */
static light_check check_light_buffer(const frame *f, const tl_projection *pr, float clear_depth,
                                      const tl_light *lights, size_t count, const char *label)
{
    light_check c = {0};
    size_t shown = 0;
    if (!f->rt0 || !f->diffuse) {
        fprintf(stderr, "  %s: no RT0 or light buffer to check\n", label);
        c.bad = 1;
        return c;
    }
    for (uint32_t y = 0; y < f->h; y++)
        for (uint32_t x = 0; x < f->w; x++) {
            size_t i = ((size_t)y * f->w + x) * 4;
            gsample g;
            double ref[2][3] = {{0}}, tol[2][3] = {{0}};
            if (gbuffer_sample(f, pr, clear_depth, x, y, &g))
                for (size_t k = 0; k < count; k++) {
                    double t[2], e[2];
                    light_terms(&lights[k], &g, t, e);
                    for (int s = 0; s < 2; s++)
                        for (int ch = 0; ch < 3; ch++) {
                            double col = fabs((double)lights[k].color[ch]);
                            ref[s][ch] += col * t[s];
                            tol[s][ch] += col * e[s] + half_ulp(ref[s][ch] + col * e[s]);
                        }
                }
            for (int s = 0; s < 2; s++) {
                const float *buf = s ? f->specular : f->diffuse;
                if (!buf) continue;
                for (int ch = 0; ch < 3; ch++) {
                    double gpu = buf[i + ch], rv = ref[s][ch];
                    double t = tol[s][ch], d = fabs(gpu - rv);
                    double ratio = d == 0.0 ? 0.0 : d / t;
                    if (!(ratio <= 1.0)) {
                        if (shown++ < 6)
                            fprintf(stderr, "  %s: pixel (%u, %u) %s[%d] = %.9g, reference %.9g, tolerance %.3g\n",
                                    label, x, y, s ? "specular" : "diffuse", ch, gpu, rv, t);
                        c.bad++;
                    }
                    if (count == 1 && rv > 0.0) {
                        c.n++;
                        c.rn += gpu == half_rn(rv);
                        c.rz += gpu == half_rz(rv);
                    }
                    if (ratio > c.max_ratio || isnan(ratio)) c.max_ratio = isnan(ratio) ? INFINITY : ratio;
                    if (rv > c.max_value) c.max_value = rv;
                    if (s == 0 && ch == 0 && rv > 1e-3) c.lit++;
                }
            }
        }
    printf("  %s: %zu lit pixels, max value %.6g, max |gpu - ref| / tolerance %.3g, %zu beyond", label, c.lit,
           c.max_value, c.max_ratio, c.bad);
    if (c.n) printf("; of %zu values, %zu equal the reference rounded to nearest, %zu toward zero", c.n, c.rn, c.rz);
    printf("\n");
    return c;
}

/* ---- one rendered frame -------------------------------------------------------------------- */

typedef struct run {
    tl_renderer *r;
    tl_renderer_desc desc;
    tl_frame_stats stats;
    frame f;
    tl_projection pr;
    float clear; /* window depth of the background */
} run;

static void run_free(run *u)
{
    frame_free(&u->f);
    tl_renderer_destroy(u->r);
    memset(u, 0, sizeof *u);
}

/* Creates a renderer, sets the scene, renders with the scene camera and reads the targets. */
static int run_scene(run *u, tl_renderer_desc d, const tl_scene *s, const char *label)
{
    memset(u, 0, sizeof *u);
    if (!ensure_context()) {
        TL_CHECK(!"no GL context");
        return 0;
    }
    u->desc = d;
    u->r = make_renderer(d);
    TL_CHECK(u->r != NULL);
    if (!u->r) return 0;
    tl_result res = tl_renderer_set_scene(u->r, s);
    if (res != TL_OK)
        fprintf(stderr, "  %s: set_scene: %s (%s)\n", label, tl_result_string(res), tl_renderer_last_error(u->r));
    TL_CHECK(res == TL_OK);
    if (res == TL_OK) {
        res = tl_renderer_render(u->r, NULL, &u->stats);
        if (res != TL_OK)
            fprintf(stderr, "  %s: render: %s (%s)\n", label, tl_result_string(res), tl_renderer_last_error(u->r));
        TL_CHECK(res == TL_OK);
    }
    if (res != TL_OK) {
        run_free(u);
        return 0;
    }
    frame_read(u->r, &u->f);
    TL_CHECK(u->f.depth && u->f.hdr); /* RT0 and the light buffer only when the plan has lights */
    u->pr = projection_of(&d, &s->camera, u->f.w, u->f.h);
    u->clear = d.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED ? 0.0f : 1.0f;
    return u->f.depth && u->f.hdr;
}

static void check_all_targets_finite(run *u, const char *label)
{
    size_t bad = 0, n = count_nonfinite_all_targets(u->r, label, &bad);
    TL_CHECK(n >= 3); /* depth, HDR, output at least */
    TL_CHECK_EQ_U(bad, 0);
}

/* ---- lighting ------------------------------------------------------------------------------ */

/* Gloss 0 (power 2) and gloss 1 (power 4096) in a rendered frame: RT0 stores both ends exactly,
 * the light buffer matches the model at the G-buffer's samples, the gloss-1 peak is the expected
 * factor above the gloss-0 peak, and no target holds a non-finite value. */
TL_TEST(stability_gloss_0_and_1)
{
    double peak[2] = {0, 0};
    for (int gi = 0; gi < 2; gi++) {
        mini_scene m;
        mini_init(&m, 1.0471976f, 0.1f, 100.0f);
        m.mat[0] = plain_material(0.5f, 1.0f, (float)gi);
        add_wall(&m, 5.0f, 0);
        m.light[0] = point_light(0.0f, 0.0f, 0.0f, 10.0f, 1.0f, 1.0f, 1.0f);  /* at the eye: peak at the centre */
        m.light[1] = point_light(1.5f, 1.0f, -3.0f, 6.0f, 0.0f, 0.25f, 1.0f); /* off-axis peak, no red */
        m.s.light_count = 2;
        char label[64];
        snprintf(label, sizeof label, "gloss %d", gi);
        run u;
        if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, label)) continue;
        check_all_targets_finite(&u, label);
        size_t wrong_gloss = 0;
        for (size_t i = 0; i < (size_t)64 * 64; i++) wrong_gloss += u.f.rt0[4 * i + 3] != (float)gi;
        TL_CHECK_EQ_U(wrong_gloss, 0);
        light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 2, label);
        TL_CHECK_EQ_U(c.bad, 0);
        TL_CHECK(c.lit > 1000);
        if (u.f.specular) /* the four pixels around the view axis */
            for (uint32_t y = 31; y <= 32; y++)
                for (uint32_t x = 31; x <= 32; x++) peak[gi] = fmax(peak[gi], u.f.specular[((size_t)y * 64 + x) * 4]);
        run_free(&u);
    }
    /* the lobe's normalisation: (4096 + 8) / (2 + 8) = 410 at N.H = 1; the pixels next to the axis
     * are off the peak by ~0.7 degrees (cos^4096 = 0.72); red comes from the light at the eye alone */
    printf("  specular peaks: gloss 0 %.6g, gloss 1 %.6g (ratio %.1f)\n", peak[0], peak[1], peak[1] / peak[0]);
    TL_CHECK(peak[1] > 200.0 * peak[0] && peak[1] < 410.5 * peak[0]);
}

/* N.L -> 0: point lights in the wall's plane, a hair in front of it and a hair behind it, and a
 * directional light along the wall. The diffuse term must vanish to within what the encoded
 * normal allows: N.L <= sin(max oct12-precise error 0.0393 deg + depth-step angle). */
TL_TEST(stability_grazing_light_n_dot_l)
{
    const float offsets[3] = {0.0f, 1e-3f, -1e-3f}; /* in the plane, in front, behind */
    for (int o = 0; o < 3; o++) {
        mini_scene m;
        mini_init(&m, 1.0471976f, 0.1f, 100.0f);
        m.mat[0] = plain_material(0.5f, 1.0f, 0.75f);
        add_wall(&m, 5.0f, 0);
        m.light[0] = point_light(2.0f, 0.5f, -5.0f + offsets[o], 6.0f, 3.0f, 3.0f, 3.0f);
        m.light[1] = (tl_light){TL_LIGHT_DIRECTIONAL, {0, 0, 0}, {1.0f, 0.0f, offsets[o]}, {2, 2, 2}, 0, 0, 0};
        m.s.light_count = 2;
        char label[80];
        snprintf(label, sizeof label, "grazing N.L, light offset %g", (double)offsets[o]);
        run u;
        if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, label)) continue;
        check_all_targets_finite(&u, label);
        light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 2, label);
        TL_CHECK_EQ_U(c.bad, 0);
        /* independent of the reference: diffuse / (colour * falloff) is N.L, which may exceed
         * the light's true elevation over the plane (offset / distance) only by the normal's
         * encoding error (oct12 precise, max 0.0393 deg) and the tilt of one D24 depth step
         * (1.5e-5 m at 5 m with near 0.1, far 100) seen from the light */
        double worst = -1.0;
        const double normal_err = 0.0393 * 3.14159265358979 / 180.0, depth_step = 1.5e-5;
        for (uint32_t y = 0; y < 64; y++)
            for (uint32_t x = 0; x < 64; x++) {
                gsample g;
                if (!gbuffer_sample(&u.f, &u.pr, u.clear, x, y, &g)) continue;
                double t[2], e[2], dir_terms[2];
                gsample h = g; /* the same sample with the normal turned towards the light */
                const float *lp = m.light[0].position;
                double d[3] = {lp[0] - g.p[0], lp[1] - g.p[1], lp[2] - g.p[2]};
                double dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                for (int k = 0; k < 3; k++) h.n[k] = d[k] / dl;
                light_terms(&m.light[0], &h, t, e);
                light_terms(&m.light[1], &g, dir_terms, e);
                if (t[0] < 1e-3) continue;
                double gpu = u.f.diffuse[((size_t)y * 64 + x) * 4] - 2.0 * dir_terms[0];
                double allowed = sin(normal_err + depth_step / dl) + fmax(offsets[o], 0.0f) / dl;
                double excess = gpu / (3.0 * t[0]) - allowed;
                worst = fmax(worst, excess);
            }
        printf("  %s: max N.L beyond the allowance %.3g\n", label, worst);
        TL_CHECK_LE(worst, 0x1.0p-10);
        run_free(&u);
    }
}

/* N.V -> 0: a floor seen from 1 m above it out to 110 m, where the view ray of the row next to
 * the horizon meets the floor at 0.5 degrees; lit by a point light far down the floor and a directional
 * light at 0.06 degrees above the horizon (N.L -> 0 as well). */
TL_TEST(stability_grazing_view_n_dot_v)
{
    mini_scene m;
    mini_init(&m, 1.0471976f, 0.1f, 1000.0f);
    m.mat[0] = plain_material(0.5f, 1.0f, 0.9f);
    add_quad(&m, (float[3]){-300, -1, 10}, (float[3]){600, 0, 0}, (float[3]){0, 0, -400}, 0); /* +Y */
    m.light[0] = point_light(0.0f, 0.0f, -60.0f, 80.0f, 400.0f, 400.0f, 400.0f);
    m.light[1] = (tl_light){TL_LIGHT_DIRECTIONAL, {0, 0, 0}, {0.0f, -1e-3f, -1.0f}, {3, 3, 3}, 0, 0, 0};
    m.s.light_count = 2;
    char label[64];
    snprintf(label, sizeof label, "grazing N.V");
    run u;
    if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, label)) return;
    check_all_targets_finite(&u, label);
    light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 2, label);
    TL_CHECK_EQ_U(c.bad, 0);
    TL_CHECK(c.lit > 500);
    /* the rows next to the horizon are floor at N.V < 0.02, and they are lit */
    double min_ndotv = 1.0;
    for (uint32_t y = 0; y < 32; y++) {
        gsample g;
        if (!gbuffer_sample(&u.f, &u.pr, u.clear, 32, y, &g)) continue;
        double pl = sqrt(g.p[0] * g.p[0] + g.p[1] * g.p[1] + g.p[2] * g.p[2]);
        double ndotv = -(g.n[0] * g.p[0] + g.n[1] * g.p[1] + g.n[2] * g.p[2]) / pl;
        min_ndotv = fmin(min_ndotv, ndotv);
    }
    printf("  %s: smallest N.V on the floor %.4f\n", label, min_ndotv);
    TL_CHECK(min_ndotv < 0.01);
    run_free(&u);
}

/* A point light on the lit surface: the distance to the pixel at the image centre (odd size,
 * so a pixel centre lies on the view axis) is below one depth step, far under the falloff's
 * clamp distance 0.01 radius. The light buffer must hold at most colour / (0.01 radius)^2
 * (and at most colour * 4096, the per-light clamp) and match the model everywhere. */
TL_TEST(stability_light_at_shaded_point)
{
    const float radii[2] = {10.0f, 0.5f}; /* peak 1 / 0.1^2 = 100, and 1 / 0.005^2 = 40000 -> clamp 4096 */
    const tl_depth_format formats[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    for (int f = 0; f < 2; f++)
        for (int ri = 0; ri < 2; ri++) {
            mini_scene m;
            mini_init(&m, 1.0471976f, 0.1f, 100.0f);
            m.mat[0] = plain_material(0.5f, 1.0f, 0.5f);
            add_wall(&m, 5.0f, 0);
            m.light[0] = point_light(0.0f, 0.0f, -5.0f, radii[ri], 2.0f, 2.0f, 2.0f);
            m.s.light_count = 1;
            char label[96];
            snprintf(label, sizeof label, "light on the surface, radius %g, %s", (double)radii[ri],
                     tl_depth_format_name(formats[f]));
            run u;
            if (!run_scene(&u, (tl_renderer_desc){.width = 63, .height = 63,
                                                  .depth_format = formats[f]}, &m.s, label))
                continue;
            check_all_targets_finite(&u, label);
            light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 1, label);
            TL_CHECK_EQ_U(c.bad, 0);
            double m01 = 0.01 * radii[ri], cap = 2.0 * fmin(4096.0, 1.0 / (m01 * m01));
            double peak = 0.0;
            for (size_t i = 0; i < (size_t)63 * 63 * 4; i++)
                if (i % 4 != 3) {
                    TL_CHECK(u.f.diffuse[i] >= 0.0f);
                    peak = fmax(peak, u.f.diffuse[i]);
                }
            gsample g;
            TL_CHECK(gbuffer_sample(&u.f, &u.pr, u.clear, 31, 31, &g));
            double dist = sqrt(g.p[0] * g.p[0] + g.p[1] * g.p[1] + (g.p[2] + 5.0) * (g.p[2] + 5.0));
            printf("  %s: centre pixel %.3g m from the light, diffuse there %.6g, peak %.6g (cap %.6g)\n", label, dist,
                   (double)u.f.diffuse[(31 * 63 + 31) * 4], peak, cap);
            TL_CHECK(dist < m01);
            TL_CHECK_LE(peak, cap * (1.0 + 0x1.0p-11));
            run_free(&u);
        }
}

/* Radius 0 and radii so small that the falloff underflows: no light, no NaN (attenuation would
 * be 0 / 0 at radius 0). The renderer skips radius <= 0; the frame must equal the frame without
 * those lights, bit for bit. */
TL_TEST(stability_light_radius_zero)
{
    const float tiny[] = {0.0f, FLT_TRUE_MIN, 1e-30f};
    mini_scene m;
    mini_init(&m, 1.0471976f, 0.1f, 100.0f);
    add_wall(&m, 5.0f, 0);
    m.light[0] = point_light(1.0f, 0.0f, -4.0f, 3.0f, 1.0f, 1.0f, 1.0f); /* control */
    run ref, u;
    m.s.light_count = 1;
    if (!run_scene(&ref, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, "control")) return;
    for (size_t t = 0; t < sizeof tiny / sizeof tiny[0]; t++) {
        /* a point light on the surface (distance 0 at its pixel) and a spot light in front */
        m.light[1] = point_light(0.0f, 0.0f, -5.0f, tiny[t], 5.0f, 5.0f, 5.0f);
        m.light[2] = (tl_light){TL_LIGHT_SPOT, {0, 0, -4}, {0, 0, -1}, {5, 5, 5}, tiny[t], 0.9f, 0.8f};
        m.s.light_count = 3;
        char label[80];
        snprintf(label, sizeof label, "radius %g", (double)tiny[t]);
        if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, label)) continue;
        check_all_targets_finite(&u, label);
        size_t differ = 0;
        for (size_t i = 0; i < (size_t)64 * 64 * 4; i++) {
            differ += u.f.diffuse[i] != ref.f.diffuse[i] || u.f.hdr[i] != ref.f.hdr[i];
            if (u.f.specular) differ += u.f.specular[i] != ref.f.specular[i];
        }
        printf("  %s: %u point + %u spot instances drawn, %zu values differ from the control frame\n", label,
               u.stats.lights_drawn[TL_LIGHT_POINT], u.stats.lights_drawn[TL_LIGHT_SPOT], differ);
        TL_CHECK_EQ_U(differ, 0);
        run_free(&u);
    }
    run_free(&ref);
}

/* Huge radii: 1e6 (camera and scene deep inside the volume; the falloff's clamp distance is
 * 1e4, so the attenuation is 1e-8 everywhere and a colour of 2e8 brings it back to ~2), and
 * 1e30 and FLT_MAX, where (0.01 radius)^2 overflows float and the model gives exactly 0. The
 * volume path must match the model and the full-screen path. */
TL_TEST(stability_light_radius_huge)
{
    const float radii[3] = {1e6f, 1e30f, FLT_MAX};
    for (int ri = 0; ri < 3; ri++) {
        mini_scene m;
        mini_init(&m, 1.0471976f, 0.1f, 100.0f);
        m.mat[0] = plain_material(0.5f, 1.0f, 0.5f);
        add_wall(&m, 5.0f, 0);
        m.light[0] = point_light(2.0f, 1.0f, -3.0f, radii[ri], 2e8f, 1e8f, 3e8f);
        m.s.light_count = 1;
        char label[80];
        snprintf(label, sizeof label, "radius %g", (double)radii[ri]);
        run u, full;
        if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, label)) continue;
        check_all_targets_finite(&u, label);
        light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 1, label);
        TL_CHECK_EQ_U(c.bad, 0);
        if (ri == 0) TL_CHECK(c.lit > 3000 && c.max_value > 1.0);
        if (ri > 0) { /* (0.01 radius)^2 overflows float: the shader's attenuation is exactly 0 */
            size_t nonzero = 0;
            for (size_t i = 0; i < (size_t)64 * 64 * 4; i++) nonzero += u.f.diffuse[i] != 0.0f;
            TL_CHECK_EQ_U(nonzero, 0);
        }
        if (run_scene(&full, (tl_renderer_desc){.width = 64, .height = 64, .fullscreen_lights = 1},
                      &m.s, "full-screen")) {
            size_t differ = 0;
            for (size_t i = 0; i < (size_t)64 * 64 * 4; i++) differ += u.f.diffuse[i] != full.f.diffuse[i];
            printf("  %s: %zu light-buffer values differ from the full-screen path\n", label, differ);
            TL_CHECK_EQ_U(differ, 0);
            run_free(&full);
        }
        run_free(&u);
    }
}

/* ---- FP16 accumulation ---------------------------------------------------------------------- */

/* A blend unit's add into an FP16 target: float add, then the store's rounding. */
static double blend_add(double dst, double src, int toward_zero)
{
    float s = (float)dst + (float)src;
    return toward_zero ? half_rz(s) : half_rn(s);
}

/* The exact G-buffer sample of the test wall (z = -5 facing the camera, normal +Z) at a pixel. */
static void wall_sample(const tl_projection *pr, uint32_t x, uint32_t y, uint32_t w, uint32_t h, double gloss,
                        gsample *g)
{
    float ndc[2];
    pixel_ndc(x, y, w, h, ndc);
    g->p[0] = 5.0 * ((double)ndc[0] + pr->m[8]) / pr->m[0];
    g->p[1] = 5.0 * ((double)ndc[1] + pr->m[9]) / pr->m[5];
    g->p[2] = -5.0;
    g->n[0] = g->n[1] = 0.0;
    g->n[2] = 1.0;
    g->gloss = gloss;
    memcpy(g->p_lo, g->p, sizeof g->p);
    memcpy(g->p_hi, g->p, sizeof g->p);
}

/* 10^4 point lights clustered 1.5-2.5 m in front of a wall, each covering the whole 16x16 frame
 * (the camera is inside every volume, so all are drawn by back faces in scene order).
 *
 * thin-lpp: additive blending into the RGBA16F light buffer rounds after every light. The buffer
 * must equal the same sequence of FP16 additions of the model's terms, bracketed by each term's
 * float error and depth read step (light_terms): lower and upper sequences, under round to
 * nearest or under round toward zero (whichever the implementation's store uses; both are
 * monotonic, so the GPU's sum lies between the two sequences of its mode).
 * Every mode: the frame is finite, 10^4 lights give no less than their first 5000 (accumulation
 * is monotonic), no more than the exact sum, and the fraction of the exact (double) HDR lost is
 * reported: once a term falls below an FP16 step of the running sum it is lost, while forward
 * shading sums in float and rounds to FP16 once (asserted within 2^-10 + 10^4 x 2^-23). */
TL_TEST(stability_10k_lights_fp16_accumulation)
{
    enum { N = 10000, W = 16 };
    const double gloss = 0.3, albedo = 0.5, specular = 0.5;
    tl_light *lights = malloc(N * sizeof *lights);
    double *exact = malloc((size_t)W * W * 3 * sizeof *exact);
    TL_CHECK(lights && exact);
    if (!lights || !exact) return;
    tl_rng rng = {0x10A11u};
    for (size_t k = 0; k < N; k++) {
        float x = (float)(tl_rng_unit(&rng) - 0.5), y = (float)(tl_rng_unit(&rng) - 0.5);
        float z = (float)(-2.5 - tl_rng_unit(&rng));
        float c = (float)(0.5 + tl_rng_unit(&rng));
        lights[k] = point_light(x, y, z, 6.0f, 0.05f * c, 0.04f, 0.03f * (1.5f - c));
    }
    /* exact HDR of every pixel, in double, at the exact wall */
    tl_projection pr0;
    TL_CHECK(tl_projection_perspective(TL_DEPTH_FORMAT_D24, 1.0471976f, 1.0f, 0.1f, 100.0f, &pr0) == TL_OK);
    for (uint32_t y = 0; y < W; y++)
        for (uint32_t x = 0; x < W; x++) {
            gsample g;
            wall_sample(&pr0, x, y, W, W, gloss, &g);
            double sum[2][3] = {{0}};
            for (size_t k = 0; k < N; k++) {
                double t[2], e[2];
                model_terms(&lights[k], g.p, g.n, g.gloss, t, e);
                for (int ch = 0; ch < 3; ch++) {
                    sum[0][ch] += lights[k].color[ch] * t[0];
                    sum[1][ch] += lights[k].color[ch] * t[1];
                }
            }
            for (int ch = 0; ch < 3; ch++)
                exact[((size_t)y * W + x) * 3 + ch] = albedo * sum[0][ch] + specular * sum[1][ch];
        }
    for (size_t mi = 0; mi < MODE_COUNT; mi++) {
        mini_scene m;
        mini_init(&m, 1.0471976f, 0.1f, 100.0f);
        m.mat[0] = plain_material((float)albedo, (float)specular, (float)gloss);
        add_wall(&m, 5.0f, 0);
        m.s.lights = lights;
        char label[64];
        snprintf(label, sizeof label, "10^4 lights, %s", tl_render_mode_name(modes[mi]));
        run u, half_run;
        m.s.light_count = N / 2;
        if (!run_scene(&half_run, (tl_renderer_desc){.mode = modes[mi], .width = W, .height = W}, &m.s, "5000 lights"))
            continue;
        m.s.light_count = N;
        if (!run_scene(&u, (tl_renderer_desc){.mode = modes[mi], .width = W, .height = W}, &m.s, label)) {
            run_free(&half_run);
            continue;
        }
        check_all_targets_finite(&u, label);
        if (modes[mi] == TL_MODE_FORWARD)
            TL_CHECK_EQ_U(u.stats.forward_light_pairs, N);
        else
            TL_CHECK_EQ_U(u.stats.lights_drawn[TL_LIGHT_POINT], N);
        /* thin-lpp: the light buffer against FP16 accumulation */
        size_t outside[2] = {0, 0}, px = 0;
        double max_bracket = 0.0;
        if (modes[mi] == TL_MODE_THIN_LPP) {
            TL_CHECK(u.f.rt0 && u.f.diffuse && u.f.specular);
            for (uint32_t y = 0; u.f.rt0 && u.f.diffuse && u.f.specular && y < W; y++)
                for (uint32_t x = 0; x < W; x++) {
                    gsample g;
                    if (!gbuffer_sample(&u.f, &u.pr, u.clear, x, y, &g)) continue;
                    double lo[2][2][3] = {{{0}}}, hi[2][2][3] = {{{0}}}; /* [rounding][diffuse/specular][channel] */
                    for (size_t k = 0; k < N; k++) {
                        double t[2], e[2];
                        light_terms(&lights[k], &g, t, e);
                        for (int rz = 0; rz < 2; rz++)
                            for (int s = 0; s < 2; s++)
                                for (int ch = 0; ch < 3; ch++) {
                                    double col = lights[k].color[ch];
                                    lo[rz][s][ch] = blend_add(lo[rz][s][ch], fmax(0.0, col * (t[s] - e[s])), rz);
                                    hi[rz][s][ch] = blend_add(hi[rz][s][ch], col * (t[s] + e[s]), rz);
                                }
                    }
                    size_t i = ((size_t)y * W + x) * 4;
                    px++;
                    for (int rz = 0; rz < 2; rz++)
                        for (int s = 0; s < 2; s++)
                            for (int ch = 0; ch < 3; ch++) {
                                double gpu = (s ? u.f.specular : u.f.diffuse)[i + ch];
                                if (!(gpu >= lo[rz][s][ch] && gpu <= hi[rz][s][ch])) outside[rz]++;
                                double width = (hi[rz][s][ch] - lo[rz][s][ch]) / fmax(hi[rz][s][ch], 1e-30);
                                max_bracket = fmax(max_bracket, width);
                            }
                }
            printf("  %s: light buffer outside the FP16 accumulation bracket: %zu values (round to nearest), "
                   "%zu (toward zero), of %zu; widest bracket %.3g relative\n",
                   label, outside[0], outside[1], px * 6, max_bracket);
            TL_CHECK(px == (size_t)W * W);
            if (outside[0] && outside[1])
                fprintf(stderr, "  %s: the light buffer is no FP16 accumulation of the lights' terms\n", label);
            TL_CHECK(outside[0] == 0 || outside[1] == 0);
        }
        /* every mode: HDR against the exact sum */
        size_t decreasing = 0, above = 0;
        double loss_sum = 0.0, loss_max = 0.0, worst_rel = 0.0;
        const double fwd_tol = 0x1.0p-10 + N * 0x1.0p-23 + 0x1.0p-12;
        /* thin-deferred reads albedo back from RT1's 8-bit sRGB YCbCr: up to ~2 steps (2.5 %) brighter */
        const double above_tol = modes[mi] == TL_MODE_THIN_DEFERRED ? 0.025 : fwd_tol;
        for (size_t i = 0; i < (size_t)W * W; i++)
            for (int ch = 0; ch < 3; ch++) {
                double gpu = u.f.hdr[4 * i + ch], ex = exact[3 * i + ch];
                if (half_run.f.hdr[4 * i + ch] > gpu) decreasing++;
                if (gpu > ex * (1.0 + above_tol)) above++;
                double loss = 1.0 - gpu / ex;
                loss_sum += loss;
                loss_max = fmax(loss_max, loss);
                worst_rel = fmax(worst_rel, fabs(loss));
            }
        double loss_mean = loss_sum / (double)(W * W * 3);
        printf("  %s: HDR below the exact sum by %.1f %% on average, %.1f %% at most (|relative error| max %.3g); "
               "%zu values above it, %zu darker than with 5000 lights\n",
               label, 100.0 * loss_mean, 100.0 * loss_max, worst_rel, above, decreasing);
        TL_CHECK_EQ_U(decreasing, 0);
        TL_CHECK_EQ_U(above, 0);
        if (modes[mi] == TL_MODE_FORWARD) TL_CHECK_LE(worst_rel, fwd_tol);
        run_free(&u);
        run_free(&half_run);
    }
    free(lights);
    free(exact);
}

/* Light colours at and beyond the FP16 maximum (65504), alone and in pairs whose sum exceeds it,
 * and at 1 mm from the surface with radius 0.5, where the weight reaches the per-light clamp 4096
 * (1 / (0.01 radius)^2 = 40000 before it): DESIGN.md section 5 says no NaN or Inf may reach any
 * target. Every allocated target is read back; the pixel under the light (the centre of the 63x63
 * frame) must come out white, not black or NaN. llvmpipe stores FP16 rounding toward zero, which
 * saturates at 65504 where round-to-nearest hardware gives Inf (colour x weight > 65520, or a
 * blended sum beyond it): the cases that overflow only there are marked. */
TL_TEST(stability_intensity_fp16_max)
{
    static const struct { float color, dist, radius; int count; const char *what; } cases[] = {
        {65504.0f, 1.0f, 4.0f, 1, "one light 65504 at 1 m"},
        {65504.0f, 0.001f, 0.5f, 1, "one light 65504 at 1 mm, weight clamped to 4096 (Inf with RN)"},
        {40000.0f, 1.0f, 4.0f, 2, "two lights 40000 at 1 m, sum > 65504 (Inf with RN)"},
        {16.0f, 0.001f, 0.5f, 1, "one light 16 at 1 mm: 16 x 4096 = 65536 (Inf with RN)"},
        {1e30f, 1.0f, 4.0f, 1, "one light 1e30 (Inf with RN)"},
        {FLT_MAX, 0.5f, 4.0f, 1, "one light FLT_MAX"},
    };
    const uint32_t W = 63;
    for (size_t mi = 0; mi < MODE_COUNT; mi++)
        for (int lb = TL_LIGHT_BUFFER_EXACT;
             lb <= (modes[mi] == TL_MODE_THIN_LPP ? TL_LIGHT_BUFFER_COMPACT : TL_LIGHT_BUFFER_EXACT); lb++)
            for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++) {
                mini_scene m;
                mini_init(&m, 1.0471976f, 0.1f, 100.0f);
                m.mat[0] = plain_material(0.5f, 1.0f, 0.5f);
                add_wall(&m, 5.0f, 0);
                for (int k = 0; k < cases[ci].count; k++) {
                    float c = cases[ci].color;
                    m.light[k] = point_light(0.3f * (float)k, 0.0f, -5.0f + cases[ci].dist, cases[ci].radius, c, c, c);
                }
                m.s.light_count = (size_t)cases[ci].count;
                char label[160];
                snprintf(label, sizeof label, "%s, %s%s", cases[ci].what, tl_render_mode_name(modes[mi]),
                         modes[mi] != TL_MODE_THIN_LPP ? "" : lb == TL_LIGHT_BUFFER_EXACT ? " (exact)" : " (compact)");
                run u;
                if (!run_scene(&u, (tl_renderer_desc){.mode = modes[mi], .width = W, .height = W,
                                                      .light_buffer = (tl_light_buffer)lb}, &m.s, label))
                    continue;
                size_t bad = 0, n = count_nonfinite_all_targets(u.r, label, &bad);
                TL_CHECK(n >= 3); /* depth, HDR, output at least */
                if (bad) fprintf(stderr, "  RENDERER BUG (DESIGN 5: no NaN or Inf in any target): %s\n", label);
                TL_CHECK_EQ_U(bad, 0);
                uint8_t *img = malloc((size_t)W * W * 4);
                TL_CHECK(tl_renderer_read_output(u.r, img, (size_t)W * W * 4) == TL_OK);
                size_t i = ((size_t)(W / 2) * W + W / 2) * 4;
                double hdr_max = 0.0, light_max = 0.0;
                for (size_t k = 0; k < (size_t)W * W * 4; k++)
                    if (k % 4 != 3) {
                        if (isfinite(u.f.hdr[k])) hdr_max = fmax(hdr_max, u.f.hdr[k]);
                        if (u.f.diffuse && isfinite(u.f.diffuse[k])) light_max = fmax(light_max, u.f.diffuse[k]);
                    }
                char lmax[32] = "none";
                if (u.f.diffuse) snprintf(lmax, sizeof lmax, "%.6g", light_max);
                printf("  %s: %zu non-finite values; light buffer max %s, HDR max %.6g; output under the light "
                       "(%u, %u, %u)\n", label, bad, lmax, hdr_max, img[i], img[i + 1], img[i + 2]);
                TL_CHECK(img[i] >= 250 && img[i + 1] >= 250 && img[i + 2] >= 250);
                TL_CHECK_LE(hdr_max, 65504.0);
                free(img);
                run_free(&u);
            }
}

/* ---- scenes ------------------------------------------------------------------------------- */

/* No lights: the light buffer is zero and HDR is albedo * ambient + emissive, rounded to FP16. */
TL_TEST(stability_no_lights)
{
    mini_scene m;
    mini_init(&m, 1.0471976f, 0.1f, 100.0f);
    m.mat[0] = plain_material(0.5f, 0.5f, 0.5f);
    m.mat[0].emissive[0] = 0.01f;
    add_wall(&m, 5.0f, 0);
    m.s.ambient[0] = 0.1f;
    m.s.ambient[1] = 0.2f;
    m.s.ambient[2] = 0.3f;
    m.s.light_count = 0;
    char label[64];
    snprintf(label, sizeof label, "no lights");
    run u;
    if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, label)) return;
    check_all_targets_finite(&u, label);
    const double expect[3] = {half_rn(0.5f * 0.1f + 0.01f), half_rn(0.5f * 0.2f), half_rn(0.5f * 0.3f)};
    size_t wrong = 0, nonzero_light = 0;
    for (size_t i = 0; i < (size_t)64 * 64; i++)
        for (int ch = 0; ch < 3; ch++) {
            if (fabs(u.f.hdr[4 * i + ch] - expect[ch]) > half_ulp(expect[ch])) wrong++;
            if (u.f.diffuse && u.f.diffuse[4 * i + ch] != 0.0f) nonzero_light++;
            if (u.f.specular && u.f.specular[4 * i + ch] != 0.0f) nonzero_light++;
        }
    printf("  %s: HDR (%.6g, %.6g, %.6g) expected, %zu values differ by more than one FP16 step; "
           "%zu non-zero light values; %u light draws\n", label, (double)u.f.hdr[0], (double)u.f.hdr[1],
           (double)u.f.hdr[2], wrong, nonzero_light,
           u.stats.lights_drawn[1] + u.stats.lights_drawn[2] + u.stats.lights_drawn[3]);
    TL_CHECK_EQ_U(wrong, 0);
    TL_CHECK_EQ_U(nonzero_light, 0);
    TL_CHECK_EQ_U(u.stats.lights_drawn[1] + u.stats.lights_drawn[2] + u.stats.lights_drawn[3], 0);
    run_free(&u);
}

/* No geometry: a scene with lights but no vertices, indices, objects or materials, and one whose
 * only object has no triangles. Renders to black with every target finite. */
TL_TEST(stability_empty_scene)
{
    for (size_t mi = 0; mi < MODE_COUNT; mi++)
        for (int variant = 0; variant < 2; variant++) {
            mini_scene m;
            mini_init(&m, 1.0471976f, 0.1f, 100.0f);
            m.light[0] = point_light(0.0f, 0.0f, -2.0f, 5.0f, 1.0f, 1.0f, 1.0f);
            m.light[1] = (tl_light){TL_LIGHT_DIRECTIONAL, {0, 0, 0}, {0, -1, 0}, {1, 1, 1}, 0, 0, 0};
            m.light[2] = (tl_light){TL_LIGHT_SPOT, {0, 0, 0}, {0, 0, -1}, {1, 1, 1}, 5.0f, 0.9f, 0.8f};
            m.s.light_count = 3;
            m.s.ambient[0] = m.s.ambient[1] = m.s.ambient[2] = 0.5f;
            if (variant == 0) {
                m.s.vertices = NULL;
                m.s.indices = NULL;
                m.s.objects = NULL;
                m.s.materials = NULL;
                m.s.material_count = 0;
            } else { /* an object with an empty index range */
                add_wall(&m, 5.0f, 0);
                m.obj[0].index_count = 0;
            }
            char label[64];
            snprintf(label, sizeof label, "%s, %s", variant ? "empty object" : "no geometry",
                     tl_render_mode_name(modes[mi]));
            run u;
            if (!run_scene(&u, (tl_renderer_desc){.mode = modes[mi], .width = 64, .height = 64, .fxaa = TL_FXAA_29},
                           &m.s, label)) {
                fprintf(stderr, "  RENDERER BUG (DESIGN 5: a scene without geometry must render): %s\n", label);
                continue;
            }
            check_all_targets_finite(&u, label);
            uint8_t *img = malloc((size_t)64 * 64 * 4);
            TL_CHECK(tl_renderer_read_output(u.r, img, (size_t)64 * 64 * 4) == TL_OK);
            size_t lit = 0;
            for (size_t i = 0; i < (size_t)64 * 64 * 4; i++)
                if (i % 4 != 3) lit += img[i] != 0 || u.f.hdr[i] != 0.0f;
            printf("  %s: %zu non-black values\n", label, lit);
            TL_CHECK_EQ_U(lit, 0);
            free(img);
            run_free(&u);
        }
}

/* A 1x1 target: its one pixel centre lies on the view axis, as does the centre pixel of a 63x63
 * frame of the same scene (same aspect), so both must agree to two FP16 steps (light buffer and
 * HDR stores); in thin-deferred to one 8-bit chroma step of RT1 as well (the 1x1 image has no
 * neighbour to take the missing chroma from and gets neutral chroma: about 2 % in linear colour).
 * FXAA on one pixel changes nothing. */
TL_TEST(stability_1x1_target)
{
    for (size_t mi = 0; mi < MODE_COUNT; mi++) {
        mini_scene m;
        mini_init(&m, 1.0471976f, 0.1f, 100.0f);
        m.mat[0] = plain_material(0.5f, 0.5f, 0.6f);
        add_wall(&m, 5.0f, 0);
        m.light[0] = point_light(0.5f, 0.3f, -3.0f, 6.0f, 3.0f, 2.0f, 1.0f);
        m.light[1] = (tl_light){TL_LIGHT_DIRECTIONAL, {0, 0, 0}, {-0.2f, -0.3f, -1.0f}, {0.5f, 0.5f, 0.5f}, 0, 0, 0};
        m.light[2] = (tl_light){TL_LIGHT_SPOT, {0, 0, -1}, {0, 0, -1}, {4, 4, 4}, 8.0f, 0.95f, 0.9f};
        m.s.light_count = 3;
        m.s.ambient[2] = 0.05f;
        char label[64];
        snprintf(label, sizeof label, "1x1, %s", tl_render_mode_name(modes[mi]));
        run one, big, fx;
        if (!run_scene(&one, (tl_renderer_desc){.mode = modes[mi], .width = 1, .height = 1}, &m.s, label)) continue;
        check_all_targets_finite(&one, label);
        if (run_scene(&big, (tl_renderer_desc){.mode = modes[mi], .width = 63, .height = 63}, &m.s, "63x63")) {
            size_t c = (31 * 63 + 31) * 4, bad = 0;
            for (int ch = 0; ch < 3; ch++) {
                double a = one.f.hdr[ch], b = big.f.hdr[c + ch];
                printf("  %s: HDR[%d] %.9g vs centre of 63x63 %.9g\n", label, ch, a, b);
                double tol = 2.0 * half_ulp(b) + (modes[mi] == TL_MODE_THIN_DEFERRED ? 0.02 * b : 0.0);
                if (!(fabs(a - b) <= tol)) bad++;
                TL_CHECK(a > 0.0);
            }
            TL_CHECK_EQ_U(bad, 0);
            run_free(&big);
        }
        if (run_scene(&fx, (tl_renderer_desc){.mode = modes[mi], .width = 1, .height = 1, .fxaa = TL_FXAA_39}, &m.s,
                      "1x1 FXAA")) {
            uint8_t a[4], b[4];
            TL_CHECK(tl_renderer_read_output(one.r, a, 4) == TL_OK && tl_renderer_read_output(fx.r, b, 4) == TL_OK);
            printf("  %s: output (%u, %u, %u) without FXAA, (%u, %u, %u) with\n", label, a[0], a[1], a[2], b[0], b[1],
                   b[2]);
            for (int ch = 0; ch < 3; ch++) TL_CHECK(abs((int)a[ch] - (int)b[ch]) <= 1);
            run_free(&fx);
        }
        run_free(&one);
    }
}

/* The largest target the context allows. A square one at GL_MAX_TEXTURE_SIZE (16384 on llvmpipe)
 * needs 16384^2 x 40 B = 10 GiB of thin-lpp targets, so the limit is exercised on one axis at a
 * time: max x 8 (aspect 2048:1; a 0.002 rad vertical field of view is 128 degrees across) and
 * 8 x max (60 degrees vertical), each lit and checked against the model. One more pixel on
 * either axis must be refused with TL_ERROR_LIMIT and a message. */
typedef void (*get_integerv_fn)(unsigned int pname, int *data);

TL_TEST(stability_largest_target)
{
    TL_CHECK(ensure_context());
    if (!g_ctx) return;
    get_integerv_fn get_integerv = (get_integerv_fn)tl_context_get_proc_address(g_ctx, "glGetIntegerv");
    TL_CHECK(get_integerv != NULL);
    if (!get_integerv) return;
    int max_tex = 0, max_rb = 0, max_fb[2] = {0, 0}, max_vp[2] = {0, 0};
    get_integerv(0x0D33 /* GL_MAX_TEXTURE_SIZE */, &max_tex);
    get_integerv(0x84E8 /* GL_MAX_RENDERBUFFER_SIZE */, &max_rb);
    get_integerv(0x9315 /* GL_MAX_FRAMEBUFFER_WIDTH */, &max_fb[0]);
    get_integerv(0x9316 /* GL_MAX_FRAMEBUFFER_HEIGHT */, &max_fb[1]);
    get_integerv(0x0D3A /* GL_MAX_VIEWPORT_DIMS */, max_vp);
    printf("  GL_MAX_TEXTURE_SIZE %d, GL_MAX_RENDERBUFFER_SIZE %d, GL_MAX_FRAMEBUFFER_WIDTH/HEIGHT %d/%d, "
           "GL_MAX_VIEWPORT_DIMS %d x %d\n", max_tex, max_rb, max_fb[0], max_fb[1], max_vp[0], max_vp[1]);
    TL_CHECK(max_tex >= 1024);
    uint32_t max = (uint32_t)max_tex;
    for (int axis = 0; axis < 2; axis++) {
        uint32_t w = axis ? 8 : max, h = axis ? max : 8;
        mini_scene m;
        mini_init(&m, axis ? 1.0471976f : 0.002f, 0.1f, 100.0f);
        m.mat[0] = plain_material(0.5f, 0.5f, 0.5f);
        add_quad(&m, (float[3]){-1e3f, -1e3f, -5}, (float[3]){2e3f, 0, 0}, (float[3]){0, 2e3f, 0}, 0);
        m.light[0] = point_light(0.5f, 0.0f, -4.0f, 6.0f, 3.0f, 2.0f, 1.0f);
        m.light[1] = point_light(0.0f, -1.0f, -4.0f, 6.0f, 1.0f, 2.0f, 3.0f);
        m.s.light_count = 2;
        char label[64];
        snprintf(label, sizeof label, "%ux%u", w, h);
        run u;
        if (!run_scene(&u, (tl_renderer_desc){.width = w, .height = h, .fxaa = TL_FXAA_29}, &m.s,
                       label))
            continue;
        check_all_targets_finite(&u, label);
        light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 2, label);
        TL_CHECK_EQ_U(c.bad, 0);
        TL_CHECK(c.lit > 1000);
        run_free(&u);
        /* one pixel more */
        tl_renderer_desc d = {.width = axis ? 8 : max + 1, .height = axis ? max + 1 : 8,
                              .get_proc_address = tl_context_proc_loader, .get_proc_address_user = g_ctx};
        tl_renderer *r = NULL;
        char err[512] = "";
        tl_result res = tl_renderer_create(&d, &r, err, sizeof err);
        printf("  %ux%u: %s, \"%s\"\n", d.width, d.height, tl_result_string(res), err);
        TL_CHECK(res == TL_ERROR_LIMIT && r == NULL && strlen(err) > 10);
        tl_renderer_destroy(r);
    }
}

/* Zero-area triangles (three equal vertices, collinear vertices, a triangle seen edge-on, two
 * equal vertices) in front of a wall produce no fragment: every target equals the wall-only frame
 * bit for bit. A quad whose vertex normals are zero stores the shading normal's fallback, +Z
 * facing the viewer (shaders/material.glsl), to within the oct12 error. */
TL_TEST(stability_degenerate_triangles)
{
    mini_scene m;
    mini_init(&m, 1.0471976f, 0.1f, 100.0f);
    m.mat[0] = plain_material(0.5f, 0.5f, 0.5f);
    m.mat[1] = plain_material(0.8f, 0.5f, 0.9f);
    m.mat[1].flags = TL_MATERIAL_DOUBLE_SIDED;
    m.s.material_count = 2;
    add_wall(&m, 5.0f, 0);
    m.light[0] = point_light(0.5f, 0.3f, -3.0f, 6.0f, 3.0f, 2.0f, 1.0f);
    m.s.light_count = 1;
    run ref, u;
    if (!run_scene(&ref, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, "wall only")) return;
    /* degenerate object: 4 triangles over 7 vertices */
    uint32_t b = (uint32_t)m.nv;
    /* (0 0 0): one point; (1 0 3): collinear points; (1 2 3): a triangle seen edge-on (its
     * plane holds the view axis); (4 5 6): two equal vertices */
    const float pts[7][3] = {{0, 0, -3}, {-1, -1, -3}, {0, 0, -3.5f}, {1, 1, -3}, {0.5f, 0.2f, -2},
                             {0.5f, 0.2f, -2}, {-0.7f, 0.4f, -2.5f}};
    for (int k = 0; k < 7; k++) {
        memset(&m.v[m.nv], 0, sizeof m.v[0]);
        memcpy(m.v[m.nv].position, pts[k], sizeof pts[k]);
        m.v[m.nv].normal[2] = 1.0f;
        m.nv++;
    }
    const uint32_t tris[12] = {0, 0, 0, 1, 0, 3, 1, 2, 3, 4, 5, 6};
    tl_object *ob = &m.obj[m.s.object_count++];
    memset(ob, 0, sizeof *ob);
    memcpy(ob->transform, identity, sizeof identity);
    ob->first_index = (uint32_t)m.ni;
    ob->index_count = 12;
    ob->material = 1;
    ob->bounds_min[0] = -1, ob->bounds_min[1] = -1, ob->bounds_min[2] = -4;
    ob->bounds_max[0] = 1, ob->bounds_max[1] = 1, ob->bounds_max[2] = -2;
    for (int k = 0; k < 12; k++) m.idx[m.ni++] = b + tris[k];
    m.s.vertex_count = m.nv;
    m.s.index_count = m.ni;
    char label[64];
    snprintf(label, sizeof label, "degenerate triangles");
    if (run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, label)) {
        check_all_targets_finite(&u, label);
        size_t differ = 0;
        for (size_t i = 0; i < (size_t)64 * 64 * 4; i++)
            differ += u.f.depth[i] != ref.f.depth[i] || u.f.rt0[i] != ref.f.rt0[i] ||
                      u.f.diffuse[i] != ref.f.diffuse[i] || u.f.hdr[i] != ref.f.hdr[i];
        printf("  %s: %zu values differ from the wall-only frame\n", label, differ);
        TL_CHECK_EQ_U(differ, 0);
        run_free(&u);
    }
    /* a quad with zero vertex normals in front of the wall */
    mini_scene z;
    mini_init(&z, 1.0471976f, 0.1f, 100.0f);
    z.mat[0] = plain_material(0.5f, 0.5f, 0.5f);
    add_wall(&z, 5.0f, 0);
    add_quad(&z, (float[3]){-1, -1, -3}, (float[3]){2, 0, 0}, (float[3]){0, 2, 0}, 0);
    for (int k = 4; k < 8; k++) z.v[k].normal[0] = z.v[k].normal[1] = z.v[k].normal[2] = 0.0f;
    z.light[0] = point_light(0.5f, 0.3f, -2.0f, 6.0f, 3.0f, 2.0f, 1.0f);
    z.s.light_count = 1;
    snprintf(label, sizeof label, "zero normals");
    if (run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &z.s, label)) {
        check_all_targets_finite(&u, label);
        size_t i = (32 * 64 + 32) * 4; /* on the zero-normal quad */
        printf("  %s: stored normal (%.6f, %.6f, %.6f), depth %.4f m\n", label, (double)u.f.rt0[i],
               (double)u.f.rt0[i + 1], (double)u.f.rt0[i + 2], (double)u.f.depth[i + 1]);
        TL_CHECK(fabs(u.f.depth[i + 1] - 3.0f) < 1e-3f);
        TL_CHECK(u.f.rt0[i + 2] > cosf(0.0393f * 3.14159265f / 180.0f) - 1e-6f);
        run_free(&u);
    }
    run_free(&ref);
}

/* NaN and Inf in vertex positions and normals. tl_renderer_set_scene may refuse such a scene
 * (TL_ERROR_INVALID_ARGUMENT with a message naming the vertex); if it accepts it, the frame must
 * keep every target finite and still show the valid wall. */
TL_TEST(stability_nan_inf_vertices)
{
    static const struct { int field; float value; const char *what; } cases[] = {
        {0, NAN, "NaN position"}, {0, INFINITY, "+Inf position"}, {0, -INFINITY, "-Inf position"},
        {1, NAN, "NaN normal"},   {1, INFINITY, "Inf normal"},    {2, NAN, "NaN uv"},
    };
    TL_CHECK(ensure_context());
    if (!g_ctx) return;
    for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++) {
        mini_scene m;
        mini_init(&m, 1.0471976f, 0.1f, 100.0f);
        m.mat[0] = plain_material(0.5f, 0.5f, 0.5f);
        add_wall(&m, 5.0f, 0);
        add_quad(&m, (float[3]){-1, -1, -3}, (float[3]){2, 0, 0}, (float[3]){0, 2, 0}, 0);
        tl_vertex *v = &m.v[5]; /* one corner of the small quad */
        if (cases[ci].field == 0) v->position[0] = cases[ci].value;
        if (cases[ci].field == 1) v->normal[1] = cases[ci].value;
        if (cases[ci].field == 2) v->uv[0] = cases[ci].value;
        m.light[0] = point_light(0.5f, 0.3f, -2.0f, 6.0f, 3.0f, 2.0f, 1.0f);
        m.s.light_count = 1;
        char label[80];
        snprintf(label, sizeof label, "%s", cases[ci].what);
        tl_renderer *r = make_renderer((tl_renderer_desc){.width = 64, .height = 64});
        TL_CHECK(r != NULL);
        if (!r) continue;
        tl_result res = tl_renderer_set_scene(r, &m.s);
        if (res != TL_OK) {
            printf("  %s: refused, %s: \"%s\"\n", label, tl_result_string(res), tl_renderer_last_error(r));
            TL_CHECK(res == TL_ERROR_INVALID_ARGUMENT);
            TL_CHECK(strstr(tl_renderer_last_error(r), "vertex") != NULL);
        } else {
            TL_CHECK(tl_renderer_render(r, NULL, NULL) == TL_OK);
            size_t bad = 0, n = count_nonfinite_all_targets(r, label, &bad);
            float *hdr = read_target(r, TL_TARGET_HDR);
            double corner = hdr ? hdr[(2 * 64 + 2) * 4 + 1] : 0.0; /* wall pixel away from the quad */
            printf("  %s: accepted; %zu targets, %zu non-finite values; wall HDR %.4g\n", label, n, bad, corner);
            if (bad) fprintf(stderr, "  RENDERER BUG (DESIGN 5: NaN/Inf vertices reach a target): %s\n", label);
            TL_CHECK_EQ_U(bad, 0);
            TL_CHECK(corner > 0.0);
            free(hdr);
        }
        tl_renderer_destroy(r);
    }
}

/* Missing textures: a texture without pixels, with a zero or oversized extent, and material
 * texture indices out of range all fall back to the flat material colour: every target equals the
 * frame rendered with TL_NO_TEXTURE, bit for bit. */
TL_TEST(stability_missing_textures)
{
    uint8_t *wide = calloc((size_t)20000 * 4, 1);
    mini_scene m;
    mini_init(&m, 1.0471976f, 0.1f, 100.0f);
    m.mat[0] = plain_material(0.6f, 0.5f, 0.5f);
    add_wall(&m, 5.0f, 0);
    m.light[0] = point_light(0.5f, 0.3f, -3.0f, 6.0f, 3.0f, 2.0f, 1.0f);
    m.s.light_count = 1;
    run ref, u;
    if (!run_scene(&ref, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, "no texture")) return;
    static const char *const what[] = {"rgba NULL", "width 0", "20000 x 1 (over the limit)", "index out of range",
                                       "every texture index out of range"};
    for (int c = 0; c < 5; c++) {
        mini_scene t = m;
        t.s.vertices = t.v;
        t.s.indices = t.idx;
        t.s.objects = t.obj;
        t.s.materials = t.mat;
        t.s.lights = t.light;
        t.s.textures = t.tex;
        t.s.texture_count = 1;
        t.tex[0] = (tl_texture){4, 4, NULL, "missing"};
        if (c == 1) t.tex[0] = (tl_texture){0, 4, wide, "empty"};
        if (c == 2) t.tex[0] = (tl_texture){20000, 1, wide, "too wide"};
        t.mat[0].albedo_texture = c >= 3 ? 7u : 0u;
        if (c == 4) {
            t.mat[0].normal_texture = t.mat[0].metallic_roughness_texture = 9u;
            t.mat[0].emissive_texture = t.mat[0].occlusion_texture = 1u;
        }
        char label[80];
        snprintf(label, sizeof label, "texture %s", what[c]);
        if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &t.s, label)) continue;
        check_all_targets_finite(&u, label);
        size_t differ = 0;
        for (size_t i = 0; i < (size_t)64 * 64 * 4; i++) differ += u.f.hdr[i] != ref.f.hdr[i];
        printf("  %s: %zu HDR values differ from the untextured frame\n", label, differ);
        TL_CHECK_EQ_U(differ, 0);
        run_free(&u);
    }
    run_free(&ref);
    free(wide);
}

/* ---- depth: positions at the near and far plane, grazing view rays -------------------------- */

typedef struct plane_quad {
    double n[3], c;        /* n . p = c */
    double lo[3], hi[3];   /* extent */
} plane_quad;

/* Exact view-space z of the nearest quad hit by the ray through NDC (x, y); 0 when none. */
static double exact_z(const tl_projection *pr, double x, double y, const plane_quad *q, size_t count, double near_z)
{
    double r[3] = {(x + pr->m[8]) / pr->m[0], (y + pr->m[9]) / pr->m[5], -1.0}; /* the ray's point at z = -1 */
    double best = 0.0;
    for (size_t k = 0; k < count; k++) {
        double nd = q[k].n[0] * r[0] + q[k].n[1] * r[1] + q[k].n[2] * r[2];
        if (nd == 0.0) continue;
        double t = q[k].c / nd;
        if (!(t >= near_z)) continue; /* behind the camera or clipped by the near plane */
        int inside = 1;
        for (int a = 0; a < 3; a++) {
            double v = r[a] * t, lo = q[k].lo[a], hi = q[k].hi[a];
            inside &= v >= lo - 1e-9 * fabs(lo) && v <= hi + 1e-9 * fabs(hi);
        }
        if (inside && (best == 0.0 || t < best)) best = t;
    }
    return -best;
}

/* Window depth of view-space z, exactly (double). */
static double exact_window(const tl_projection *pr, double z)
{
    double ndc = (pr->m[10] * z + pr->m[14]) / (-z);
    return pr->format == TL_DEPTH_FORMAT_D32F_REVERSED ? ndc : 0.5 * ndc + 0.5;
}

/* View-space z of a window depth, exactly (double). */
static double exact_linearize(const tl_projection *pr, double w)
{
    double zn = pr->format == TL_DEPTH_FORMAT_D32F_REVERSED ? w : 2.0 * w - 1.0;
    return pr->m[14] / (pr->m[11] * zn - pr->m[10]);
}

/* One step of the stored depth at window depth w: a D24 code, or a float ULP for D32F. */
static double depth_step(tl_depth_format f, double w)
{
    if (f != TL_DEPTH_FORMAT_D32F_REVERSED && f != TL_DEPTH_FORMAT_D32F) return 1.0 / 16777215.0;
    float wf = (float)w;
    return (double)nextafterf(wf, INFINITY) - (double)wf;
}

typedef struct depth_stats {
    size_t pixels, at_far, bad_window, bad_position;
    double max_window_ratio, max_rel, max_allowed_rel;
} depth_stats;

/* Compares the DEPTH target (window depth, linear distance) and the position the light pass
 * reconstructs from it (the view-ray method) with the exact intersection, pixel by pixel.
 *
 * The window depth may differ from the exact one by
 * - the format's rounding: half a D24 code, or half a float ULP for D32F;
 * - the vertex transform in float: clip z = m10 z + m14 and the divide by w round at 2^-24 of
 *   |m10| + |m14 / z| (this dominates reversed Z near a finite far plane, where the two terms
 *   cancel: window ~ 1e-7 from terms ~ 1e-3);
 * - the rasteriser's float plane equation, 2^-24 of the window's change across the image per
 *   operation; `slope_ops` of them are allowed (walls facing the camera have no change).
 * The allowed position error is what that window interval gives through the exact inverse
 * projection, plus 4 x 2^-22 for the float reconstruction (docs/precision.md). A pixel that the
 * exact depth puts within that interval of the far plane may hold the clear value (D24 at
 * 1:10^7 cannot tell the last 4 x 10^-4 of the range from the far plane). */
static depth_stats check_depth(const run *u, const plane_quad *q, size_t count, double near_z, double slope_ops,
                               const char *label)
{
    depth_stats st = {0};
    tl_depth_format f = u->desc.depth_format ? u->desc.depth_format : TL_DEPTH_FORMAT_D24;
    int rev = f == TL_DEPTH_FORMAT_D32F_REVERSED;
    const tl_projection *pr = &u->pr;
    size_t shown = 0;
    for (uint32_t y = 0; y < u->f.h; y++)
        for (uint32_t x = 0; x < u->f.w; x++) {
            float ndc[2], nx[2], ny[2];
            pixel_ndc(x, y, u->f.w, u->f.h, ndc);
            pixel_ndc(x + 1, y, u->f.w, u->f.h, nx);
            pixel_ndc(x, y + 1, u->f.w, u->f.h, ny);
            double z = exact_z(pr, ndc[0], ndc[1], q, count, near_z);
            if (z == 0.0) continue;
            size_t i = ((size_t)y * u->f.w + x) * 4;
            double w = exact_window(pr, z);
            double zx = exact_z(pr, nx[0], nx[1], q, count, near_z), zy = exact_z(pr, ny[0], ny[1], q, count, near_z);
            double gx = zx != 0.0 ? fabs(exact_window(pr, zx) - w) : 0.0;
            double gy = zy != 0.0 ? fabs(exact_window(pr, zy) - w) : 0.0;
            double tol = 0.5 * depth_step(f, w) +
                         4.0 * 0x1.0p-24 * (fabs(pr->m[10]) + fabs(pr->m[14] / z)) * (rev ? 1.0 : 0.5) +
                         slope_ops * 0x1.0p-24 * (gx * u->f.w + gy * u->f.h);
            double wl = fmax(w - tol, rev ? 0x1.0p-149 : 0.0), wh = fmin(w + tol, rev ? 1.0 : 1.0 - 0x1.0p-40);
            if (u->f.depth[i] == u->clear && (rev ? w - tol <= 0.0 : w + tol >= 1.0)) {
                st.at_far++;
                continue;
            }
            st.pixels++;
            double dw = fabs((double)u->f.depth[i] - w);
            st.max_window_ratio = fmax(st.max_window_ratio, dw / tol);
            if (!(dw <= tol)) {
                if (shown++ < 4)
                    fprintf(stderr, "  %s: pixel (%u, %u) window depth %.9g, exact %.9g, allowed +-%.3g\n", label, x, y,
                            (double)u->f.depth[i], w, tol);
                st.bad_window++;
            }
            gsample g;
            if (!gbuffer_sample(&u->f, pr, u->clear, x, y, &g)) {
                st.bad_position++;
                continue;
            }
            double r[3] = {-z * (ndc[0] + pr->m[8]) / pr->m[0], -z * (ndc[1] + pr->m[9]) / pr->m[5], z};
            double rl = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
            double e = sqrt((g.p[0] - r[0]) * (g.p[0] - r[0]) + (g.p[1] - r[1]) * (g.p[1] - r[1]) +
                            (g.p[2] - r[2]) * (g.p[2] - r[2])) / rl;
            double za = exact_linearize(pr, wl), zb = exact_linearize(pr, wh);
            double allowed = fmax(fabs(za - z), fabs(zb - z)) / fabs(z) + 4.0 * 0x1.0p-22;
            st.max_rel = fmax(st.max_rel, e);
            st.max_allowed_rel = fmax(st.max_allowed_rel, allowed);
            if (!(e <= allowed)) {
                if (shown++ < 8)
                    fprintf(stderr, "  %s: pixel (%u, %u) position error %.3g > allowed %.3g\n", label, x, y, e,
                            allowed);
                st.bad_position++;
            }
        }
    printf("  %s: %zu pixels (+%zu lost to the far plane), window depth error at most %.3g of its allowance, "
           "position relative error max %.3g (allowed up to %.3g); %zu / %zu beyond\n", label, st.pixels, st.at_far,
           st.max_window_ratio, st.max_rel, st.max_allowed_rel, st.bad_window, st.bad_position);
    return st;
}

/* Walls exactly at the near plane and just inside the far plane (1 - 2^-12 of it), and at 10^6
 * near distances with an infinite far plane, in D24 and reversed-Z D32F. */
TL_TEST(stability_positions_at_near_and_far_plane)
{
    static const struct { float near_z, far_z, dist; const char *what; } cases[] = {
        {0.1f, 100.0f, 0.1f, "at the near plane (0.1)"},
        {0.1f, 100.0f, 100.0f * (1.0f - 0x1.0p-12f), "at the far plane (100 (1 - 2^-12))"},
        {0.1f, 1e6f, 1e6f * (1.0f - 0x1.0p-12f), "at the far plane of 1:10^7"},
        {0.1f, 0.0f, 1e5f, "at 10^6 near distances, infinite far plane"},
    };
    const tl_depth_format formats[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++)
        for (int f = 0; f < 2; f++) {
            mini_scene m;
            mini_init(&m, 1.0471976f, cases[ci].near_z, cases[ci].far_z);
            m.mat[0] = plain_material(0.5f, 0.5f, 0.5f);
            add_wall(&m, cases[ci].dist, 0);
            float d = cases[ci].dist;
            float k = d * d; /* about 1 at the wall */
            m.light[0] = point_light(0.1f * d, 0.1f * d, -0.5f * d, 2.0f * d, k, k, k);
            m.s.light_count = 1;
            char label[128];
            snprintf(label, sizeof label, "wall %s, %s", cases[ci].what, tl_depth_format_name(formats[f]));
            run u;
            if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64, .depth_format = formats[f]}, &m.s, label))
                continue;
            check_all_targets_finite(&u, label);
            float s = 2.0f * d + 1.0f;
            plane_quad q = {{0, 0, 1}, -(double)d, {-s, -s, -d - 1.0}, {s, s, -d + 1.0}};
            depth_stats st = check_depth(&u, &q, 1, cases[ci].near_z, 1.0, label);
            TL_CHECK(st.pixels + st.at_far == 64 * 64);
            TL_CHECK_EQ_U(st.bad_window, 0);
            TL_CHECK_EQ_U(st.bad_position, 0);
            light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 1, label);
            TL_CHECK_EQ_U(c.bad, 0);
            TL_CHECK(c.lit > 1000 || st.at_far == 64 * 64); /* D24 at 1:10^7: the wall merges with the far plane */
            run_free(&u);
        }
}

/* Grazing view rays: a 170-degree field of view over a floor 1 m below the eye, out to a wall at
 * 50 m (D24 and reversed D32F, far 1000). Rays meet the floor at down to 1.3 degrees near the
 * horizon and leave the axis by up to 85 degrees at the image edges; positions reconstructed
 * from the stored depth must match the exact intersections within the depth steps that the
 * sloped plane equation costs (4 at these slopes, measured 2), and lighting must match the model. */
TL_TEST(stability_grazing_view_rays_positions)
{
    const tl_depth_format formats[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    for (int f = 0; f < 2; f++) {
        mini_scene m;
        mini_init(&m, 2.96706f, 0.1f, 1000.0f);
        m.mat[0] = plain_material(0.5f, 0.5f, 0.7f);
        add_quad(&m, (float[3]){-2000, -1, 1}, (float[3]){4000, 0, 0}, (float[3]){0, 0, -51}, 0); /* floor */
        add_quad(&m, (float[3]){-2000, -1, -50}, (float[3]){4000, 0, 0}, (float[3]){0, 2000, 0}, 0); /* wall */
        m.light[0] = point_light(0.0f, 2.0f, -20.0f, 60.0f, 200.0f, 200.0f, 200.0f);
        m.s.light_count = 1;
        char label[96];
        snprintf(label, sizeof label, "grazing rays, %s", tl_depth_format_name(formats[f]));
        run u;
        if (!run_scene(&u, (tl_renderer_desc){.width = 96, .height = 64,
                                              .depth_format = formats[f]}, &m.s, label))
            continue;
        check_all_targets_finite(&u, label);
        plane_quad q[2] = {{{0, 1, 0}, -1.0, {-2000, -1.5, -50}, {2000, -0.5, 1}},
                           {{0, 0, 1}, -50.0, {-2000, -1, -51}, {2000, 1999, -49}}};
        depth_stats st = check_depth(&u, q, 2, 0.1, 16.0, label);
        TL_CHECK(st.pixels >= 96 * 56); /* the bottom rows' floor is cut by the near plane */
        TL_CHECK_EQ_U(st.bad_window, 0);
        TL_CHECK_EQ_U(st.bad_position, 0);
        light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 1, label);
        TL_CHECK_EQ_U(c.bad, 0);
        run_free(&u);
    }
}
