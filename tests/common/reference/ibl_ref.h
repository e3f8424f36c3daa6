/* Double-precision reference of light from an environment (docs/lighting.md, "Light from the
 * environment"), written for the tests independently of src/render/environment/ibl_bake.c: the test
 * environment (an analytic sky), the equirectangular image's radiance as GL samples it, and a
 * Monte Carlo estimate of the radiance a surface of the lighting model (normalised Lambert, GGX
 * with Schlick-GGX k = alpha / 2 and Schlick's Fresnel) reflects from it. World space, +Y up;
 * u = atan2(z, x) / 2 pi + 1/2, v = acos(y) / pi, row 0 at the top. */
#ifndef TL_IBL_REF_H
#define TL_IBL_REF_H

#include <stdint.h>

typedef struct ibl_ref_env {
    const float *rgb; /* w x h RGB, rows top to bottom */
    uint32_t w, h;
} ibl_ref_env;

/* The test sky's radiance in unit direction d: a blue zenith over a bright horizon, a darker
 * ground that varies with azimuth (so the image's wrap at u = 0 carries detail), and a soft sun
 * (a Gaussian lobe of standard deviation 0.1 rad, about 6 degrees; peak radiance 24). Smooth everywhere. */
void ibl_ref_sky(const double d[3], double out[3]);
/* The sky at every texel centre of a w x h image. */
void ibl_ref_sky_image(uint32_t w, uint32_t h, float *rgb);

/* The direction of (u, v), and (u, v) of a direction. */
void ibl_ref_direction(double u, double v, double d[3]);
void ibl_ref_uv(const double d[3], double *u, double *v);
/* The image's radiance in direction d, bilinear between texel centres, u wrapping, v clamped:
 * what a GL_LINEAR, GL_REPEAT x GL_CLAMP_TO_EDGE sampler returns. */
void ibl_ref_radiance(const ibl_ref_env *e, const double d[3], double out[3]);

/* Radiance reflected towards v by a surface with normal n (unit, n.v > 0): the integral over the
 * hemisphere of radiance x (albedo / pi + D G F / (4 n.l n.v)) x n.l, as two estimates on
 * stratified jittered samples (n x n of each): cosine-distributed for the diffuse term, GGX
 * half vectors for the specular one. seed picks the jitter. */
void ibl_ref_shade(const ibl_ref_env *e, const double n[3], const double v[3], const double albedo[3],
                   const double f0[3], double alpha, unsigned n_sqrt, uint64_t seed, double out[3]);

#endif
