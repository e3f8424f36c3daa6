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

static tl_result tl__ensure_buffer(tl_renderer *r, GLuint *buf, size_t *capacity, size_t bytes)
{
    const GladGLContext *gl = &r->gl;
    if (bytes <= *capacity && *buf) return TL_OK;
    size_t cap = *capacity ? *capacity : 4096;
    while (cap < bytes) cap *= 2;
    if (*buf) gl->DeleteBuffers(1, buf);
    gl->CreateBuffers(1, buf);
    gl->NamedBufferStorage(*buf, (GLsizeiptr)cap, NULL, GL_DYNAMIC_STORAGE_BIT);
    *capacity = cap;
    return TL_OK;
}

tl_result tl__forward_lists(tl_renderer *r, const tl__view *v, uint64_t *pairs)
{
    const GladGLContext *gl = &r->gl;
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
        for (int k = 0; k < 3; k++) {
            fl->position_radius[k] = m[k] * l->position[0] + m[4 + k] * l->position[1] + m[8 + k] * l->position[2] + m[12 + k];
        }
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
        r->fwd_spheres[nvis][0] = c[0];
        r->fwd_spheres[nvis][1] = c[1];
        r->fwd_spheres[nvis][2] = c[2];
        r->fwd_spheres[nvis][3] = type == TL_LIGHT_DIRECTIONAL ? -1.0f : rad;
        r->fwd_visible[nvis++] = (uint32_t)i;
    }
    /* lists: count first, then fill, into one index array */
    size_t total = 0;
    for (size_t o = 0; o < r->object_count; o++) {
        const tl_object *ob = &r->objects[o];
        uint32_t n = 0;
        for (size_t j = 0; j < nvis; j++) {
            const float *sp = r->fwd_spheres[j];
            n += (uint32_t)(sp[3] < 0.0f || tl__sphere_box(sp, sp[3], ob->bounds_min, ob->bounds_max));
        }
        r->fwd_first[o] = (uint32_t)total;
        r->fwd_count[o] = n;
        total += n;
    }
    if (total > r->fwd_index_capacity) {
        size_t cap = r->fwd_index_capacity ? r->fwd_index_capacity : 1024;
        while (cap < total) cap *= 2;
        uint32_t *n = (uint32_t *)tl__alloc(&r->alloc, cap * sizeof *n);
        if (!n) return tl__fail(r, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for %zu forward light indices", total);
        tl__free(&r->alloc, r->fwd_indices);
        r->fwd_indices = n;
        r->fwd_index_capacity = cap;
    }
    for (size_t o = 0; o < r->object_count; o++) {
        const tl_object *ob = &r->objects[o];
        uint32_t *dst = r->fwd_indices + r->fwd_first[o];
        for (size_t j = 0; j < nvis; j++) {
            const float *sp = r->fwd_spheres[j];
            if (sp[3] < 0.0f || tl__sphere_box(sp, sp[3], ob->bounds_min, ob->bounds_max)) *dst++ = (uint32_t)j;
        }
    }
    *pairs = total;
    tl__ensure_buffer(r, &r->ssbo_lights, &r->ssbo_lights_capacity, (nvis ? nvis : 1) * sizeof(tl__forward_light));
    tl__ensure_buffer(r, &r->ssbo_indices, &r->ssbo_indices_capacity, (total ? total : 1) * sizeof(uint32_t));
    if (nvis) gl->NamedBufferSubData(r->ssbo_lights, 0, (GLsizeiptr)(nvis * sizeof(tl__forward_light)), r->fwd_lights);
    if (total) gl->NamedBufferSubData(r->ssbo_indices, 0, (GLsizeiptr)(total * sizeof(uint32_t)), r->fwd_indices);
    gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, r->ssbo_lights);
    gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, r->ssbo_indices);
    return TL_OK;
}
