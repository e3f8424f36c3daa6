/* The render modes against the double-precision lighting reference (tests/common/reference), pixel
 * by pixel, on the built-in crypt (modes_reference.h). */
#include "modes_reference.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lighting_ref.h"
#include "render_fixture.h"
#include "thinlight/codec.h"
#include "tl_test.h"

#define BIT(t) TL_TARGET_BIT(t)

/* The stored normals' angular error: fat's RGBA16F components within half an FP16 step, 2^-11
 * relative, so the direction within sqrt(3) 2^-11 rad (as test_ggx_render.c). Forward shades the
 * interpolated normal, which fat stores rounded: its reference is fat's normal tilted that far. */
#define FAT_NORMAL_ERROR (1.7320508 / 2048.0)

static void capture_view(void *user, const tl_app_pass_context *ctx)
{
    modes_frame *f = (modes_frame *)user;
    memcpy(f->view, ctx->view->view, sizeof f->view);
    memcpy(f->proj, ctx->view->projection, sizeof f->proj);
}

static float *read_target(tl_renderer *r, tl_target_id id, size_t n)
{
    size_t size = n * 4 * sizeof(float);
    float *p = malloc(size);
    if (p && tl_renderer_read_target(r, id, p, &size) != TL_OK) {
        free(p);
        return NULL;
    }
    return p;
}

int modes_render(const tl_scene *s, tl_renderer_desc d, modes_frame *f)
{
    memset(f, 0, sizeof *f);
    tl_app_pass_desc ap = {.name = "capture-view", .before = "tonemap", .writes = BIT(TL_TARGET_HDR),
                           .execute = capture_view, .user = f};
    tl_renderer *r = tl_test_renderer(
        &(tl_test_renderer_desc){.renderer = d, .scene = s, .passes = &ap, .pass_count = 1, .frames = 1, .readable = true});
    if (!r) return 0;
    size_t n = (size_t)d.width * d.height;
    int ok = tl_renderer_get_plan(r, &f->plan) == TL_OK;
    f->w = d.width;
    f->h = d.height;
    f->mode = d.options.mode;
    f->depth_format = d.options.depth_format ? d.options.depth_format : TL_DEPTH_FORMAT_D24;
    f->hdr = ok ? read_target(r, TL_TARGET_HDR, n) : NULL;
    f->ldr = ok ? read_target(r, TL_TARGET_LDR, n) : NULL;
    f->out = ok ? malloc(n * 4) : NULL;
    if (f->out && tl_renderer_read_output(r, f->out, &(size_t){n * 4}) != TL_OK) ok = 0;
    f->depth = ok ? read_target(r, TL_TARGET_DEPTH, n) : NULL;
    if (ok && d.options.mode == TL_MODE_FAT && s->light_count) { /* without lights nothing reads them */
        f->position = read_target(r, TL_TARGET_FAT_POSITION, n);
        f->normal = read_target(r, TL_TARGET_FAT_NORMAL, n);
        f->albedo = read_target(r, TL_TARGET_FAT_ALBEDO, n);
        f->material = read_target(r, TL_TARGET_FAT_MATERIAL, n);
        ok = f->position && f->normal && f->albedo && f->material;
    }
    if (ok && (d.options.mode == TL_MODE_THIN_LPP || d.options.mode == TL_MODE_THIN_DEFERRED))
        ok = (f->normal = read_target(r, TL_TARGET_RT0, n)) != NULL;
    if (ok && d.options.mode == TL_MODE_VISIBILITY) ok = (f->vis_id = read_target(r, TL_TARGET_VIS_ID, n)) != NULL;
    tl_renderer_destroy(r);
    return ok && f->hdr && f->ldr && f->out && f->depth;
}

void modes_frame_free(modes_frame *f)
{
    void *p[] = {f->hdr, f->ldr, f->out, f->depth, f->position, f->normal, f->albedo, f->material, f->vis_id};
    for (size_t i = 0; i < sizeof p / sizeof p[0]; i++) free(p[i]);
    memset(f, 0, sizeof *f);
}

/* ---- the reference ------------------------------------------------------------------------------ */

