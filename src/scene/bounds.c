/* Objects' defaults and bounds: a zero transform is the identity, zero bounds are computed from the
 * object's triangles (tl_object_compute_bounds, tl_scene_compute_bounds, and the renderer's copy at
 * set_scene through tl__object_defaults). */
#include <float.h>
#include <math.h>
#include <string.h>

#include "scene/validate.h"

int tl__transform_is_zero(const float m[16])
{
    for (int k = 0; k < 16; k++)
        if (m[k] != 0.0f) return 0;
    return 1;
}

int tl__bounds_are_zero(const tl_object *o)
{
    for (int k = 0; k < 3; k++)
        if (o->bounds_min[k] != 0.0f || o->bounds_max[k] != 0.0f) return 0;
    return 1;
}

static float tl__saturate(double v) { return v > FLT_MAX ? FLT_MAX : v < -FLT_MAX ? -FLT_MAX : (float)v; }

void tl__object_bounds_compute(const tl_scene *s, const tl_object *o, float min[3], float max[3])
{
    static const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const float *m = tl__transform_is_zero(o->transform) ? identity : o->transform;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (uint32_t i = 0; i < o->index_count; i++) {
        const float *p = s->vertices[s->indices[(size_t)o->first_index + i]].position;
        for (int r = 0; r < 3; r++) {
            double w = (double)m[r] * p[0] + (double)m[4 + r] * p[1] + (double)m[8 + r] * p[2] + (double)m[12 + r];
            lo[r] = w < lo[r] ? w : lo[r];
            hi[r] = w > hi[r] ? w : hi[r];
        }
    }
    for (int r = 0; r < 3; r++) {
        min[r] = o->index_count ? tl__saturate(lo[r]) : 0.0f;
        max[r] = o->index_count ? tl__saturate(hi[r]) : 0.0f;
    }
}

void tl__object_defaults(const tl_scene *s, tl_object *o)
{
    if (tl__bounds_are_zero(o)) tl__object_bounds_compute(s, o, o->bounds_min, o->bounds_max);
    if (tl__transform_is_zero(o->transform))
        o->transform[0] = o->transform[5] = o->transform[10] = o->transform[15] = 1.0f;
}

int tl__scene_objects_bounds(const tl_scene *s, float min[3], float max[3])
{
    int any = 0;
    for (size_t i = 0; s->objects && i < s->object_count; i++) {
        const tl_object *o = &s->objects[i];
        if (!o->index_count) continue;
        float lo[3], hi[3];
        if (tl__bounds_are_zero(o)) {
            tl__object_bounds_compute(s, o, lo, hi);
        } else {
            memcpy(lo, o->bounds_min, sizeof lo);
            memcpy(hi, o->bounds_max, sizeof hi);
        }
        for (int k = 0; k < 3; k++) {
            min[k] = any && min[k] < lo[k] ? min[k] : lo[k];
            max[k] = any && max[k] > hi[k] ? max[k] : hi[k];
        }
        any = 1;
    }
    return any;
}

/* What tl_object_compute_bounds reads of `o`, checked: its index range, indices, the positions
 * they name and the transform. */
static tl_result tl__object_readable(const tl_scene *s, const tl_object *o)
{
    if ((uint64_t)o->first_index + o->index_count > s->index_count || (o->index_count && !s->indices))
        return TL_ERROR_INVALID_ARGUMENT;
    for (int k = 0; k < 16; k++)
        if (!isfinite(o->transform[k])) return TL_ERROR_INVALID_ARGUMENT;
    for (uint32_t i = 0; i < o->index_count; i++) {
        uint32_t v = s->indices[(size_t)o->first_index + i];
        if (v >= s->vertex_count || !s->vertices) return TL_ERROR_INVALID_ARGUMENT;
        const float *p = s->vertices[v].position;
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2])) return TL_ERROR_INVALID_ARGUMENT;
    }
    return TL_OK;
}

tl_result tl_object_compute_bounds(const tl_scene *scene, const tl_object *object, float bounds_min[3],
                                   float bounds_max[3])
{
    if (!scene || !object || !bounds_min || !bounds_max) return TL_ERROR_INVALID_ARGUMENT;
    tl_result res = tl__object_readable(scene, object);
    if (res != TL_OK) return res;
    float lo[3], hi[3]; /* the object may be the one whose bounds are written */
    tl__object_bounds_compute(scene, object, lo, hi);
    memcpy(bounds_min, lo, sizeof lo);
    memcpy(bounds_max, hi, sizeof hi);
    return TL_OK;
}

tl_result tl_scene_compute_bounds(tl_scene *scene)
{
    if (!scene || (scene->object_count && !scene->objects)) return TL_ERROR_INVALID_ARGUMENT;
    for (size_t i = 0; i < scene->object_count; i++) {
        tl_result res = tl__object_readable(scene, &scene->objects[i]);
        if (res != TL_OK) return res;
    }
    int any = 0;
    float min[3] = {0, 0, 0}, max[3] = {0, 0, 0};
    for (size_t i = 0; i < scene->object_count; i++) {
        tl_object *o = &scene->objects[i];
        tl__object_bounds_compute(scene, o, o->bounds_min, o->bounds_max);
        if (!o->index_count) continue;
        for (int k = 0; k < 3; k++) {
            min[k] = any && min[k] < o->bounds_min[k] ? min[k] : o->bounds_min[k];
            max[k] = any && max[k] > o->bounds_max[k] ? max[k] : o->bounds_max[k];
        }
        any = 1;
    }
    memcpy(scene->bounds_min, min, sizeof min);
    memcpy(scene->bounds_max, max, sizeof max);
    return TL_OK;
}
