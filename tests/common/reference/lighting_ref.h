/* Double-precision reference of the two lighting models (docs/lighting.md), written once for the
 * tests: today's normalised Lambert + normalised Blinn-Phong, and GGX (Trowbridge-Reitz D,
 * Schlick-GGX Smith G with k = alpha / 2, Schlick Fresnel) with spherical area lights. Every
 * function is the same formula, in the same structure, as its GLSL twin in shaders/lighting.glsl
 * (the gloss mappings as in src/codec/gloss.c); thresholds that pick a branch are the shader's.
 * Vectors are double[3]; directions need not be unit length where noted (they are normalised
 * here, in double). Pure functions: no allocation, no state. */
#ifndef TL_LIGHTING_REF_H
#define TL_LIGHTING_REF_H

#include <stddef.h>

#define TL_REF_PI 3.14159265358979323846
/* One light's diffuse and specular weights are clamped to this (shaders/lighting.glsl). */
#define TL_REF_LIGHT_CLAMP 4096.0
/* Smallest GGX alpha of the gloss mapping (codec.h TL_GGX_MIN_ALPHA). */
#define TL_REF_GGX_MIN_ALPHA 0.0078125
/* Largest sin^2 of a sphere light's half-angle: a point inside the sphere (or on it) is lit as if
 * it were at distance radius / sqrt(this) from the centre, so every term stays finite. */
#define TL_REF_SPHERE_MAX_SIN2 (1.0 - 1.0 / 1024.0)

typedef enum tl_ref_light_type {
    TL_REF_LIGHT_POINT = 1,
    TL_REF_LIGHT_SPOT = 2,
    TL_REF_LIGHT_DIRECTIONAL = 3,
} tl_ref_light_type;

/* A light as the shaders see it (view space). Colours have pi folded in: a white Lambertian
 * surface facing a light at distance d reflects radiance colour / d^2. */
typedef struct tl_ref_light {
    tl_ref_light_type type;
    double position[3];   /* point, spot */
    double direction[3];  /* unit, the direction light travels (spot, directional) */
    double color[3];
    double range;         /* the windowed falloff reaches 0 here (point, spot) */
    double source_radius; /* sphere light radius (point, spot; GGX model only); 0 = punctual */
    double cos_inner, cos_outer;
    double specular;      /* tl_light.specular: 0 = 1, a value above 0 scales the highlight, < 0 none */
} tl_ref_light;

typedef enum tl_ref_model {
    TL_REF_MODEL_BLINN_PHONG = 1,
    TL_REF_MODEL_GGX = 2,
} tl_ref_model;

/* A surface as the material pass sees it. */
typedef struct tl_ref_surface {
    double albedo[3];   /* diffuse colour, linear */
    double specular[3]; /* F0 */
    double gloss;       /* [0,1] */
    double emissive[3];
    double occlusion;   /* scales the ambient term */
} tl_ref_surface;

/* glTF's metallic-roughness material as the renderer converts it (docs/gltf.md): albedo = base
 * (1 - metallic), F0 = mix(0.04, base, metallic), gloss = 1 - roughness (both clamped to [0,1]);
 * metals take F0 from the base colour. Emissive 0, occlusion 1. */
void tl_ref_surface_metallic_roughness(const double base[3], double metallic, double roughness,
                                       tl_ref_surface *out);

/* ---- gloss mappings (codec.h) ---------------------------------------------------------------- */

/* Blinn-Phong exponent 2^(1 + 11 gloss), gloss clamped to [0,1]. */
double tl_ref_specular_power(double gloss);
/* GGX alpha max((1 - gloss)^2, TL_REF_GGX_MIN_ALPHA), gloss clamped to [0,1]. */
double tl_ref_ggx_alpha(double gloss);

/* ---- falloff and cone (both models) ---------------------------------------------------------- */

