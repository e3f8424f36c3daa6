/* The CPU reference of the lighting model (docs/renderer.md, shaders/lighting.glsl) at the
 * G-buffer's own samples, FP16 rounding, and the light-buffer comparison (stability.h). */
#include <math.h>
#include <stdio.h>

#include "stability.h"

/* NDC of a pixel centre, computed as the light pass computes it (float). */
void pixel_ndc(uint32_t x, uint32_t y, uint32_t w, uint32_t h, float ndc[2])
{
    ndc[0] = ((float)x + 0.5f) * (1.0f / (float)w) * 2.0f - 1.0f;
    ndc[1] = ((float)y + 0.5f) * (1.0f / (float)h) * 2.0f - 1.0f;
}

static void unit3(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++) v[k] /= l;
}

static void cross3(const double a[3], const double b[3], double o[3])
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

void camera_ray(const tl_camera *c, uint32_t w, uint32_t h, double x, double y, double dir[3])
{
    double f[3], r[3], u[3], up[3] = {c->up[0], c->up[1], c->up[2]};
    if (up[0] == 0.0 && up[1] == 0.0 && up[2] == 0.0) up[1] = 1.0;
    for (int k = 0; k < 3; k++) f[k] = (double)c->target[k] - (double)c->position[k];
    unit3(f);
    cross3(f, up, r);
    unit3(r);
    cross3(r, f, u);
    double ty = tan(0.5 * (double)c->fov_y), tx = ty * (double)w / (double)h;
    double nx = 2.0 * x / (double)w - 1.0, ny = 2.0 * y / (double)h - 1.0;
    for (int k = 0; k < 3; k++) dir[k] = f[k] + nx * tx * r[k] + ny * ty * u[k];
}

long scene_ray_object(const tl_scene *s, const double origin[3], const double dir[3], double *t_hit)
{
    long best = -1;
    double best_t = INFINITY;
    for (size_t o = 0; o < s->object_count; o++) {
        const tl_object *ob = &s->objects[o];
        for (uint32_t i = 0; i + 3 <= ob->index_count; i += 3) {
            const float *p[3];
            for (int k = 0; k < 3; k++) p[k] = s->vertices[s->indices[ob->first_index + i + k]].position;
            /* Moller-Trumbore, both faces */
            double e1[3], e2[3], q[3], pv[3], tv[3];
            for (int k = 0; k < 3; k++) {
                e1[k] = (double)p[1][k] - p[0][k];
                e2[k] = (double)p[2][k] - p[0][k];
                tv[k] = origin[k] - p[0][k];
            }
            cross3(dir, e2, pv);
            double det = e1[0] * pv[0] + e1[1] * pv[1] + e1[2] * pv[2];
            if (det == 0.0) continue;
            double a = (tv[0] * pv[0] + tv[1] * pv[1] + tv[2] * pv[2]) / det;
            cross3(tv, e1, q);
            double b = (dir[0] * q[0] + dir[1] * q[1] + dir[2] * q[2]) / det;
            double t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
            if (a < 0.0 || b < 0.0 || a + b > 1.0 || !(t > 0.0) || t >= best_t) continue;
            best_t = t;
            best = (long)o;
        }
    }
    if (t_hit) *t_hit = best_t;
    return best;
}

/* One step of a stored window depth as the light pass may see it: a float ULP of w, and at least
 * a D24 code for D24. */
static float depth_read_step(tl_depth_format f, float w)
{
    float ulp = nextafterf(w, INFINITY) - w;
    if (f == TL_DEPTH_FORMAT_D24 || f == TL_DEPTH_FORMAT_DEFAULT) ulp = fmaxf(ulp, 1.0f / (float)TL_UNORM_MAX(24));
    return ulp;
}

int gbuffer_sample(const frame *f, const tl_projection *pr, float clear_depth, uint32_t x, uint32_t y,
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
void model_terms(const tl_light *l, const double p[3], const double n[3], double gloss, double out[2],
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
void light_terms(const tl_light *l, const gsample *g, double out[2], double err[2])
{
    double lo[2], hi[2], e[2];
    model_terms(l, g->p, g->n, g->gloss, out, err);
    model_terms(l, g->p_lo, g->n, g->gloss, lo, e);
    model_terms(l, g->p_hi, g->n, g->gloss, hi, e);
    for (int s = 0; s < 2; s++) err[s] += fmax(fabs(lo[s] - out[s]), fabs(hi[s] - out[s]));
}

/* Float -> FP16 -> float, round to nearest even, overflow to Inf as a GPU conversion does. */
double half_rn(double v)
{
    if (fabs(v) >= 65520.0) return v > 0 ? INFINITY : -INFINITY;
    return tl_half_to_float(tl_half_from_float((float)v));
}

/* Float -> FP16 -> float, rounded toward zero (what llvmpipe's render-target conversion does). */
double half_rz(double v)
{
    float f = (float)v;
    if (fabsf(f) >= 65536.0f) return v > 0 ? INFINITY : -INFINITY;
    uint16_t h = tl_half_from_float(f);
    if (fabs((double)tl_half_to_float(h)) > fabs((double)f)) h = (uint16_t)(h - 1u); /* one step toward zero */
    return tl_half_to_float(h);
}

/* The spacing of FP16 values at |v| (one ULP: the most a faithful rounding, to nearest or toward
 * zero, can move a value), at least the smallest subnormal. */
double half_ulp(double v)
{
    double a = fabs(v);
    /* below 2^-14, FP16's smallest normal (exponent bias 15), the subnormals are 2^-14 / 2^10 apart */
    if (a < 0x1.0p-14) return ldexp(0x1.0p-14, -TL_HALF_MANTISSA_BITS);
    int e;
    frexp(a, &e); /* a in [2^(e-1), 2^e) */
    return ldexp(1.0, e - 1 - TL_HALF_MANTISSA_BITS);
}

/* Compares the light buffer (diffuse RGB, specular RGB) with the sum over `lights` evaluated at
 * the G-buffer's own samples. Tolerance: the shader's float error and the depth read step per
 * light (light_terms), plus one FP16 ULP of the running sum per light (each blend stores once;
 * the store's rounding is faithful, to nearest or toward zero). Background pixels are exactly 0. */
light_check check_light_buffer(const frame *f, const tl_projection *pr, float clear_depth,
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
