/* Double-precision reference of light from an environment (ibl_ref.h). */
#include "ibl_ref.h"

#include <math.h>
#include <stddef.h>

#define IBL_PI 3.14159265358979323846

void ibl_ref_direction(double u, double v, double d[3])
{
    double phi = 2.0 * IBL_PI * (u - 0.5), theta = IBL_PI * v;
    d[0] = sin(theta) * cos(phi);
    d[1] = cos(theta);
    d[2] = sin(theta) * sin(phi);
}

void ibl_ref_uv(const double d[3], double *u, double *v)
{
    double r = hypot(d[0], d[2]);
    *u = r > 0.0 ? atan2(d[2], d[0]) / (2.0 * IBL_PI) + 0.5 : 0.5;
    *v = atan2(r, d[1]) / IBL_PI;
}

void ibl_ref_sky(const double d[3], double out[3])
{
    static const double zenith[3] = {0.15, 0.35, 0.9}, horizon[3] = {1.0, 0.9, 0.75}, ground[3] = {0.3, 0.22, 0.15};
    static const double sun_dir[3] = {0.48, 0.6, -0.64}, sun[3] = {24.0, 21.0, 16.0};
    double y = d[1], up = y > 0.0 ? sqrt(y) : 0.0, down = y < 0.0 ? 1.0 - exp(8.0 * y) : 0.0;
    double az = 1.0 + 0.35 * cos(atan2(d[2], d[0]) * 3.0); /* azimuthal bands on the ground */
    double c = d[0] * sun_dir[0] + d[1] * sun_dir[1] + d[2] * sun_dir[2];
    double s = exp((c - 1.0) / 0.01); /* exp(-theta^2 / 0.02): 0.1 rad standard deviation */
    for (int k = 0; k < 3; k++) {
        double sky = horizon[k] + (zenith[k] - horizon[k]) * up;
        double g = horizon[k] + (ground[k] * az - horizon[k]) * down;
        out[k] = (y >= 0.0 ? sky : g) + sun[k] * s;
    }
}

void ibl_ref_sky_image(uint32_t w, uint32_t h, float *rgb)
{
    for (uint32_t j = 0; j < h; j++)
        for (uint32_t i = 0; i < w; i++) {
            double d[3], c[3];
            ibl_ref_direction((i + 0.5) / w, (j + 0.5) / h, d);
            ibl_ref_sky(d, c);
            for (int k = 0; k < 3; k++) rgb[((size_t)j * w + i) * 3 + k] = (float)c[k];
        }
}

void ibl_ref_radiance(const ibl_ref_env *e, const double d[3], double out[3])
{
    double u, v;
    ibl_ref_uv(d, &u, &v);
    double x = u * e->w - 0.5, y = v * e->h - 0.5, fx = floor(x), fy = floor(y), ax = x - fx, ay = y - fy;
    long w = (long)e->w, h = (long)e->h;
    long x0 = (((long)fx % w) + w) % w, x1 = (x0 + 1) % w, y0 = (long)fy, y1 = y0 + 1;
    if (y0 < 0) y0 = 0;
    if (y1 < 0) y1 = 0;
    if (y0 > h - 1) y0 = h - 1;
    if (y1 > h - 1) y1 = h - 1;
    for (int k = 0; k < 3; k++) {
        double a = e->rgb[((size_t)y0 * e->w + x0) * 3 + k], b = e->rgb[((size_t)y0 * e->w + x1) * 3 + k];
        double c = e->rgb[((size_t)y1 * e->w + x0) * 3 + k], f = e->rgb[((size_t)y1 * e->w + x1) * 3 + k];
        out[k] = (1.0 - ay) * ((1.0 - ax) * a + ax * b) + ay * ((1.0 - ax) * c + ax * f);
    }
}

static double ibl_rand(uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}

static void ibl_frame(const double n[3], double t[3], double b[3])
{
    double a[3] = {fabs(n[0]) < 0.9 ? 1.0 : 0.0, fabs(n[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    t[0] = a[1] * n[2] - a[2] * n[1];
    t[1] = a[2] * n[0] - a[0] * n[2];
    t[2] = a[0] * n[1] - a[1] * n[0];
    double l = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    for (int k = 0; k < 3; k++) t[k] /= l;
    b[0] = n[1] * t[2] - n[2] * t[1];
    b[1] = n[2] * t[0] - n[0] * t[2];
    b[2] = n[0] * t[1] - n[1] * t[0];
}

static double ibl_dot(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Diffuse: cosine-distributed l, estimator radiance x albedo (the pdf n.l / pi cancels). */
static void ibl_diffuse(const ibl_ref_env *e, const double n[3], const double t[3], const double b[3], unsigned m,
                        uint64_t *s, double out[3])
{
    for (unsigned i = 0; i < m * m; i++) {
        double e1 = ((i % m) + ibl_rand(s)) / m, e2 = ((i / m) + ibl_rand(s)) / m;
        double r = sqrt(e1), phi = 2.0 * IBL_PI * e2, z = sqrt(1.0 - e1), l[3], c[3];
        for (int k = 0; k < 3; k++) l[k] = r * cos(phi) * t[k] + r * sin(phi) * b[k] + z * n[k];
        ibl_ref_radiance(e, l, c);
        for (int k = 0; k < 3; k++) out[k] += c[k] / (m * m);
    }
}

/* Specular: GGX half vectors (pdf D n.h / (4 v.h) for l), estimator radiance F G v.h / (n.h n.v). */
static void ibl_specular(const ibl_ref_env *e, const double n[3], const double v[3], const double t[3],
                         const double b[3], const double f0[3], double alpha, unsigned m, uint64_t *s, double out[3])
{
    double nv = ibl_dot(n, v), kk = alpha * 0.5, a2 = alpha * alpha;
    for (unsigned i = 0; i < m * m; i++) {
        double e1 = ((i % m) + ibl_rand(s)) / m, e2 = ((i / m) + ibl_rand(s)) / m;
        double ct = sqrt((1.0 - e2) / (1.0 + (a2 - 1.0) * e2)), st = sqrt(1.0 - ct * ct), phi = 2.0 * IBL_PI * e1;
        double h[3], l[3], c[3];
        for (int k = 0; k < 3; k++) h[k] = st * cos(phi) * t[k] + st * sin(phi) * b[k] + ct * n[k];
        double vh = ibl_dot(v, h);
        for (int k = 0; k < 3; k++) l[k] = 2.0 * vh * h[k] - v[k];
        double nl = ibl_dot(n, l);
        if (nl <= 0.0 || vh <= 0.0) continue;
        double g = (nl / (nl * (1.0 - kk) + kk)) * (nv / (nv * (1.0 - kk) + kk));
        double w = g * vh / (ct * nv), fc = pow(1.0 - vh, 5.0);
        ibl_ref_radiance(e, l, c);
        for (int k = 0; k < 3; k++) out[k] += c[k] * w * (f0[k] + (1.0 - f0[k]) * fc) / (m * m);
    }
}

void ibl_ref_shade(const ibl_ref_env *e, const double n[3], const double v[3], const double albedo[3],
                   const double f0[3], double alpha, unsigned n_sqrt, uint64_t seed, double out[3])
{
    double t[3], b[3], d[3] = {0, 0, 0}, s[3] = {0, 0, 0};
    uint64_t state = seed;
    ibl_frame(n, t, b);
    ibl_diffuse(e, n, t, b, n_sqrt, &state, d);
    ibl_specular(e, n, v, t, b, f0, alpha, n_sqrt, &state, s);
    for (int k = 0; k < 3; k++) out[k] = albedo[k] * d[k] + s[k];
}
