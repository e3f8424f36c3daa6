/* Image-based light computed on the CPU from an equirectangular environment (docs/lighting.md,
 * "Light from the environment"): its irradiance as 9 spherical-harmonic coefficients (Ramamoorthi
 * and Hanrahan 2001), its GGX-prefiltered mip chain and the split-sum BRDF table (Karis 2013).
 * Pure: no GL; the caller owns every buffer. Directions are world space, +Y up:
 * u = atan2(z, x) / 2 pi + 1/2, v = acos(y) / pi, row 0 at the top. */
#ifndef TL_RENDER_IBL_BAKE_H
#define TL_RENDER_IBL_BAKE_H

#include <stddef.h>
#include <stdint.h>

/* Levels of the prefiltered chain: level k holds perceptual roughness k / (levels - 1). */
#define TL__IBL_LEVELS 7
/* Side of the split-sum table (n.v across, roughness down). */
#define TL__IBL_BRDF_SIZE 64

/* The direction of equirectangular coordinates (u, v) in [0, 1]^2. */
void tl__ibl_direction(double u, double v, double d[3]);

/* The radiance's projection on the 9 real SH basis functions (bands 0..2), in double. */
void tl__ibl_sh9(const float *rgb, uint32_t w, uint32_t h, double sh[9][3]);
/* The 9 basis functions at unit direction d (the order of tl__ibl_sh9). */
void tl__ibl_sh_basis(const double d[3], double y[9]);
/* Coefficients c_i whose sum c_i Y_i(n) is the irradiance at normal n over pi (a white Lambertian
 * surface's radiance): the radiance's times A_l / pi, A = (pi, 2 pi / 3, pi / 4). */
void tl__ibl_sh_diffuse(double sh[9][3], float out[9][4]);

/* A box-filtered pyramid of the environment (level 0 the image itself, not copied). */
typedef struct tl__ibl_pyramid {
    uint32_t levels;
    uint32_t w[16], h[16];
    const float *px[16]; /* RGB; level 0 the caller's, the others in `store` */
    float *store;
} tl__ibl_pyramid;

/* Floats `store` needs for an image of w x h (levels above 0). */
size_t tl__ibl_pyramid_floats(uint32_t w, uint32_t h);
void tl__ibl_pyramid_build(const float *rgb, uint32_t w, uint32_t h, float *store, tl__ibl_pyramid *p);
/* Trilinear radiance of the pyramid in direction d at fractional level lod (u wraps, v clamps). */
void tl__ibl_pyramid_sample(const tl__ibl_pyramid *p, const double d[3], double lod, double out[3]);

/* The width of the prefiltered chain's level 0 for an environment of width w (512; height half
 * of it). */
uint32_t tl__ibl_base_width(uint32_t w);
/* One level of the prefiltered chain (RGBA floats, ow x oh): GGX lobes of the level's roughness
 * around each texel's direction, n = v = r (Karis 2013), importance-sampled with the pyramid's
 * level chosen by each sample's solid angle (filtered importance sampling). */
void tl__ibl_prefilter_level(const tl__ibl_pyramid *p, uint32_t level, uint32_t ow, uint32_t oh, float *out);
/* The split-sum table: RG floats, TL__IBL_BRDF_SIZE^2, texel (i, j) at n.v = (i + 1/2) / size and
 * roughness (j + 1/2) / size: the scale A and bias B with specular = prefiltered (F0 A + B). */
void tl__ibl_brdf_table(float *out);

#endif
