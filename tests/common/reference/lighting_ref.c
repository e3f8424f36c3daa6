/* Double-precision reference of the lighting models; see lighting_ref.h and docs/lighting.md.
 * Sources, by title and author: Karis, "Real Shading in Unreal Engine 4" (SIGGRAPH 2013 course
 * notes) for the GGX / Schlick-GGX / Schlick model and the sphere light's representative point
 * and energy normalisation; Lagarde and de Rousiers, "Moving Frostbite to Physically Based
 * Rendering" (SIGGRAPH 2014 course notes) and Snyder, "Area Light Sources for Real-Time Graphics"
 * (Microsoft Research, 1996) for the irradiance of a sphere cut by the horizon. */
#include "lighting_ref.h"

#include <math.h>

static double clamp01(double x) { return x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0; }
static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* a / |a|; false (out untouched) when |a| <= min_len */
static int unit3(const double a[3], double min_len, double out[3])
{
    double len = sqrt(dot3(a, a));
    if (!(len > min_len)) return 0;
    for (int i = 0; i < 3; i++) out[i] = a[i] / len;
    return 1;
}

void tl_ref_surface_metallic_roughness(const double base[3], double metallic, double roughness,
                                       tl_ref_surface *out)
{
    double m = clamp01(metallic);
    for (int i = 0; i < 3; i++) {
        out->albedo[i] = base[i] * (1.0 - m);
        out->specular[i] = 0.04 + (base[i] - 0.04) * m;
        out->emissive[i] = 0.0;
    }
    out->gloss = 1.0 - clamp01(roughness);
    out->occlusion = 1.0;
}

/* ---- gloss mappings ---------------------------------------------------------------------------- */

double tl_ref_specular_power(double gloss) { return exp2(1.0 + 11.0 * clamp01(gloss)); }

double tl_ref_ggx_alpha(double gloss)
{
    double r = 1.0 - clamp01(gloss);
    return fmax(r * r, TL_REF_GGX_MIN_ALPHA);
}

/* ---- falloff and cone -------------------------------------------------------------------------- */

double tl_ref_window(double d, double range)
{
    double x = d / range, w = clamp01(1.0 - x * x * x * x);
    return w * w;
}

double tl_ref_attenuation(double d, double range)
{
    double m = 0.01 * range;
    return tl_ref_window(d, range) / fmax(d * d, m * m);
}

double tl_ref_spot(const double to_light[3], const double direction[3], double cos_inner, double cos_outer)
{
    double c = -dot3(to_light, direction);
    double t = clamp01((c - cos_outer) / fmax(cos_inner - cos_outer, 1e-4));
    return t * t * (3.0 - 2.0 * t);
}

/* Direction to the light's centre, the window times the cone, and the squared distance (0 and
 * window 1 for directional lights). A light at the shaded point lights it along the normal. */
static double light_geometry(const tl_ref_light *light, const double p[3], const double n[3], double to_light[3],
                             double l[3], double *d2)
{
    if (light->type == TL_REF_LIGHT_DIRECTIONAL) {
        for (int i = 0; i < 3; i++) to_light[i] = l[i] = -light->direction[i];
        *d2 = 0.0;
        return 1.0;
    }
    for (int i = 0; i < 3; i++) to_light[i] = light->position[i] - p[i];
    *d2 = dot3(to_light, to_light);
    if (!unit3(to_light, 1e-6, l))
        for (int i = 0; i < 3; i++) l[i] = n[i];
    double win = tl_ref_window(sqrt(*d2), light->range);
    if (light->type == TL_REF_LIGHT_SPOT) win *= tl_ref_spot(l, light->direction, light->cos_inner, light->cos_outer);
    return win;
}

/* ---- Blinn-Phong ------------------------------------------------------------------------------- */

double tl_ref_blinn_phong_lobe(const double n[3], const double l[3], const double v[3], double power)
{
    double h[3] = {l[0] + v[0], l[1] + v[1], l[2] + v[2]};
    if (dot3(h, h) < 1e-12) return 0.0;
    unit3(h, 0.0, h);
    double nh = fmax(dot3(n, h), 0.0);
    return (power + 8.0) / (8.0 * TL_REF_PI) * pow(nh, power);
}

