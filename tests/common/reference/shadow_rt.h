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