/* clamp(1 - (d / range)^4, 0, 1)^2: 1 at the light, exactly 0 from d = range on. */
double tl_ref_window(double d, double range);
/* The punctual falloff: window / max(d^2, (0.01 range)^2). */
double tl_ref_attenuation(double d, double range);
/* Smoothstep between cos_outer and cos_inner of the angle between -to_light and direction. */
double tl_ref_spot(const double to_light[3], const double direction[3], double cos_inner, double cos_outer);

/* ---- today's model: normalised Lambert + normalised Blinn-Phong ------------------------------ */

/* (power + 8) / (8 pi) * max(n.h, 0)^power; 0 when l + v is (nearly) zero. */
double tl_ref_blinn_phong_lobe(const double n[3], const double l[3], const double v[3], double power);
/* Weights of one light at point p (tl_light_terms): out[0] = min(att * n.l, 4096) (diffuse),
 * out[1] = min(out[0] * lobe, 4096) (specular, to multiply by F0). */
void tl_ref_blinn_phong_terms(const tl_ref_light *light, const double p[3], const double n[3], const double v[3],
                              double power, double out[2]);

/* ---- GGX ------------------------------------------------------------------------------------- */

/* Trowbridge-Reitz distribution alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2); 0 for n.h <= 0. */
double tl_ref_ggx_d(double nh, double alpha);
/* Schlick-GGX masking of one direction, x / (x (1 - k) + k) with k = alpha / 2. */
double tl_ref_ggx_g1(double x, double alpha);
/* Visibility G1(n.l) G1(n.v) / (4 n.l n.v), written without the divisions (finite at 0). */
double tl_ref_ggx_vis(double nl, double nv, double alpha);
/* Schlick's weight s = (1 - v.h)^5 (v.h clamped to [0,1]); F = F0 (1 - s) + s. */
double tl_ref_fresnel_weight(double vh);
/* Irradiance of a Lambertian sphere light of unit intensity (radiance 1 / (pi radius^2)) at a
 * point whose normal makes cos_beta with the direction to the sphere's centre, at squared
 * distance d2 (>= radius^2 / TL_REF_SPHERE_MAX_SIN2): cos_beta / d2 while the sphere is above
 * the horizon, the exact form factor of the visible part while the horizon cuts it, 0 below. */
double tl_ref_sphere_irradiance(double cos_beta, double d2, double radius);
/* Direction to Karis' representative point: the point of the sphere (centre to_light from the
 * shaded point) closest to the reflection ray r. `fallback` when that point is the shaded point. */
void tl_ref_sphere_specular_dir(const double to_light[3], const double r[3], double radius,
                                const double fallback[3], double out[3]);
/* Karis' energy normalisation (alpha / alpha')^2, alpha' = min(alpha + radius / (2 d), 1). */
double tl_ref_sphere_normalization(double alpha, double radius, double d);
/* Weights of one light at point p for the GGX model: out[0] diffuse (to multiply by albedo),
 * out[1] = w (1 - s), out[2] = w s with w = min(pi D Vis n.l falloff, 4096) and s Schlick's
 * weight, so that the light's specular is colour * (F0 out[1] + out[2]). */
void tl_ref_ggx_terms(const tl_ref_light *light, const double p[3], const double n[3], const double v[3],
                      double alpha, double out[3]);
/* The specular BRDF without Fresnel, D Vis, for unit-or-not n, v, l; *vh receives v.h. */
double tl_ref_ggx_dv(const double n[3], const double v[3], const double l[3], double alpha, double *vh);

/* ---- one pixel --------------------------------------------------------------------------------- */

/* Linear HDR radiance of a surface point p (view space, camera at the origin) with normal n:
 *   albedo * (sum colour * diffuse + ambient * occlusion) + specular + emissive,
 * specular = F0 * sum colour * out[1] (Blinn-Phong) or sum colour * (F0 out[1] + out[2]) (GGX). */
void tl_ref_shade(tl_ref_model model, const tl_ref_surface *s, const double p[3], const double n[3],
                  const tl_ref_light *lights, size_t light_count, const double ambient[3], double out[3]);

#endif