void tl_ref_blinn_phong_terms(const tl_ref_light *light, const double p[3], const double n[3], const double v[3],
                              double power, double out[2])
{
    double to_light[3], l[3], d2;
    double att = light_geometry(light, p, n, to_light, l, &d2);
    if (light->type != TL_REF_LIGHT_DIRECTIONAL) {
        double m = 0.01 * light->range;
        att /= fmax(d2, m * m);
    }
    double nl = fmax(dot3(n, l), 0.0);
    out[0] = fmin(att * nl, TL_REF_LIGHT_CLAMP);
    out[1] = fmin(out[0] * tl_ref_blinn_phong_lobe(n, l, v, power), TL_REF_LIGHT_CLAMP);
}

/* ---- GGX --------------------------------------------------------------------------------------- */

double tl_ref_ggx_d(double nh, double alpha)
{
    if (!(nh > 0.0)) return 0.0;
    double a2 = alpha * alpha, nh2 = fmin(nh * nh, 1.0);
    /* 1 - nh^2 (1 - a^2) as (1 - nh^2) + nh^2 a^2: no cancellation near the peak */
    double den = (1.0 - nh2) + nh2 * a2;
    return a2 / (TL_REF_PI * den * den);
}

double tl_ref_ggx_g1(double x, double alpha)
{
    double k = 0.5 * alpha;
    return x / (x * (1.0 - k) + k);
}

double tl_ref_ggx_vis(double nl, double nv, double alpha)
{
    double k = 0.5 * alpha;
    return 0.25 / ((nl * (1.0 - k) + k) * (nv * (1.0 - k) + k));
}

double tl_ref_fresnel_weight(double vh)
{
    double t = 1.0 - clamp01(vh);
    return t * t * t * t * t;
}

double tl_ref_sphere_irradiance(double cos_beta, double d2, double radius)
{
    double r2 = radius * radius, s = r2 / d2, c2 = cos_beta * cos_beta;
    if (c2 >= s) return fmax(cos_beta, 0.0) / d2; /* wholly above (or below) the horizon */
    /* The horizon cuts the sphere: s > c2 >= 0, so s > 0 and sin(beta) > 0. */
    double sin_b = sqrt(1.0 - c2);
    double x = sqrt(1.0 / s - 1.0);
    double y = -x * cos_beta / sin_b;
    double q = sin_b * sqrt(fmax(1.0 - y * y, 0.0));
    double e = (cos_beta * acos(fmax(fmin(y, 1.0), -1.0)) - x * q) * s + atan2(q, x);
    return fmax(e, 0.0) / (TL_REF_PI * r2);
}

void tl_ref_sphere_specular_dir(const double to_light[3], const double r[3], double radius,
                                const double fallback[3], double out[3])
{
    double lr = dot3(to_light, r), c[3], pt[3];
    for (int i = 0; i < 3; i++) c[i] = lr * r[i] - to_light[i];
    double c2 = dot3(c, c);
    if (c2 > radius * radius) {
        double t = radius / sqrt(c2);
        for (int i = 0; i < 3; i++) pt[i] = to_light[i] + c[i] * t;
    } else { /* the ray meets the sphere: the ray's point closest to the centre */
        for (int i = 0; i < 3; i++) pt[i] = lr * r[i];
    }
    if (!unit3(pt, 1e-6, out))
        for (int i = 0; i < 3; i++) out[i] = fallback[i];
}

double tl_ref_sphere_normalization(double alpha, double radius, double d)
{
    double ap = fmin(alpha + radius / (2.0 * d), 1.0);
    return (alpha / ap) * (alpha / ap);
}