static void lights_to_view(const tl_scene *s, const float view[16], tl_ref_light *out)
{
    for (size_t i = 0; i < s->light_count; i++) {
        const tl_light *l = &s->lights[i];
        tl_ref_light *o = &out[i];
        memset(o, 0, sizeof *o);
        o->type = (tl_ref_light_type)(l->type ? l->type : TL_LIGHT_POINT);
        double dl = sqrt((double)l->direction[0] * l->direction[0] + (double)l->direction[1] * l->direction[1] +
                         (double)l->direction[2] * l->direction[2]);
        for (int k = 0; k < 3; k++) {
            o->position[k] = (double)view[k] * l->position[0] + (double)view[4 + k] * l->position[1] +
                             (double)view[8 + k] * l->position[2] + view[12 + k];
            o->direction[k] = ((double)view[k] * l->direction[0] + (double)view[4 + k] * l->direction[1] +
                               (double)view[8 + k] * l->direction[2]) / dl;
            o->color[k] = l->color[k] > 0.0f ? l->color[k] : 0.0;
        }
        o->range = l->radius;
        o->source_radius = 0.0; /* Blinn-Phong: punctual (GGX: set by the caller) */
        o->cos_inner = l->type == TL_LIGHT_SPOT ? l->cos_inner : 1.0;
        o->cos_outer = l->cos_outer;
        o->specular = l->specular;
    }
}

/* Radiance of the lights alone (no ambient, no emission) at p with normal n, and its range over n
 * tilted by `tilt` radians four ways. */
static void shade_range(tl_ref_model model, const tl_ref_surface *surf, const double p[3], const double n[3], double tilt,
                        const tl_ref_light *lights, size_t count, double centre[3], double lo[3], double hi[3])
{
    const double zero[3] = {0, 0, 0};
    tl_ref_shade(model, surf, p, n, lights, count, zero, centre);
    for (int k = 0; k < 3; k++) lo[k] = hi[k] = centre[k];
    if (tilt <= 0.0) return;
    double a[3] = {fabs(n[0]) < 0.9 ? 1.0 : 0.0, fabs(n[0]) < 0.9 ? 0.0 : 1.0, 0.0}, t[2][3];
    t[0][0] = n[1] * a[2] - n[2] * a[1];
    t[0][1] = n[2] * a[0] - n[0] * a[2];
    t[0][2] = n[0] * a[1] - n[1] * a[0];
    double l = sqrt(t[0][0] * t[0][0] + t[0][1] * t[0][1] + t[0][2] * t[0][2]);
    for (int k = 0; k < 3; k++) t[0][k] /= l;
    t[1][0] = n[1] * t[0][2] - n[2] * t[0][1];
    t[1][1] = n[2] * t[0][0] - n[0] * t[0][2];
    t[1][2] = n[0] * t[0][1] - n[1] * t[0][0];
    for (int j = 0; j < 4; j++) {
        double m[3], c[3], sgn = j & 1 ? -1.0 : 1.0, tn = tan(tilt);
        for (int k = 0; k < 3; k++) m[k] = n[k] + sgn * tn * t[j >> 1][k];
        tl_ref_shade(model, surf, p, m, lights, count, zero, c);
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], c[k]);
            hi[k] = fmax(hi[k], c[k]);
        }
    }
}

/* The view position of pixel (x, y) of a mode's frame: fat's position target; the depth target
 * rebuilt with the codec (the GLSL twin) otherwise, with `step` float steps added to the window
 * depth. 0 for the background. */
static int frame_position(const modes_frame *f, const tl_projection *pr, size_t x, size_t y, int step, double p[3])
{
    size_t i = y * f->w + x;
    if (f->position) {
        for (int k = 0; k < 3; k++) p[k] = f->position[4 * i + k];
        return f->position[4 * i + 3] > 0.5f;
    }
    float d = f->depth[4 * i], q[3];
    if (d == (f->depth_format == TL_DEPTH_FORMAT_D32F_REVERSED ? 0.0f : 1.0f)) return 0;
    if (step) d = nextafterf(d, step > 0 ? 2.0f : -1.0f);
    float ndc_x = ((float)x + 0.5f) * (1.0f / (float)f->w) * 2.0f - 1.0f;
    float ndc_y = ((float)y + 0.5f) * (1.0f / (float)f->h) * 2.0f - 1.0f;
    tl_view_position_from_depth(pr, ndc_x, ndc_y, d, q);
    for (int k = 0; k < 3; k++) p[k] = q[k];
    return 1;
}

