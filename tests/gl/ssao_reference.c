/* SSAO against a CPU evaluation of the same estimator (shaders/ssao.frag.glsl, docs/effects.md) in
 * double precision: the renderer's depth, RT0 (or fat's position and normal targets) are read back,
 * each pixel's view position and normal rebuilt as the shader rebuilds them (the C codec is the
 * GLSL codec's twin, bit for bit: tests/gl/parity_*), and the estimator run with the same sample
 * kernel (golden-angle spiral, per-pixel interleaved gradient noise, the hemisphere's frame). The
 * blur (ssao_blur.frag.glsl) is run on the read-back raw estimate, and the AO's effect on HDR is
 * checked against the frame without SSAO.
 *
 * The shader computes in float and picks pixels by rounding; the reference does not pretend to
 * reproduce float bits. Every quantity carries an error radius instead: positions from the depth
 * code and its neighbours' codes (2 float steps of window depth) plus 4 float roundings, normals
 * 4 roundings (12-bit RT0 and FP16 fat normals are read exactly), depth-rebuilt normals (forward)
 * the relative error of their tangents, the sample angle 4 float steps plus the shader's sin/cos.
 * A sample whose pixel, occlusion test or coincidence test is undecided within those radii counts
 * with both outcomes, so each pixel gets an interval [lo, hi] of AO; the stored R16F value must lie
 * in it, widened by one FP16 step (llvmpipe rounds toward zero: less than one step) and by the
 * float evaluation of the terms (FLOAT_SLACK). Most intervals have zero width; the test reports how
 * many do not, and how wide the widest is. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effects_scenes.h"
#include "render_fixture.h"
#include "thinlight/codec.h"
#include "thinlight/renderer.h"
#include "tl_test.h"

#define BIT(t) TL_TARGET_BIT(t)

/* The float evaluation of one pixel's estimate beyond its inputs' error radii: each term within 16
 * float ulps of its value (<= 1; the allowance test_lighting_glsl.c measures llvmpipe's pow and
 * transcendentals against), the running sum of up to 64 terms one rounding each. */
#define FLOAT_SLACK (16.0 * 0x1.0p-23 + 64.0 * 0x1.0p-24)

typedef struct iv {
    double lo, hi;
} iv;

static iv iv_union(iv a, iv b) { return (iv){fmin(a.lo, b.lo), fmax(a.hi, b.hi)}; }

enum { SRC_THIN, SRC_FAT, SRC_DEPTH_NORMALS };

/* One frame's read-back G-buffer, rebuilt as the shader sees it. */
typedef struct ssao_frame {
    uint32_t w, h;
    float m[16];  /* the projection the frame used (tl_view_info.projection) */
    float clear;  /* window depth of the background */
    int source;
    tl_ssao_desc s;
    int hemisphere;
    float *depth;                /* DEPTH: window depth, distance */
    float *rt0, *fpos, *fnormal; /* RT0 (thin), FAT_POSITION and FAT_NORMAL (fat) */
    /* per pixel: valid, position, its error radius */
    unsigned char *valid;
    double *p, *ep;
} ssao_frame;

static double ulpf(double v) { return (double)nextafterf((float)fabs(v), INFINITY) - fabs((float)fabs(v)); }

/* The view position of pixel (x, y) from window depth d as tl_gbuffer_position computes it. */
static void position_from_depth(const ssao_frame *f, const tl_projection *pr, int x, int y, float d, double out[3])
{
    float ndc_x = ((float)x + 0.5f) * (1.0f / (float)f->w) * 2.0f - 1.0f;
    float ndc_y = ((float)y + 0.5f) * (1.0f / (float)f->h) * 2.0f - 1.0f;
    float p[3];
    tl_view_position_from_depth(pr, ndc_x, ndc_y, d, p);
    for (int k = 0; k < 3; k++) out[k] = p[k];
}