double tl_ref_ggx_dv(const double n[3], const double v[3], const double l[3], double alpha, double *vh)
{
    double nu[3], vu[3], lu[3], h[3];
    unit3(n, 0.0, nu);
    unit3(v, 0.0, vu);
    unit3(l, 0.0, lu);
    for (int i = 0; i < 3; i++) h[i] = lu[i] + vu[i];
    *vh = 0.0;
    double nl = fmax(dot3(nu, lu), 0.0), nv = fmin(fmax(dot3(nu, vu), 0.0), 1.0);
    if (dot3(h, h) < 1e-12 || !(nl > 0.0)) return 0.0;
    unit3(h, 0.0, h);
    *vh = dot3(vu, h);
    return tl_ref_ggx_d(dot3(nu, h), alpha) * tl_ref_ggx_vis(nl, nv, alpha);
}

void tl_ref_ggx_terms(const tl_ref_light *light, const double p[3], const double n[3], const double v[3],
                      double alpha, double out[3])
{
    double to_light[3], lc[3], ls[3], d2;
    double win = light_geometry(light, p, n, to_light, lc, &d2), diffuse, scale = win;
    for (int i = 0; i < 3; i++) ls[i] = lc[i];
    if (light->type == TL_REF_LIGHT_DIRECTIONAL) {
        diffuse = fmax(dot3(n, lc), 0.0);
    } else {
        double r = light->source_radius, m = 0.01 * light->range;
        double d2c = fmax(d2, fmax(r * r / TL_REF_SPHERE_MAX_SIN2, m * m));
        diffuse = win * tl_ref_sphere_irradiance(dot3(n, lc), d2c, r);
        scale = win / d2c;
        if (r > 0.0) {
            double refl[3], nv2 = 2.0 * dot3(n, v);
            for (int i = 0; i < 3; i++) refl[i] = nv2 * n[i] - v[i];
            tl_ref_sphere_specular_dir(to_light, refl, r, n, ls);
            scale *= tl_ref_sphere_normalization(alpha, r, sqrt(d2c));
        }
    }
    double vh, spec = TL_REF_PI * tl_ref_ggx_dv(n, v, ls, alpha, &vh) * fmax(dot3(n, ls), 0.0) * scale;
    double w = fmin(spec, TL_REF_LIGHT_CLAMP), s = tl_ref_fresnel_weight(vh);
    out[0] = fmin(diffuse, TL_REF_LIGHT_CLAMP);
    out[1] = w * (1.0 - s);
    out[2] = w * s;
}

/* ---- one pixel --------------------------------------------------------------------------------- */

void tl_ref_shade(tl_ref_model model, const tl_ref_surface *s, const double p[3], const double n[3],
                  const tl_ref_light *lights, size_t light_count, const double ambient[3], double out[3])
{
    const double fp16_max = 65504.0;
    double v[3] = {-p[0], -p[1], -p[2]}, nu[3] = {0.0, 0.0, 1.0};
    unit3(v, 0.0, v);
    unit3(n, 0.0, nu);
    double diffuse[3] = {0}, spec1[3] = {0}, spec2[3] = {0};
    double power = tl_ref_specular_power(s->gloss), alpha = tl_ref_ggx_alpha(s->gloss);
    for (size_t k = 0; k < light_count; k++) {
        double t[3] = {0.0, 0.0, 0.0};
        if (model == TL_REF_MODEL_GGX) tl_ref_ggx_terms(&lights[k], p, nu, v, alpha, t);
        else tl_ref_blinn_phong_terms(&lights[k], p, nu, v, power, t);
        double k_spec = lights[k].specular == 0.0 ? 1.0 : fmax(lights[k].specular, 0.0); /* after the clamp */
        t[1] *= k_spec;
        t[2] *= k_spec;
        /* one light's output never exceeds FP16's maximum (light.frag.glsl) */
        for (int i = 0; i < 3; i++) {
            diffuse[i] += fmin(lights[k].color[i] * t[0], fp16_max);
            spec1[i] += fmin(lights[k].color[i] * t[1], fp16_max);
            spec2[i] += fmin(lights[k].color[i] * t[2], fp16_max);
        }
    }
    for (int i = 0; i < 3; i++)
        out[i] = s->albedo[i] * (diffuse[i] + ambient[i] * s->occlusion) + s->specular[i] * spec1[i] + spec2[i] +
                 s->emissive[i];
}