/* The lights that reach p (the windowed falloff is exactly 0 from the range on). */
static size_t lights_at(const tl_ref_light *all, size_t count, const double p[3], tl_ref_light *out)
{
    size_t n = 0;
    for (size_t i = 0; i < count; i++) {
        if (all[i].type != TL_REF_LIGHT_DIRECTIONAL) {
            double d2 = 0.0;
            for (int k = 0; k < 3; k++) d2 += (p[k] - all[i].position[k]) * (p[k] - all[i].position[k]);
            if (d2 >= all[i].range * all[i].range) continue;
        }
        out[n++] = all[i];
    }
    return n;
}

/* ---- visibility's surface outside its triangle ---------------------------------------------- */

static void cross3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Window coordinates (pixels) of view-space point p. */
static void to_window(const modes_frame *m, const double p[3], double out[2])
{
    double c[4];
    for (int r = 0; r < 4; r++)
        c[r] = (double)m->proj[r] * p[0] + (double)m->proj[4 + r] * p[1] + (double)m->proj[8 + r] * p[2] + m->proj[12 + r];
    out[0] = (c[0] / c[3] * 0.5 + 0.5) * m->w;
    out[1] = (c[1] / c[3] * 0.5 + 0.5) * m->h;
}

/* Distance in pixels from q to segment ab. */
static double segment_distance(const double q[2], const double a[2], const double b[2])
{
    double ex = b[0] - a[0], ey = b[1] - a[1], l2 = ex * ex + ey * ey;
    double t = l2 > 0.0 ? fmin(fmax(((q[0] - a[0]) * ex + (q[1] - a[1]) * ey) / l2, 0.0), 1.0) : 0.0;
    return hypot(q[0] - a[0] - t * ex, q[1] - a[1] - t * ey);
}

/* Pixel (x, y) of a visibility frame whose centre lies outside its triangle (the one VIS_ID names),
 * in double. The rasteriser covers a pixel whose centre is outside the exact triangle by up to its
 * sub-pixel snapping of the vertices, and shades its attribute planes extrapolated there, as
 * vis_rebuild.glsl does. Returns 1 with the centre's distance outside the triangle in pixels and
 * the triangle's own point nearest in barycentrics (clamped to [0, 1] and renormalised), with its
 * normal (the interpolated one, facing the eye as the resolve's); 0 where the centre is inside (or
 * nothing was drawn); -1 where the id names no triangle of the scene. */
/* Triangle `tri` of object `obj` in the frame's view space: its vertices and vertex normals. */
static void vis_triangle(const tl_scene *s, const modes_frame *m, size_t obj, size_t tri, double P[3][3], double N[3][3])
{
    const tl_object *o = &s->objects[obj];
    double model[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, mv[16];
    int zero = 1;
    for (int k = 0; k < 16; k++) zero &= o->transform[k] == 0.0f;
    for (int k = 0; k < 16 && !zero; k++) model[k] = o->transform[k];
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++) {
            mv[4 * c + r] = 0.0;
            for (int k = 0; k < 4; k++) mv[4 * c + r] += (double)m->view[4 * k + r] * model[4 * c + k];
        }
    /* the normal matrix: the cofactors of model-view's 3x3 (its inverse transpose times the
     * determinant; the direction is normalised below, so only the determinant's sign matters) */
    double col[3][3], nm[3][3];
    for (int c = 0; c < 3; c++)
        for (int r = 0; r < 3; r++) col[c][r] = mv[4 * c + r];
    cross3(col[1], col[2], nm[0]);
    cross3(col[2], col[0], nm[1]);
    cross3(col[0], col[1], nm[2]);
    double det = dot3(col[0], nm[0]);
    for (int v = 0; v < 3; v++) {
        const tl_vertex *vx = &s->vertices[s->indices[o->first_index + 3 * tri + (size_t)v]];
        for (int r = 0; r < 3; r++) {
            P[v][r] = mv[12 + r];
            N[v][r] = 0.0;
            for (int k = 0; k < 3; k++) {
                P[v][r] += mv[4 * k + r] * vx->position[k];
                N[v][r] += nm[k][r] * vx->normal[k] * (det < 0.0 ? -1.0 : 1.0);
            }
        }
    }
}