static void frame_positions(ssao_frame *f)
{
    size_t n = (size_t)f->w * f->h;
    tl_projection pr;
    memcpy(pr.m, f->m, sizeof pr.m);
    pr.format = f->clear == 0.0f ? TL_DEPTH_FORMAT_D32F_REVERSED : TL_DEPTH_FORMAT_D24;
    for (size_t i = 0; i < n; i++) {
        int x = (int)(i % f->w), y = (int)(i / f->w);
        double *p = &f->p[3 * i];
        if (f->source == SRC_FAT) {
            f->valid[i] = f->fpos[4 * i + 3] > 0.5f;
            for (int k = 0; k < 3; k++) p[k] = f->fpos[4 * i + k];
            f->ep[i] = 2.0 * ulpf(fmax(fabs(p[0]), fmax(fabs(p[1]), fabs(p[2]))));
            continue;
        }
        float d = f->depth[4 * i];
        f->valid[i] = d != f->clear;
        if (!f->valid[i]) continue;
        position_from_depth(f, &pr, x, y, d, p);
        /* the texel fetch may round the D24 code's conversion to float the other way: one step */
        double e = 0.0;
        float dd[2] = {nextafterf(d, 2.0f), nextafterf(d, -1.0f)};
        for (int j = 0; j < 2; j++) {
            double q[3];
            position_from_depth(f, &pr, x, y, dd[j], q);
            e = fmax(e, sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2])));
        }
        f->ep[i] = e + 4.0 * ulpf(fmax(fabs(p[0]), fmax(fabs(p[1]), fabs(p[2]))));
    }
}

