/* The frame's visible lights in view space, directional ones first: built once per frame for
 * whichever passes read them (forward per-object lists, Forward+, tiled shading) and uploaded once
 * into the frame's stream as the lights storage block. */
#include <math.h>
#include <string.h>

#include "lights.h"

/* Range of a light for culling: the sphere around a point light; the cone's bounding sphere
 * (centred half-way along the axis) for a spot. Directional: infinite. */
void tl__light_sphere(const tl_light *l, float c[3], float *radius)
{
    memcpy(c, l->position, sizeof(float) * 3);
    *radius = l->radius;
    if (l->type == TL_LIGHT_SPOT) {
        float co = l->cos_outer > 0.05f ? l->cos_outer : 0.05f;
        float half = 0.5f * l->radius, base = l->radius * sqrtf(1.0f - co * co) / co;
        float d[3] = {l->direction[0], l->direction[1], l->direction[2]};
        tl__vec3_normalize(d);
        for (int k = 0; k < 3; k++) c[k] += d[k] * half;
        float r2 = sqrtf(half * half + base * base);
        *radius = r2 < l->radius ? l->radius : r2;
    }
}

/* Appends the visible lights of one kind (0: directional, 1: local with a shadow slot, 2: the
 * other local ones); returns the new count. */
static size_t tl__add_visible(tl__lights *r, const tl__view *v, int kind, size_t n)
{
    int directional = kind == 0;
    for (size_t i = 0; i < r->count; i++) {
        const tl_light *l = &r->lights[i];
        int type = l->type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : (int)l->type;
        if ((type == TL_LIGHT_DIRECTIONAL) != directional) continue;
        if (!directional && (kind == 1) != (r->shadow_slots && r->shadow_slots[i] > 0.0f)) continue;
        float c[3], rad;
        tl__light_sphere(l, c, &rad);
        if (!directional && (rad <= 0.0f || !tl__sphere_visible((float(*)[4])v->planes, c, rad))) continue;
        tl__light_record_fill(l, v->view.m, r->shadow_slots ? r->shadow_slots[i] : 0.0f, &r->view[n]);
        memcpy(r->view_spheres[n], c, sizeof c);
        r->view_spheres[n][3] = directional ? -1.0f : rad;
        r->view_index[n++] = (uint32_t)i;
    }
    return n;
}

void tl__visible_lights(tl__device *dev, tl__lights *r, const tl__view *v, size_t *stream_bytes)
{
    /* casting local lights first: a tile list (in light order) starts with them, so the tiled loop
     * runs the shadow lookup's code only for them (docs/shadows.md, Cost) */
    r->view_dir_count = tl__add_visible(r, v, 0, 0);
    r->view_cast_end = tl__add_visible(r, v, 1, r->view_dir_count);
    r->view_count = tl__add_visible(r, v, 2, r->view_cast_end);
    *stream_bytes += (r->view_count + 1) * sizeof(tl__light_record) + dev->lim.ssbo_align;
}

void tl__visible_lights_upload(tl__device *dev, tl__lights *r)
{
    size_t n = r->view_count ? r->view_count : 1, offset = 0;
    void *dst = tl__stream_reserve(&dev->stream, n * sizeof(tl__light_record), dev->lim.ssbo_align, &offset);
    if (!dst) return;
    if (r->view_count) memcpy(dst, r->view, r->view_count * sizeof(tl__light_record));
    else memset(dst, 0, sizeof(tl__light_record));
    tl__stream_bind_range(&dev->gl, &dev->stream, GL_SHADER_STORAGE_BUFFER, TL__SSBO_LIGHTS, offset,
                          n * sizeof(tl__light_record));
}