static int vis_surface_outside(const tl_scene *s, const modes_frame *m, const tl_projection *pr, size_t x, size_t y,
                               double p[3], double n[3], double *outside_px)
{
    size_t i = y * m->w + x;
    if (m->vis_id[4 * i + 2] == 0.0f) return 0;
    const size_t obj = (size_t)m->vis_id[4 * i], tri = (size_t)m->vis_id[4 * i + 1];
    if (obj >= s->object_count || 3 * tri + 2 >= s->objects[obj].index_count) return -1; /* no such triangle */
    double P[3][3], N[3][3];
    vis_triangle(s, m, obj, tri, P, N);
    /* the pixel centre's ray, through two depths of its window point */
    float ndc_x = ((float)x + 0.5f) * (1.0f / (float)m->w) * 2.0f - 1.0f;
    float ndc_y = ((float)y + 0.5f) * (1.0f / (float)m->h) * 2.0f - 1.0f, q0[3], q1[3];
    tl_view_position_from_depth(pr, ndc_x, ndc_y, 0.25f, q0);
    tl_view_position_from_depth(pr, ndc_x, ndc_y, 0.75f, q1);
    double org[3], dir[3], e1[3], e2[3], pv[3], t[3], qv[3];
    for (int k = 0; k < 3; k++) {
        org[k] = q0[k];
        dir[k] = (double)q1[k] - q0[k];
        e1[k] = P[1][k] - P[0][k];
        e2[k] = P[2][k] - P[0][k];
        t[k] = org[k] - P[0][k];
    }
    cross3(dir, e2, pv);
    double inv = 1.0 / dot3(e1, pv);
    cross3(t, e1, qv);
    double b[3] = {0.0, dot3(t, pv) * inv, dot3(dir, qv) * inv};
    b[0] = 1.0 - b[1] - b[2];
    if (!isfinite(b[0]) || !isfinite(b[1]) || !isfinite(b[2]) || fmin(b[0], fmin(b[1], b[2])) >= 0.0) return 0;
    double win[3][2], centre[2] = {(double)x + 0.5, (double)y + 0.5};
    for (int v = 0; v < 3; v++) to_window(m, P[v], win[v]);
    *outside_px = fmin(segment_distance(centre, win[0], win[1]),
                       fmin(segment_distance(centre, win[1], win[2]), segment_distance(centre, win[2], win[0])));
    double sum = 0.0;
    for (int v = 0; v < 3; v++) sum += (b[v] = fmin(fmax(b[v], 0.0), 1.0));
    double face[3], nl;
    cross3(e1, e2, face);
    const double facing = dot3(face, P[0]) < 0.0 ? 1.0 : -1.0; /* double-sided: towards the eye */
    for (int k = 0; k < 3; k++) {
        p[k] = (b[0] * P[0][k] + b[1] * P[1][k] + b[2] * P[2][k]) / sum;
        n[k] = facing * (b[0] * N[0][k] + b[1] * N[1][k] + b[2] * N[2][k]);
    }
    nl = sqrt(dot3(n, n));
    for (int k = 0; k < 3; k++) n[k] /= nl;
    return 1;
}