static int at(const ssao_frame *f, int x, int y, const double **p, double *ep)
{
    if (x < 0 || y < 0 || x >= (int)f->w || y >= (int)f->h) return 0;
    size_t i = (size_t)y * f->w + x;
    if (!f->valid[i]) return 0;
    *p = &f->p[3 * i];
    *ep = f->ep[i];
    return 1;
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static double len3(const double a[3]) { return sqrt(dot3(a, a)); }
static void cross3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* Candidate normals of a pixel (the shader's tl_fx_normal) with their angular error radius: one for
 * thin and fat; for depth-rebuilt normals, each undecided choice of tangent (tl_fx_tangent picks
 * the neighbour with the smaller depth step) adds the other. Returns the count (<= 4). */
typedef struct normal_set {
    double n[4][3];
    double en;
    int count;
} normal_set;

static void normalize_or_z(double n[3])
{
    double l = len3(n);
    if (l > 1e-10 && isfinite(l))
        for (int k = 0; k < 3; k++) n[k] /= l;
    else
        n[0] = n[1] = 0.0, n[2] = 1.0;
}

/* The tangents along one axis: 1 or 2 candidates, with the error radius of each. */
static int tangents(const ssao_frame *f, int x, int y, int sx, int sy, double t[2][3], double *et)
{
    const double *p = NULL, *a = NULL, *b = NULL;
    double ep = 0, ea = 0, eb = 0;
    at(f, x, y, &p, &ep);
    int ha = at(f, x + sx, y + sy, &a, &ea), hb = at(f, x - sx, y - sy, &b, &eb);
    double da[3] = {0, 0, 0}, db[3] = {0, 0, 0};
    for (int k = 0; ha && k < 3; k++) da[k] = a[k] - p[k];
    for (int k = 0; hb && k < 3; k++) db[k] = p[k] - b[k];
    *et = ep + fmax(ha ? ea : 0.0, hb ? eb : 0.0);
    if (ha && hb) {
        double m = fabs(da[2]) - fabs(db[2]), e = ea + eb + 2.0 * ep;
        if (m <= -e) return memcpy(t[0], da, sizeof da), 1;
        if (m > e) return memcpy(t[0], db, sizeof db), 1;
        memcpy(t[0], da, sizeof da);
        memcpy(t[1], db, sizeof db);
        return 2;
    }
    memcpy(t[0], ha ? da : db, sizeof da);
    return 1;
}

static void pixel_normals(const ssao_frame *f, int x, int y, normal_set *ns)
{
    size_t i = (size_t)y * f->w + x;
    ns->count = 1;
    ns->en = 4.0 * FLT_EPSILON;
    if (f->source != SRC_DEPTH_NORMALS) {
        const float *src = f->source == SRC_FAT ? &f->fnormal[4 * i] : &f->rt0[4 * i];
        for (int k = 0; k < 3; k++) ns->n[0][k] = src[k];
        normalize_or_z(ns->n[0]);
        return;
    }
    double tx[2][3], ty[2][3], ex, ey;
    int cx = tangents(f, x, y, 1, 0, tx, &ex), cy = tangents(f, x, y, 0, 1, ty, &ey);
    const double *p = &f->p[3 * i];
    ns->count = 0;
    ns->en = 0.0;
    for (int a = 0; a < cx; a++)
        for (int b = 0; b < cy; b++) {
            double *n = ns->n[ns->count++], la = len3(tx[a]), lb = len3(ty[b]);
            cross3(tx[a], ty[b], n);
            double sin_ab = la > 0 && lb > 0 ? len3(n) / (la * lb) : 0.0;
            if (dot3(n, p) > 0.0)
                for (int k = 0; k < 3; k++) n[k] = -n[k];
            normalize_or_z(n);
            /* the cross product's direction moves by the tangents' relative errors over the sine of
             * their angle */
            double e = sin_ab > 0.05 ? (ex / la + ey / lb) / sin_ab : 1.0;
            ns->en = fmax(ns->en, e + 4.0 * FLT_EPSILON);
        }
}

static double smoothstep01(double e1, double t)
{
    double s = fmin(fmax(t / e1, 0.0), 1.0);
    return s * s * (3.0 - 2.0 * s);
}

/* tl_ssao_term for a neighbour q (error radii ep, eq) of p and an interval of b. */
static iv term_iv(const ssao_frame *f, const double p[3], double ep, const double q[3], double eq, iv b)
{
    double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, l = len3(d), el = ep + eq;
    double coincide = 1e-6 * fmax(1.0, fabs(p[2]));
    if (l + el <= coincide) return (iv){1.0, 1.0};
    double a_hi = 1.0 - smoothstep01(f->s.falloff, fmax(l - el, 0.0) - f->s.bias);
    double a_lo = 1.0 - smoothstep01(f->s.falloff, (l + el) - f->s.bias);
    double x = f->s.exponent;
    iv t = {pow(fmax(1.0 - a_hi * b.hi, 0.0), x), pow(fmax(1.0 - a_lo * b.lo, 0.0), x)};
    if (l - el <= coincide) t.hi = 1.0;
    return t;
}

/* The integers round() may give for v within e of it: 1 or 2. */
static int round_candidates(double v, double e, int out[2])
{
    out[0] = (int)floor(v - e + 0.5);
    out[1] = (int)floor(v + e + 0.5);
    return out[1] != out[0] ? 2 : 1;
}

static int floor_candidates(double v, double e, int out[2])
{
    out[0] = (int)floor(v - e);
    out[1] = (int)floor(v + e);
    return out[1] != out[0] ? 2 : 1;
}

/* tl_fx_noise at pixel (x, y) in float, as the shader may evaluate the dot product (two roundings
 * or one fused multiply-add either way round): the distinct results in out, their count returned. */
static int noise_turns(int x, int y, float out[3])
{
    const float fx = (float)x + 0.5f, fy = (float)y + 0.5f, c1 = 0.06711056f, c2 = 0.00583715f;
    volatile float px = fx * c1, py = fy * c2; /* no contraction here */
    float dots[3] = {px + py, fmaf(fx, c1, py), fmaf(fy, c2, px)};
    int n = 0;
    for (int k = 0; k < 3; k++) {
        float fr = dots[k] - floorf(dots[k]);
        volatile float t = 52.9829189f * fr;
        float noise = t - floorf(t), turn = 6.2831853f * noise;
        int seen = 0;
        for (int j = 0; j < n; j++) seen |= out[j] == turn;
        if (!seen) out[n++] = turn;
    }
    return n;
}

/* One sample of the disc estimator, every candidate pixel. */
static iv disc_sample(const ssao_frame *f, int x, int y, const double p[3], double ep, const double n[3], double en,
                      int i, float turn)
{
    const int ns = (int)f->s.samples;
    float ff = ((float)i + 0.5f) / (float)ns, a = (float)i * 2.39996323f + turn;
    double height = (double)(1.0f / (1.0f / (float)f->h));
    double rpx = fmin(f->s.radius * f->m[5] * 0.5 * height / fmax(-p[2], 1e-30), height);
    double erpx = rpx < height ? rpx * (ep / fabs(p[2]) + 4.0 * FLT_EPSILON) : 0.0;
    double ea = 4.0 * ulpf(a) + 2e-6; /* the sum in float, sin and cos */
    double r = sqrt((double)ff) * rpx, v[2] = {cos((double)a) * r, sin((double)a) * r};
    double e = r * ea + sqrt((double)ff) * erpx + 1e-9;
    int cx[2], cy[2], nx = round_candidates(v[0], e, cx), ny = round_candidates(v[1], e, cy);
    iv out = {INFINITY, -INFINITY};
    for (int a1 = 0; a1 < nx; a1++)
        for (int b1 = 0; b1 < ny; b1++) {
            const double *q;
            double eq;
            iv t = {1.0, 1.0};
            if ((cx[a1] || cy[b1]) && at(f, x + cx[a1], y + cy[b1], &q, &eq)) {
                double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, l = len3(d);
                double bc = l > 0.0 ? dot3(n, d) / l : 0.0, eb = l > 0.0 ? en + 2.0 * (ep + eq) / l : 1.0;
                iv b = {fmax(bc - eb, 0.0), fmin(fmax(bc + eb, 0.0), 1.0)};
                t = term_iv(f, p, ep, q, eq, b);
            }
            out = iv_union(out, t);
        }
    return out;
}

/* The hemisphere sample point of sample i (view space). */
static void hemi_point(const ssao_frame *f, const double p[3], const double n[3], double a, double ff, double s[3])
{
    double t[3], bt[3], axis[3] = {0, 0, 0};
    axis[fabs(n[2]) < 0.9 ? 2 : 0] = 1.0;
    cross3(n, axis, t);
    normalize_or_z(t);
    cross3(n, t, bt);
    double xy[2] = {cos(a) * sqrt(ff) * 0.95, sin(a) * sqrt(ff) * 0.95};
    double up = sqrt(1.0 - (xy[0] * xy[0] + xy[1] * xy[1])), len = f->s.radius * (0.1 + 0.9 * ff * ff);
    for (int k = 0; k < 3; k++) s[k] = p[k] + (t[k] * xy[0] + bt[k] * xy[1] + n[k] * up) * len;
}

static iv hemi_sample(const ssao_frame *f, const double p[3], double ep, const double n[3], double en, int i,
                      float turn)
{
    const int ns = (int)f->s.samples;
    float ff = ((float)i + 0.5f) / (float)ns, a = (float)i * 2.39996323f + turn;
    double ea = 4.0 * ulpf(a) + 2e-6, s[3];
    hemi_point(f, p, n, a, ff, s);
    /* the sample point moves with p, with the frame (n) and with the angle */
    double es = ep + f->s.radius * (2.0 * en + ea) + 4.0 * ulpf(len3(s));
    const float *m = f->m;
    double cw = m[3] * s[0] + m[7] * s[1] + m[11] * s[2] + m[15];
    if (!(cw > es)) return (iv){1.0, 1.0}; /* behind the eye (never in these scenes) */
    double cx = m[0] * s[0] + m[4] * s[1] + m[8] * s[2] + m[12], cy = m[1] * s[0] + m[5] * s[1] + m[9] * s[2] + m[13];
    double u = (cx / cw * 0.5 + 0.5) * f->w, v = (cy / cw * 0.5 + 0.5) * f->h;
    /* pixels per view unit at that depth, times the point's error, plus the projection in float */
    double eu = 0.5 * f->w * (fabs(m[0]) + fabs(m[8]) + fabs(cx / cw)) / cw * es * 2.0 + 1e-4;
    double ev = 0.5 * f->h * (fabs(m[5]) + fabs(m[9]) + fabs(cy / cw)) / cw * es * 2.0 + 1e-4;
    int qx[2], qy[2], nx = floor_candidates(u, eu, qx), ny = floor_candidates(v, ev, qy);
    iv out = {INFINITY, -INFINITY};
    for (int a1 = 0; a1 < nx; a1++)
        for (int b1 = 0; b1 < ny; b1++) {
            const double *q;
            double eq;
            iv t = {1.0, 1.0};
            if (at(f, qx[a1], qy[b1], &q, &eq)) {
                double d[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, l = len3(d);
                double m1 = q[2] - (s[2] + f->s.bias), e1 = eq + es;
                double m2 = dot3(n, d) - 0.087 * l, e2 = l * en + (ep + eq) * 1.087 + 1e-7 * l;
                int can_true = m1 >= -e1 && m2 > -e2, can_false = m1 < e1 || m2 <= e2;
                iv b = {can_false ? 0.0 : 1.0, can_true ? 1.0 : 0.0};
                t = term_iv(f, p, ep, q, eq, b);
            }
            out = iv_union(out, t);
        }
    return out;
}

/* The AO interval of pixel (x, y): over its candidate normals and noise values, each sample's
 * candidates summed. */
static iv pixel_ao(const ssao_frame *f, int x, int y)
{
    const double *p;
    double ep;
    if (!at(f, x, y, &p, &ep)) return (iv){1.0, 1.0};
    normal_set ns;
    pixel_normals(f, x, y, &ns);
    float turns[3];
    int nt = noise_turns(x, y, turns);
    iv out = {INFINITY, -INFINITY};
    for (int c = 0; c < ns.count; c++)
        for (int t = 0; t < nt; t++) {
            double lo = 0.0, hi = 0.0;
            for (int i = 0; i < (int)f->s.samples; i++) {
                iv s = f->hemisphere ? hemi_sample(f, p, ep, ns.n[c], ns.en, i, turns[t])
                                     : disc_sample(f, x, y, p, ep, ns.n[c], ns.en, i, turns[t]);
                lo += s.lo;
                hi += s.hi;
            }
            out = iv_union(out, (iv){lo / f->s.samples, hi / f->s.samples});
        }
    return (iv){fmin(fmax(out.lo, 0.0), 1.0), fmin(fmax(out.hi, 0.0), 1.0)};
}

/* ---- rendering ------------------------------------------------------------------------------------- */

static void capture_view(void *user, const tl_app_pass_context *ctx)
{
    memcpy(user, ctx->view->projection, 16 * sizeof(float));
}

/* Renders `s` with `d` (every target kept) and captures the frame's projection; NULL on failure. */
static tl_renderer *render_captured(const tl_scene *s, tl_renderer_desc d, float proj[16])
{
    d.options.keep_targets = TL_TARGETS_ALL;
    tl_app_pass_desc ap = {.name = "capture-view", .before = "tonemap", .writes = BIT(TL_TARGET_HDR),
                           .execute = capture_view, .user = proj};
    return tl_test_renderer(&(tl_test_renderer_desc){.renderer = d, .scene = s, .passes = &ap, .pass_count = 1, .frames = 1});
}

typedef struct ssao_result {
    double worst_raw, worst_blur, worst_hdr; /* largest miss, in units of the slack allowed */
    double widest, mean_width, p99_width;    /* of the reference intervals */
    double darkest;                          /* lowest reference AO */
    size_t occluded;                         /* pixels the reference darkens by more than 0.05 */
} ssao_result;

/* How far the stored R16F value v lies outside the interval [lo, hi], over the slack it is allowed:
 * less than one FP16 step (llvmpipe rounds toward zero) of the larger bound, FLOAT_SLACK and the
 * smallest subnormal; <= 1 passes. */
static double excess(double v, iv r)
{
    double out = fmax(0.0, fmax(r.lo - v, v - r.hi));
    return out / (r.hi * TL_HALF_REL_STEP + FLOAT_SLACK + 0x1.0p-24);
}

/* ssao_blur.frag.glsl on the read-back raw estimate: the depth-aware box of radius b. */
static double cpu_blur(const ssao_frame *f, const float *raw, int x, int y)
{
    const int b = (int)f->s.blur_radius;
    double zc = f->depth[4 * ((size_t)y * f->w + x) + 1];
    if (f->depth[4 * ((size_t)y * f->w + x)] == f->clear) return 1.0;
    double sum = 0.0, wsum = 0.0;
    for (int j = -b; j <= b; j++)
        for (int i = -b; i <= b; i++) {
            int u = x + i < 0 ? 0 : x + i >= (int)f->w ? (int)f->w - 1 : x + i;
            int v = y + j < 0 ? 0 : y + j >= (int)f->h ? (int)f->h - 1 : y + j;
            size_t k = (size_t)v * f->w + u;
            if (f->depth[4 * k] == f->clear) continue; /* weight 0: infinitely far */
            double w = fmax(0.0, 1.0 - fabs(f->depth[4 * k + 1] - zc) / (0.05 * fabs(zc)));
            sum += w * raw[4 * k];
            wsum += w;
        }
    return wsum > 0.0 ? fmin(fmax(sum / wsum, 0.0), 1.0) : 1.0;
}

/* The linear albedo thin-deferred's RT1 gives back for a uniform albedo (tl_rt1_read: sRGB, 8-bit
 * BT.601 Y and both chroma, the missing one rebuilt from neighbours that hold the same). */
static void grey_through_rt1(const float albedo[3], double out[3])
{
    float srgb[3], ycc[3], rgb[3];
    uint8_t even[2], odd[2];
    for (int c = 0; c < 3; c++) srgb[c] = tl_linear_to_srgb(albedo[c]);
    tl_albedo_encode_pixel(TL_COLOR_SPACE_YCBCR, srgb, 0, 0, even);
    tl_albedo_encode_pixel(TL_COLOR_SPACE_YCBCR, srgb, 1, 0, odd);
    ycc[0] = even[0] / 255.0f;
    ycc[1] = even[1] / 255.0f;
    ycc[2] = odd[1] / 255.0f;
    tl_luma_chroma_to_rgb(TL_COLOR_SPACE_YCBCR, ycc, rgb);
    for (int c = 0; c < 3; c++) out[c] = tl_srgb_to_linear(rgb[c]);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The targets of a frame with SSAO (r) and of the same frame without (r0). */
typedef struct ssao_images {
    float *raw, *ao, *hdr, *hdr0;
} ssao_images;

static int read_frame(tl_renderer *r, tl_renderer *r0, const tl_renderer_desc *d, ssao_frame *f, ssao_images *im)
{
    const size_t n = (size_t)d->width * d->height;
    f->w = d->width;
    f->h = d->height;
    f->s = d->options.ssao;
    f->hemisphere = d->options.ssao.method == TL_SSAO_HEMISPHERE;
    f->clear = d->options.depth_format == TL_DEPTH_FORMAT_D32F_REVERSED ? 0.0f : 1.0f;
    tl_render_mode mode = d->options.mode;
    /* thin modes and visibility (RT0 written for SSAO) store RT0; forward rebuilds normals from depth */
    f->source = mode == TL_MODE_FAT ? SRC_FAT : mode == TL_MODE_FORWARD ? SRC_DEPTH_NORMALS : SRC_THIN;
    f->depth = tl_test_read_target(r, TL_TARGET_DEPTH, n);
    if (f->source == SRC_THIN) f->rt0 = tl_test_read_target(r, TL_TARGET_RT0, n);
    if (f->source == SRC_FAT) {
        f->fpos = tl_test_read_target(r, TL_TARGET_FAT_POSITION, n);
        f->fnormal = tl_test_read_target(r, TL_TARGET_FAT_NORMAL, n);
    }
    im->raw = tl_test_read_target(r, TL_TARGET_AO_RAW, n);
    im->ao = tl_test_read_target(r, TL_TARGET_AO, n);
    im->hdr = tl_test_read_target(r, TL_TARGET_HDR, n);
    im->hdr0 = tl_test_read_target(r0, TL_TARGET_HDR, n);
    f->valid = calloc(n, 1);
    f->p = calloc(n * 3, sizeof *f->p);
    f->ep = calloc(n, sizeof *f->ep);
    return f->depth && im->raw && im->ao && im->hdr && im->hdr0 && f->valid && f->p && f->ep &&
           (f->source != SRC_THIN || f->rt0) && (f->source != SRC_FAT || (f->fpos && f->fnormal));
}

static void free_frame(ssao_frame *f, ssao_images *im)
{
    void *p[] = {f->depth, f->rt0, f->fpos, f->fnormal, f->valid, f->p, f->ep, im->raw, im->ao, im->hdr, im->hdr0};
    for (size_t i = 0; i < sizeof p / sizeof p[0]; i++) free(p[i]);
}

/* Every pixel: the raw estimate against the reference interval, the blurred value against the
 * blur of the stored estimate, HDR against the frame without SSAO less (1 - AO) albedo ambient
 * (no lights, ambient 1; two FP16 roundings; thin-deferred's ssao-apply takes RT1's albedo). */
static void compare_pixels(const ssao_frame *f, const ssao_images *im, const double albedo[3], ssao_result *res)
{
    const size_t n = (size_t)f->w * f->h;
    double *widths = malloc(n * sizeof *widths);
    for (int y = 0; y < (int)f->h; y++)
        for (int x = 0; x < (int)f->w; x++) {
            size_t i = (size_t)y * f->w + x;
            iv want = pixel_ao(f, x, y);
            double e = excess(im->raw[4 * i], want);
            if (e > 1.0 && res->worst_raw <= 1.0)
                printf("    raw AO at (%d, %d): %.6f, reference [%.6f, %.6f]\n", x, y, (double)im->raw[4 * i], want.lo,
                       want.hi);
            res->worst_raw = fmax(res->worst_raw, e);
            res->widest = fmax(res->widest, want.hi - want.lo);
            res->mean_width += (want.hi - want.lo) / (double)n;
            if (widths) widths[i] = want.hi - want.lo;
            res->darkest = fmin(res->darkest, want.lo);
            res->occluded += want.hi < 0.95;
            double b = cpu_blur(f, im->raw, x, y);
            res->worst_blur = fmax(res->worst_blur, excess(im->ao[4 * i], (iv){b, b}));
            for (int c = 0; c < 3; c++) {
                double h0 = im->hdr0[4 * i + c], occluded = 1.0 - im->ao[4 * i];
                double want_h = h0 - occluded * (albedo ? albedo[c] : h0);
                double tol = 2.0 * TL_HALF_REL_STEP * fabs(h0) + 0x1.0p-24;
                res->worst_hdr = fmax(res->worst_hdr, fabs(im->hdr[4 * i + c] - want_h) / tol);
            }
        }
    if (widths) {
        qsort(widths, n, sizeof *widths, cmp_double);
        res->p99_width = widths[n * 99 / 100];
    }
    free(widths);
}

static void check_frame(const quads *q, tl_renderer_desc d, ssao_result *res)
{
    memset(res, 0, sizeof *res);
    res->darkest = 1.0;
    ssao_frame f;
    ssao_images im;
    memset(&f, 0, sizeof f);
    memset(&im, 0, sizeof im);
    tl_renderer *r = render_captured(&q->s, d, f.m);
    tl_renderer_desc off = d;
    off.options.ssao = (tl_ssao_desc){0};
    tl_renderer *r0 = tl_test_render_once(&q->s, off);
    TL_CHECK(r && r0);
    if (r && r0) {
        int ok = read_frame(r, r0, &d, &f, &im);
        TL_CHECK(ok);
        double rt1_albedo[3];
        grey_through_rt1(q->mat[0].albedo, rt1_albedo);
        if (ok) {
            frame_positions(&f);
            compare_pixels(&f, &im, d.options.mode == TL_MODE_THIN_DEFERRED ? rt1_albedo : NULL, res);
        }
    }
    free_frame(&f, &im);
    tl_renderer_destroy(r);
    tl_renderer_destroy(r0);
}

#define W 160
#define H 90

/* The inner corner (floor and wall, the ambient term only) in every mode, both estimators, D24 and
 * reversed D32F, two parameter sets (the radius and falloff of ssao_inner_corner_darkens_bounded;
 * a larger radius with a bias and exponent 2): every raw estimate within its reference interval,
 * every blurred value the blur of the stored estimate, every HDR value the frame without SSAO less
 * the occluded ambient; and the corner is darkened (the reference is not trivially 1). */
TL_TEST(ssao_matches_cpu_estimator_every_mode)
{
    quads q;
    corner_scene(&q);
    /* visibility: its G-buffer pass writes RT0 for the estimator, vis-resolve takes the AO as forward does */
    static const tl_render_mode modes[] = {TL_MODE_THIN_LPP, TL_MODE_THIN_DEFERRED, TL_MODE_FAT, TL_MODE_FORWARD,
                                           TL_MODE_VISIBILITY};
    const tl_ssao_desc params[2] = {
        {.samples = 16, .radius = 0.5f, .bias = 0.0f, .falloff = 0.5f, .exponent = 3.0f, .blur_radius = 2},
        {.samples = 12, .radius = 1.0f, .bias = 0.05f, .falloff = 1.5f, .exponent = 2.0f, .blur_radius = 1},
    };
    for (int method = TL_SSAO_DISC; method <= TL_SSAO_HEMISPHERE; method++)
        for (size_t m = 0; m < sizeof modes / sizeof modes[0]; m++)
            for (int z = 0; z < 2; z++)
                for (int ps = 0; ps < 2; ps++) {
                    if (ps == 1 && z == 1) continue; /* the second set once per mode and method */
                    tl_renderer_desc d = {.width = W, .height = H, .options.mode = modes[m]};
                    d.options.depth_format = z ? TL_DEPTH_FORMAT_D32F_REVERSED : TL_DEPTH_FORMAT_D24;
                    d.options.ssao = params[ps];
                    d.options.ssao.enabled = 1, d.options.ssao.method = (tl_ssao_method)method;
                    ssao_result res;
                    check_frame(&q, d, &res);
                    printf("  %-10s %-13s %-13s set %d: raw %.3f, blur %.3f, HDR %.3f of the slack; reference "
                           "intervals %.2g wide on average, p99 %.2g, widest %.3f; %zu pixels occluded, darkest %.4f\n",
                           method == TL_SSAO_DISC ? "disc" : "hemisphere", tl_render_mode_name(modes[m]),
                           z ? "d32f-reversed" : "d24", ps, res.worst_raw, res.worst_blur, res.worst_hdr,
                           res.mean_width, res.p99_width, res.widest, res.occluded, res.darkest);
                    TL_CHECK_LE(res.worst_raw, 1.0);
                    TL_CHECK_LE(res.worst_blur, 1.0);
                    TL_CHECK_LE(res.worst_hdr, 1.0);
                    TL_CHECK(res.occluded > 100 && res.darkest < 0.9);
                }
}
