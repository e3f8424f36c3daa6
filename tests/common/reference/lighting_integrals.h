/* Numerical integrals of the GGX model, in double, to check the closed forms and approximations
 * of lighting_ref.h against: directional albedo (energy), the sphere light's irradiance and
 * specular by Monte Carlo over its solid angle, and the representative point's highlight energy.
 * Deterministic (seeded, stratified). */
#ifndef TL_LIGHTING_INTEGRALS_H
#define TL_LIGHTING_INTEGRALS_H

#include <stdint.h>

/* An estimate and its uncertainty: the standard error of a Monte Carlo mean (computed as if the
 * stratified samples were independent, which overstates it), or a quadrature's change when its
 * resolution doubles. */
typedef struct tl_ref_estimate {
    double value, error;
} tl_ref_estimate;

/* Masking term G1 used in the albedo integral. */
typedef enum tl_ref_g1 {
    TL_REF_G1_SCHLICK = 0, /* Schlick-GGX with k = alpha / 2 (the model, lighting_ref.h) */
    TL_REF_G1_SCHLICK_UE4, /* Schlick-GGX with UE4's k = (r + 1)^2 / 8, r = sqrt(alpha) */
    TL_REF_G1_SMITH,       /* the exact Smith G1 of GGX: 2x / (x + sqrt(a^2 + (1 - a^2) x^2)) */
} tl_ref_g1;

/* Directional albedo of the GGX lobe with F = 1: the integral over the upper hemisphere of
 * D G1(n.l) G1(n.v) / (4 n.l n.v) n.l, for n.v in (0, 1]. Quadrature over a side x side grid of
 * GGX importance samples (its integrand vanishes at the horizon, so the midpoint rule converges
 * quadratically); error = |value - value at side / 2|. */
tl_ref_estimate tl_ref_ggx_albedo(double alpha, double nv, tl_ref_g1 g1, uint32_t side);

/* The integral of D(h) n.h over the hemisphere of h (1 for a normalised distribution). */
double tl_ref_ggx_d_integral(double alpha, uint32_t steps);

/* A sphere light of radius `radius` whose centre is at `centre` from the shaded point (normal n,
 * view v, both unit; |centre| > radius), integrated over its solid angle clipped to the upper
 * hemisphere, with unit intensity (radiance 1 / (pi radius^2)), from side^2 stratified samples:
 *   diffuse:  the irradiance, integral of (n.w) dw / (pi radius^2)   (tl_ref_sphere_irradiance)
 *   specular: the weight, integral of pi D Vis (n.w) dw / (pi radius^2) (tl_ref_ggx_terms' w)
 * The specular estimate combines uniform cone samples and GGX samples (balance heuristic). */
tl_ref_estimate tl_ref_sphere_diffuse_mc(const double n[3], const double centre[3], double radius, uint32_t side,
                                         uint64_t seed);
tl_ref_estimate tl_ref_sphere_specular_mc(const double n[3], const double v[3], const double centre[3], double radius,
                                          double alpha, uint32_t side, uint64_t seed);

/* Highlight energy: the specular weight w of tl_ref_ggx_terms integrated over every direction of
 * the light's centre at distance d (the sphere's centre sweeping the whole sphere of directions
 * around the point). For the true sphere light this is (solid angle of the sphere / radius^2)
 * times the directional albedo; the ratio tells how well an approximation keeps the energy.
 * Quadrature in polar coordinates around the mirror direction, steps x (4 steps) points. */
tl_ref_estimate tl_ref_sphere_rp_energy(const double n[3], const double v[3], double d, double radius, double alpha,
                                        uint32_t steps);

#endif