/* The tone curve and sRGB encoding of tonemap.frag.glsl, in double, times 255. */
static double ldr255(double c)
{
    c = fmax(c, 0.0);
    double a = fmin(fmax((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0), 1.0);
    return 255.0 * (a <= 0.0031308 ? a * 12.92 : 1.055 * pow(a, 1.0 / 2.4) - 0.055);
}

void modes_compare_reference(const tl_scene *s, const modes_frame *fat, const modes_frame *base, const modes_frame *m,
                             modes_ref_result *res)
{
    memset(res, 0, sizeof *res);
    const size_t w = fat->w, h = fat->h, nl = s->light_count;
    tl_ref_light *all = malloc((nl + 1) * sizeof *all), *here = malloc((nl + 1) * sizeof *here);
    if (!all || !here) {
        free(all);
        free(here);
        return;
    }
    lights_to_view(s, fat->view, all);
    const tl_ref_model model = fat->plan.lighting == TL_LIGHTING_GGX ? TL_REF_MODEL_GGX : TL_REF_MODEL_BLINN_PHONG;
    for (size_t i = 0; model == TL_REF_MODEL_GGX && i < nl; i++)
        all[i].source_radius = s->lights[i].type == TL_LIGHT_DIRECTIONAL ? 0.0 : s->lights[i].source_radius;
    tl_projection pr;
    memcpy(pr.m, m->proj, sizeof pr.m);
    pr.format = m->depth_format;
    double sum_sq_pred = 0.0, sum_var = 0.0, sum_sq = 0.0, sum_sq_hdr = 0.0, sum_var_hdr = 0.0;
    /* the modes that shade the unrounded interpolated normal and position: forward, visibility */
    const int interpolated = m->mode == TL_MODE_FORWARD || m->mode == TL_MODE_VISIBILITY;
    for (size_t y = 0; y < h; y++)
        for (size_t x = 0; x < w; x++) {
            size_t i = y * w + x;
            double pf[3], pm[3];
            if (!frame_position(fat, &pr, x, y, 0, pf) || !frame_position(m, &pr, x, y, 0, pm)) continue;
            /* the same surface in both frames: positions within 0.1 % (D24's error here is far below) */
            double dd = 0.0, pl = 0.0;
            for (int k = 0; k < 3; k++) dd += (pf[k] - pm[k]) * (pf[k] - pm[k]), pl += pf[k] * pf[k];
            if (dd > 1e-6 * pl) {
                res->silhouette++;
                continue;
            }
            tl_ref_surface surf = {.occlusion = 1.0};
            for (int k = 0; k < 3; k++) surf.albedo[k] = fat->albedo[4 * i + k], surf.specular[k] = fat->material[4 * i + k];
            double nf[3] = {fat->normal[4 * i], fat->normal[4 * i + 1], fat->normal[4 * i + 2]}, nm[3], tilt = 0.0;
            double nfl = sqrt(nf[0] * nf[0] + nf[1] * nf[1] + nf[2] * nf[2]);
            for (int k = 0; k < 3; k++) nf[k] /= nfl;
            surf.gloss = fat->normal[4 * i + 3];
            if (m->mode == TL_MODE_THIN_LPP || m->mode == TL_MODE_THIN_DEFERRED) {
                for (int k = 0; k < 3; k++) nm[k] = m->normal[4 * i + k];
                surf.gloss = m->normal[4 * i + 3];
            } else {
                memcpy(nm, nf, sizeof nm);
                tilt = interpolated ? FAT_NORMAL_ERROR : 0.0;
            }
            /* forward (and visibility, from its rebuilt barycentrics) shades the interpolated
             * position, which fat stores in full float; a thin mode
             * the position its light pass rebuilt from depth, whose texel fetch may round the D24
             * code's conversion to float the other way: the range spans one float step either way */
            const double *p = interpolated ? pf : pm;
            /* visibility at a pixel whose centre is outside its triangle (vis_surface_outside): the
             * resolve evaluates the triangle's attributes extrapolated there as the rasteriser does,
             * so the reference stays at fat's point; the range at the triangle's own (clamped) point
             * is kept for the figure the test prints, to show the pixels tell the two apart */
            double pc[3], nc[3], outside_px = 0.0, tri_lo[3], tri_hi[3];
            const int vis = m->vis_id ? vis_surface_outside(s, m, &pr, x, y, pc, nc, &outside_px) : 0;
            const int outside = vis == 1;
            res->vis_bad_ids += vis < 0;
            if (outside) {
                double cp[3];
                shade_range(model, &surf, pc, nc, tilt, here, lights_at(all, nl, pc, here), cp, tri_lo, tri_hi);
                res->vis_outside++;
                res->vis_outside_worst_px = fmax(res->vis_outside_worst_px, outside_px);
            }
            size_t count = lights_at(all, nl, p, here);
            double c[3], lo[3], hi[3];
            shade_range(model, &surf, p, nm, tilt, here, count, c, lo, hi);
            for (int step = -1; step <= 1 && !m->position && !interpolated; step += 2) {
                double q[3], c2[3], lo2[3], hi2[3];
                frame_position(m, &pr, x, y, step, q);
                shade_range(model, &surf, q, nm, tilt, here, count, c2, lo2, hi2);
                for (int k = 0; k < 3; k++) lo[k] = fmin(lo[k], lo2[k]), hi[k] = fmax(hi[k], hi2[k]);
            }
            for (int k = 0; k < 3; k++) {
                /* the frame without lights (ambient and emission) as fat's G-buffer pass stored it */
                double b = base->hdr[4 * i + k], want_lo = b + lo[k], want_hi = b + hi[k], got = m->hdr[4 * i + k];
                /* FP16: the stored albedo and F0 (2^-11 relative, fat's and what thin-lpp's material pass
                 * reads differ by that), the base term's store and the frame's stores: a light-buffer or
                 * light-sum store, the HDR store, each below one step; 4 steps in all, plus the smallest
                 * subnormal of each */
                double tol = 4.0 * TL_HALF_REL_STEP * fabs(want_hi) + 4.0 * 0x1.0p-24;
                double out = got < want_lo ? want_lo - got : got > want_hi ? got - want_hi : 0.0;
                double e = out / tol;
                if (e > res->worst) {
                    res->worst = e;
                    res->worst_x = (int)x;
                    res->worst_y = (int)y;
                    res->worst_got = got;
                    res->worst_lo = want_lo;
                    res->worst_hi = want_hi;
                }
                res->beyond += e > 1.0;
                res->compared++;
                if (outside) {
                    double tlo = b + tri_lo[k], thi = b + tri_hi[k], ttol = 4.0 * TL_HALF_REL_STEP * fabs(thi) + 4.0 * 0x1.0p-24;
                    double te = (got < tlo ? tlo - got : got > thi ? got - thi : 0.0) / ttol;
                    res->vis_outside_values++;
                    res->vis_outside_clamped_beyond += te > 1.0;
                    res->vis_outside_clamped_worst = fmax(res->vis_outside_clamped_worst, te);
                }
                /* the LDR difference this frame may have from fat's: the reference ranges and
                 * tolerances of both, through the tone curve; its 8-bit rounding makes a difference
                 * of k + f steps (0 <= f < 1) k + 1 steps with probability f: E[d^2] = k^2 + f (2k + 1) */
                double span_lo = fmin(want_lo - tol, fat->hdr[4 * i + k]), span_hi = fmax(want_hi + tol, fat->hdr[4 * i + k]);
                double delta = ldr255(span_hi) - ldr255(span_lo), kk = floor(delta), ff = delta - kk;
                double e2 = kk * kk + ff * (2.0 * kk + 1.0), e4 = (1.0 - ff) * pow(kk, 4) + ff * pow(kk + 1.0, 4);
                sum_sq_pred += e2;
                sum_var += e4 - e2 * e2;
                /* the tone map: the frame's 8-bit LDR value is its HDR value through the tone curve */
                res->tonemap_worst = fmax(res->tonemap_worst, fabs(255.0 * m->ldr[4 * i + k] - ldr255(m->hdr[4 * i + k])));
                double dl = 255.0 * ((double)m->ldr[4 * i + k] - fat->ldr[4 * i + k]);
                sum_sq += dl * dl;
                /* the same for the two stored HDR values themselves: what the LDR images must show */
                delta = fabs(ldr255(m->hdr[4 * i + k]) - ldr255(fat->hdr[4 * i + k]));
                kk = floor(delta), ff = delta - kk;
                e2 = kk * kk + ff * (2.0 * kk + 1.0), e4 = (1.0 - ff) * pow(kk, 4) + ff * pow(kk + 1.0, 4);
                sum_sq_hdr += e2;
                sum_var_hdr += e4 - e2 * e2;
            }
        }
    size_t n = res->compared;
    if (n) {
        /* the predicted mean square plus 4 standard deviations of a mean of n independent values */
        double mse = sum_sq_pred / (double)n + 4.0 * sqrt(sum_var) / (double)n;
        res->psnr_bound_db = mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : 999.0;
        res->psnr_db = sum_sq > 0.0 ? 10.0 * log10(255.0 * 255.0 / (sum_sq / (double)n)) : 999.0;
        mse = sum_sq_hdr / (double)n + 4.0 * sqrt(sum_var_hdr) / (double)n;
        res->psnr_hdr_bound_db = mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : 999.0;
    }
    free(all);
    free(here);
}
