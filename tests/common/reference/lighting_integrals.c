/* Numerical integrals of the GGX model; see lighting_integrals.h. */
#include "lighting_integrals.h"

#include <math.h>

#include "lighting_ref.h"

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Two unit vectors completing w (unit) to an orthonormal basis. */
static void basis(const double w[3], double t[3], double b[3])
{
    double a[3] = {0.0, 0.0, 0.0};
    a[fabs(w[0]) < 0.6 ? 0 : fabs(w[1]) < 0.6 ? 1 : 2] = 1.0;
    double d = dot3(a, w), len = 0.0;
    for (int i = 0; i < 3; i++) t[i] = a[i] - d * w[i], len += t[i] * t[i];
    len = sqrt(len);
    for (int i = 0; i < 3; i++) t[i] /= len;
    b[0] = w[1] * t[2] - w[2] * t[1];
    b[1] = w[2] * t[0] - w[0] * t[2];
    b[2] = w[0] * t[1] - w[1] * t[0];
}

/* The direction with polar angle (cos_t, sin_t) and azimuth phi around w. */
static void around(const double w[3], const double t[3], const double b[3], double cos_t, double sin_t, double phi,
                   double out[3])
{
    double c = cos(phi) * sin_t, s = sin(phi) * sin_t;
    for (int i = 0; i < 3; i++) out[i] = w[i] * cos_t + t[i] * c + b[i] * s;
}

/* GGX sample of the half vector around n from (u1, u2) in [0,1)^2: density D(n.h) n.h. */
static void ggx_half(const double n[3], const double t[3], const double b[3], double alpha, double u1, double u2,
                     double h[3])
{
    double a2 = alpha * alpha, c2 = (1.0 - u1) / (1.0 + (a2 - 1.0) * u1);
    around(n, t, b, sqrt(c2), sqrt(fmax(1.0 - c2, 0.0)), 2.0 * TL_REF_PI * u2, h);
}

/* ---- directional albedo -------------------------------------------------------------------------- */

static double g1_of(tl_ref_g1 g, double x, double alpha)
{
    if (g == TL_REF_G1_SMITH) return 2.0 * x / (x + sqrt(alpha * alpha + (1.0 - alpha * alpha) * x * x));
    double r = sqrt(alpha), k = g == TL_REF_G1_SCHLICK_UE4 ? (r + 1.0) * (r + 1.0) / 8.0 : 0.5 * alpha;
    return x / (x * (1.0 - k) + k);
}

/* G1(x) / x, finite at x = 0 */
static double g1_over_x(tl_ref_g1 g, double x, double alpha)
{
    if (g == TL_REF_G1_SMITH) return 2.0 / (x + sqrt(alpha * alpha + (1.0 - alpha * alpha) * x * x));
    double r = sqrt(alpha), k = g == TL_REF_G1_SCHLICK_UE4 ? (r + 1.0) * (r + 1.0) / 8.0 : 0.5 * alpha;
    return 1.0 / (x * (1.0 - k) + k);
}

static double albedo_grid(double alpha, double nv, tl_ref_g1 g, uint32_t side)
{
    const double n[3] = {0.0, 0.0, 1.0}, t[3] = {1.0, 0.0, 0.0}, b[3] = {0.0, 1.0, 0.0};
    double v[3] = {sqrt(fmax(1.0 - nv * nv, 0.0)), 0.0, nv};
    double sum = 0.0, gv = g1_over_x(g, nv, alpha);
    for (uint32_t i = 0; i < side; i++)
        for (uint32_t j = 0; j < side; j++) {
            double h[3], l[3];
            ggx_half(n, t, b, alpha, (i + 0.5) / side, (j + 0.5) / side, h);
            double vh = dot3(v, h);
            if (vh <= 0.0) continue;
            for (int k = 0; k < 3; k++) l[k] = 2.0 * vh * h[k] - v[k];
            double nl = l[2];
            if (nl <= 0.0) continue;
            /* D G / (4 nl nv) nl over the density D nh / (4 vh) */
            sum += g1_of(g, nl, alpha) * gv * vh / h[2];
        }
    return sum / ((double)side * side);
}

tl_ref_estimate tl_ref_ggx_albedo(double alpha, double nv, tl_ref_g1 g1, uint32_t side)
{
    double full = albedo_grid(alpha, nv, g1, side), half = albedo_grid(alpha, nv, g1, side / 2);
    return (tl_ref_estimate){full, fabs(full - half)};
}

double tl_ref_ggx_d_integral(double alpha, uint32_t steps)
{
    /* 2 pi int_0^1 D(mu) mu dmu with s = 1 - mu^2: pi int_0^1 D(sqrt(1 - s)) ds, in log s */
    const double lo = log(1e-14);
    double sum = 0.0, dt = -lo / steps;
    for (uint32_t i = 0; i < steps; i++) {
        double s = exp(lo + (i + 0.5) * dt);
        sum += tl_ref_ggx_d(sqrt(1.0 - s), alpha) * s * dt;
    }
    return TL_REF_PI * (sum + tl_ref_ggx_d(1.0, alpha) * 1e-14);
}

/* ---- sphere light by Monte Carlo ----------------------------------------------------------------- */

typedef struct rng {
    uint64_t s;
} rng;

