/* The one light record every pass reads (lights.h, tl__light_record): the volumes' instances and
 * the lights storage block of tiles, Forward+ and forward; light_eval.glsl's tl_light_data. */
#include <string.h>

#include "lights.h"

_Static_assert(sizeof(tl__light_record) == TL__LIGHT_BYTES, "the lights storage block's record");

/* One packing of a light for every pass: type resolved, direction unit (a zero one points down),
 * the cone's cosines only for spots, no sphere for directional lights. */
void tl__light_record_fill(const tl_light *l, const float *view, float shadow_slot, tl__light_record *out)
{
    static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const float *m = view ? view : identity;
    int type = l->type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : (int)l->type;
    for (int k = 0; k < 3; k++)
        out->position_radius[k] = m[k] * l->position[0] + m[4 + k] * l->position[1] + m[8 + k] * l->position[2] + m[12 + k];
    out->position_radius[3] = l->radius;
    float dir[3] = {l->direction[0], l->direction[1], l->direction[2]};
    tl__vec3_normalize(dir);
    if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f) dir[1] = -1.0f;
    float d[3];
    for (int k = 0; k < 3; k++) d[k] = m[k] * dir[0] + m[4 + k] * dir[1] + m[8 + k] * dir[2];
    if (view) tl__vec3_normalize(d);
    memcpy(out->color_type, l->color, sizeof(float) * 3);
    out->color_type[3] = (float)type;
    memcpy(out->direction_cos_outer, d, sizeof d);
    out->direction_cos_outer[3] = type == TL_LIGHT_SPOT ? l->cos_outer : -1.0f;
    out->cos_inner[0] = type == TL_LIGHT_SPOT ? l->cos_inner : 1.0f;
    out->cos_inner[1] = type == TL_LIGHT_DIRECTIONAL ? 0.0f : l->source_radius;
    out->cos_inner[2] = shadow_slot;
    out->cos_inner[3] = l->specular == 0.0f ? 1.0f : l->specular < 0.0f ? 0.0f : l->specular; /* tl_light.specular */
}
