/* Ray-traced shadow truth (Embree 3; a test and bench dependency only): the scene's opaque
 * triangles in world space, a primary ray through each pixel's centre (the exact surface point,
 * not the rebuilt one) and a shadow ray from there to the light. */
#ifndef TL_SHADOW_RT_H
#define TL_SHADOW_RT_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/scene.h"

typedef struct tl_shadow_rt tl_shadow_rt;

/* Per pixel: what the truth says. */
enum { TL_RT_NONE = 0, TL_RT_LIT = 1, TL_RT_SHADOWED = 2, TL_RT_AWAY = 3 /* facing away from the light */ };

/* NULL (after a line on stderr) when Embree fails. */
tl_shadow_rt *tl_shadow_rt_create(const tl_scene *scene);
void tl_shadow_rt_destroy(tl_shadow_rt *rt);

/* The camera as the renderer resolves it (fov 0: 60 degrees; up 0: +Y). Pixel rows bottom-up
 * (GL's read-back order); state[w * h] and object[w * h] (the object hit + 1, 0 without a hit). */
void tl_shadow_rt_truth(const tl_shadow_rt *rt, const tl_camera *camera, uint32_t w, uint32_t h, const tl_light *light,
                        uint8_t *state, uint32_t *object);

/* Per pixel the primary hit's world position and geometric normal (facing the eye), 3 floats each;
 * zeros without a hit (tl_shadow_rt_truth's object is 0 there). */
void tl_shadow_rt_surface(const tl_shadow_rt *rt, const tl_camera *camera, uint32_t w, uint32_t h, float *position,
                          float *normal);

/* A light with a size: per pixel the fraction of its emitter seen from the surface point, from
 * strata^2 stratified shadow rays over the disc that faces the point (point and spot lights: the
 * sphere of source_radius around position; directional lights: the cone of angular radius `angle`
 * radians around the direction); -1 without a hit or where the surface faces away from the
 * light's centre. object[w * h] as tl_shadow_rt_truth. */
void tl_shadow_rt_area(const tl_shadow_rt *rt, const tl_camera *camera, uint32_t w, uint32_t h, const tl_light *light,
                       float angle, uint32_t strata, float *visibility, uint32_t *object);
/* States from area visibility: lit where the whole emitter is seen, shadowed where none of it is,
 * TL_RT_NONE in the penumbra (so tl_shadow_rt_compare leaves it and `band` pixels around it out),
 * TL_RT_AWAY where not measured. */
void tl_shadow_rt_area_state(const float *visibility, uint8_t *state, size_t n);

/* The comparison of a render's shadow term (term[i] in 0..1, < 0 where the light adds nothing in
 * the unshadowed render) with the truth, outside the penumbra: pixels within `band` pixels of a
 * change of the truth's state or of the object hit (a silhouette) are left out. */
typedef struct tl_shadow_error {
    size_t counted;   /* pixels compared */
    size_t acne;      /* shadowed in the render, lit in truth */
    size_t leaks;     /* lit in the render, shadowed in truth */
    double wrong;     /* (acne + leaks) / counted */
} tl_shadow_error;
tl_shadow_error tl_shadow_rt_compare(const uint8_t *state, const uint32_t *object, const float *term, uint32_t w,
                                     uint32_t h, int band);
/* The same over two renders' terms (thin against fat): pixels whose lit state differs. */
tl_shadow_error tl_shadow_rt_compare_terms(const uint8_t *state, const uint32_t *object, const float *a, const float *b,
                                           uint32_t w, uint32_t h, int band);

#endif
