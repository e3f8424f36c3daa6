/* The shadow tests' scenes (shadow_scenes.c): the stiff scene (a long plane seen at grazing angles
 * with near/far 1:10^6, a thin pole, a box resting on the plane, a low directional light and a
 * point light at the surface) and the crypt with its braziers and moonlight casting. */
#ifndef TL_SHADOW_SCENES_H
#define TL_SHADOW_SCENES_H

#include "thinlight/renderer.h"
#include "shadow_rt.h"

typedef struct tl_shadow_case {
    tl_scene *scene;    /* owned: freed by tl_shadow_case_free */
    int built;          /* 1: arrays malloc'd here, 0: tl_scene_create_default */
    tl_light lights[4]; /* the casting lights measured, one at a time */
    size_t light_count;
    const char *light_names[4];
} tl_shadow_case;

int tl_shadow_stiff_case(tl_shadow_case *c);
/* A box resting on a floor, a pole and a floating plate under a spot and a point light with a
 * 0.25 m source radius: penumbrae that widen away from the contact (PCSS against area truth). */
int tl_shadow_penumbra_case(tl_shadow_case *c);
/* A floor under two spot lights whose axes are tilted from its normal (one low, looking 14 degrees
 * down to the horizon; one 2 m up at 45 degrees); with `occluder`, a box standing in both pools. */
int tl_shadow_spot_case(tl_shadow_case *c, int occluder);
int tl_shadow_crypt_case(tl_shadow_case *c, uint32_t detail);
void tl_shadow_case_free(tl_shadow_case *c);

#endif