static double rng_unit(rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return (double)((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

/* The light's cone: unit axis, 1 - cos(half-angle), solid angle. */
typedef struct cone {
    double w[3], t[3], b[3], omc, omega;
} cone;

static cone make_cone(const double centre[3], double radius)
{
    cone c;
    double d = sqrt(dot3(centre, centre)), s2 = radius * radius / (d * d);
    for (int i = 0; i < 3; i++) c.w[i] = centre[i] / d;
    basis(c.w, c.t, c.b);
    c.omc = s2 / (1.0 + sqrt(1.0 - s2));
    c.omega = 2.0 * TL_REF_PI * c.omc;
    return c;
}

static void cone_sample(const cone *c, double u1, double u2, double out[3])
{
    double a = u1 * c->omc;
    around(c->w, c->t, c->b, 1.0 - a, sqrt(a * (2.0 - a)), 2.0 * TL_REF_PI * u2, out);
}

static tl_ref_estimate mean_of(double sum, double sum2, double n, double scale)
{
    double mean = sum / n, var = fmax(sum2 / n - mean * mean, 0.0);
    return (tl_ref_estimate){scale * mean, scale * sqrt(var / n)};
}

tl_ref_estimate tl_ref_sphere_diffuse_mc(const double n[3], const double centre[3], double radius, uint32_t side,
                                         uint64_t seed)
{
    cone c = make_cone(centre, radius);
    rng r = {seed};
    double sum = 0.0, sum2 = 0.0;
    for (uint32_t i = 0; i < side; i++)
        for (uint32_t j = 0; j < side; j++) {
            double w[3];
            cone_sample(&c, (i + rng_unit(&r)) / side, (j + rng_unit(&r)) / side, w);
            double f = fmax(dot3(n, w), 0.0);
            sum += f;
            sum2 += f * f;
        }
    return mean_of(sum, sum2, (double)side * side, c.omega / (TL_REF_PI * radius * radius));
}

/* Density of the GGX strategy for the direction w: D(h) n.h / (4 v.h), h = (w + v) / |w + v|. */
static double ggx_density(const double n[3], const double v[3], const double w[3], double alpha)
{
    double h[3] = {w[0] + v[0], w[1] + v[1], w[2] + v[2]}, len = sqrt(dot3(h, h));
    if (!(len > 1e-12)) return 0.0;
    for (int i = 0; i < 3; i++) h[i] /= len;
    double nh = dot3(n, h), vh = dot3(v, h);
    return vh > 0.0 ? tl_ref_ggx_d(nh, alpha) * nh / (4.0 * vh) : 0.0;
}

/* pi D Vis (n.w)+ / (pi r^2) of one direction */
static double specular_of(const double n[3], const double v[3], const double w[3], double alpha, double r2)
{
    double vh;
    return tl_ref_ggx_dv(n, v, w, alpha, &vh) * fmax(dot3(n, w), 0.0) / r2;
}

tl_ref_estimate tl_ref_sphere_specular_mc(const double n[3], const double v[3], const double centre[3], double radius,
                                          double alpha, uint32_t side, uint64_t seed)
{
    cone c = make_cone(centre, radius);
    double t[3], b[3], r2 = radius * radius, pc = 1.0 / c.omega, cos_max = 1.0 - c.omc;
    basis(n, t, b);
    rng r = {seed};
    double sum = 0.0, sum2 = 0.0;
    for (uint32_t i = 0; i < side; i++)
        for (uint32_t j = 0; j < side; j++) {
            double x[3], h[3], y[3];
            cone_sample(&c, (i + rng_unit(&r)) / side, (j + rng_unit(&r)) / side, x);
            double e = specular_of(n, v, x, alpha, r2) / (pc + ggx_density(n, v, x, alpha));
            ggx_half(n, t, b, alpha, (i + rng_unit(&r)) / side, (j + rng_unit(&r)) / side, h);
            double vh = dot3(v, h);
            for (int k = 0; k < 3; k++) y[k] = 2.0 * vh * h[k] - v[k];
            if (vh > 0.0 && dot3(y, c.w) >= cos_max)
                e += specular_of(n, v, y, alpha, r2) / (pc + ggx_density(n, v, y, alpha));
            sum += e;
            sum2 += e * e;
        }
    return mean_of(sum, sum2, (double)side * side, 1.0);
}

/* ---- highlight energy of the representative point ------------------------------------------------ */

static double rp_energy(const double n[3], const double v[3], double d, double radius, double alpha, uint32_t steps)
{
    double m[3], t[3], b[3], vn = dot3(v, n);
    for (int i = 0; i < 3; i++) m[i] = 2.0 * vn * n[i] - v[i];
    basis(m, t, b);
    /* range 50 d: the window is 1 - 3e-7 over the sphere of centres, and 0.01 range < d */
    tl_ref_light light = {.type = TL_REF_LIGHT_POINT, .range = 50.0 * d, .source_radius = radius};
    const double p[3] = {0.0, 0.0, 0.0};
    uint32_t nphi = 4 * steps;
    double sum = 0.0;
    for (uint32_t i = 0; i < steps; i++) {
        /* theta = pi u^3: dense near the mirror direction, where the highlight is */
        double u = (i + 0.5) / steps, theta = TL_REF_PI * u * u * u, dtheta = 3.0 * TL_REF_PI * u * u / steps;
        double ring = 0.0;
        for (uint32_t j = 0; j < nphi; j++) {
            double w[3], out[3];
            around(m, t, b, cos(theta), sin(theta), 2.0 * TL_REF_PI * (j + 0.5) / nphi, w);
            for (int k = 0; k < 3; k++) light.position[k] = d * w[k];
            tl_ref_ggx_terms(&light, p, n, v, alpha, out);
            ring += out[1] + out[2];
        }
        sum += ring * (2.0 * TL_REF_PI / nphi) * sin(theta) * dtheta;
    }
    return sum;
}

tl_ref_estimate tl_ref_sphere_rp_energy(const double n[3], const double v[3], double d, double radius, double alpha,
                                        uint32_t steps)
{
    double full = rp_energy(n, v, d, radius, alpha, steps), half = rp_energy(n, v, d, radius, alpha, steps / 2);
    return (tl_ref_estimate){full, fabs(full - half)};
}
