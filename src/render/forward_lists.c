/* Forward shading's per-object light lists, as a competent forward renderer builds them: of the
 * lights in the view frustum, each object gets those whose range reaches its bounds (directional
 * lights reach everything). Lights go to a storage buffer in view space, lists to an index buffer. */
#include <math.h>
#include <string.h>

#include "renderer_internal.h"

static int tl__sphere_box(const float c[3], float radius, const float lo[3], const float hi[3])
{
    float d2 = 0.0f;
    for (int k = 0; k < 3; k++) {
        float v = c[k] < lo[k] ? lo[k] - c[k] : c[k] > hi[k] ? c[k] - hi[k] : 0.0f;
        d2 += v * v;
    }
    return d2 <= radius * radius;
}

/* Range of a light for culling: the sphere around a point light; the cone's bounding sphere
 * (centred half-way along the axis) for a spot. Directional: infinite. */
static void tl__light_sphere(const tl_light *l, float c[3], float *radius)
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

/* Visible lights (view space) with their world-space bounding spheres; returns how many. */
static size_t tl__forward_visible(tl_renderer *r, const tl__view *v)
{
    size_t nvis = 0;
    for (size_t i = 0; i < r->light_count; i++) {
        const tl_light *l = &r->lights[i];
        int type = l->type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : (int)l->type;
        float c[3], rad;
        tl__light_sphere(l, c, &rad);
        if (type != TL_LIGHT_DIRECTIONAL && (rad <= 0.0f || !tl__sphere_visible((float(*)[4])v->planes, c, rad)))
            continue;
        tl__forward_light *fl = &r->fwd_lights[nvis];
        const float *m = v->view.m;
        for (int k = 0; k < 3; k++)
            fl->position_radius[k] = m[k] * l->position[0] + m[4 + k] * l->position[1] + m[8 + k] * l->position[2] + m[12 + k];
        fl->position_radius[3] = l->radius;
        float dir[3] = {l->direction[0], l->direction[1], l->direction[2]};
        tl__vec3_normalize(dir);
        if (dir[0] == 0.0f && dir[1] == 0.0f && dir[2] == 0.0f) dir[1] = -1.0f;
        float vd[3];
        for (int k = 0; k < 3; k++) vd[k] = m[k] * dir[0] + m[4 + k] * dir[1] + m[8 + k] * dir[2];
        tl__vec3_normalize(vd);
        memcpy(fl->color_type, l->color, sizeof(float) * 3);
        fl->color_type[3] = (float)type;
        memcpy(fl->direction_cos_outer, vd, sizeof vd);
        fl->direction_cos_outer[3] = type == TL_LIGHT_SPOT ? l->cos_outer : -1.0f;
        fl->cos_inner[0] = type == TL_LIGHT_SPOT ? l->cos_inner : 1.0f;
        fl->cos_inner[1] = fl->cos_inner[2] = fl->cos_inner[3] = 0.0f;
        memcpy(r->fwd_spheres[nvis], c, sizeof c);
        r->fwd_spheres[nvis][3] = type == TL_LIGHT_DIRECTIONAL ? -1.0f : rad;
        r->fwd_visible[nvis++] = (uint32_t)i;
    }
    return nvis;
}

static int tl__reaches(const float *sphere, const tl_object *o)
{
    return sphere[3] < 0.0f || tl__sphere_box(sphere, sphere[3], o->bounds_min, o->bounds_max);
}

tl_result tl__forward_prepare(tl_renderer *r, const tl__view *v, tl__frame_record *rec)
{
    size_t nvis = tl__forward_visible(r, v);
    /* lists: count first, then fill, into one index array */
    size_t total = 0;
    for (size_t o = 0; o < r->object_count; o++) {
        uint32_t n = 0;
        for (size_t j = 0; j < nvis; j++) n += (uint32_t)tl__reaches(r->fwd_spheres[j], &r->objects[o]);
        r->fwd_first[o] = (uint32_t)total;
        r->fwd_count[o] = n;
        total += n;
    }
    if (total > r->fwd_index_capacity) {
        size_t cap = r->fwd_index_capacity ? r->fwd_index_capacity : 1024;
        while (cap < total) cap *= 2;
        uint32_t *n = (uint32_t *)tl__alloc_array(&r->alloc, cap, sizeof *n);
        if (!n) return tl__fail(r, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for %zu forward light indices", total);
        tl__free(&r->alloc, r->fwd_indices);
        r->fwd_indices = n;
        r->fwd_index_capacity = cap;
    }
    for (size_t o = 0; o < r->object_count; o++) {
        uint32_t *dst = r->fwd_indices + r->fwd_first[o];
        for (size_t j = 0; j < nvis; j++)
            if (tl__reaches(r->fwd_spheres[j], &r->objects[o])) *dst++ = (uint32_t)j;
    }
    r->fwd_light_count = nvis;
    r->fwd_index_count = total;
    rec->st.forward_light_pairs = total;
    rec->stream_bytes += (nvis + 1) * sizeof(tl__forward_light) + (total + 1) * sizeof(uint32_t) + 2 * r->ssbo_align;
    return TL_OK;
}

/* Lights and lists into the frame's stream, bound to the forward shader's storage blocks. */
void tl__forward_upload(tl_renderer *r)
{
    const GladGLContext *gl = &r->gl;
    size_t nl = r->fwd_light_count ? r->fwd_light_count : 1, ni = r->fwd_index_count ? r->fwd_index_count : 1;
    size_t lo = 0, io = 0;
    void *l = tl__stream_reserve(&r->stream, nl * sizeof(tl__forward_light), r->ssbo_align, &lo);
    void *i = tl__stream_reserve(&r->stream, ni * sizeof(uint32_t), r->ssbo_align, &io);
    if (!l || !i) return;
    if (r->fwd_light_count) memcpy(l, r->fwd_lights, r->fwd_light_count * sizeof(tl__forward_light));
    else memset(l, 0, sizeof(tl__forward_light));
    if (r->fwd_index_count) memcpy(i, r->fwd_indices, r->fwd_index_count * sizeof(uint32_t));
    else memset(i, 0, sizeof(uint32_t));
    tl__stream_bind_range(gl, &r->stream, GL_SHADER_STORAGE_BUFFER, TL__SSBO_FORWARD_LIGHTS, lo,
                          nl * sizeof(tl__forward_light));
    tl__stream_bind_range(gl, &r->stream, GL_SHADER_STORAGE_BUFFER, TL__SSBO_FORWARD_INDICES, io, ni * sizeof(uint32_t));
}
