/* Forward shading's per-object light lists, as a competent forward renderer builds them: of the
 * lights in the view frustum (light_lists.c), each object gets those whose range reaches its
 * bounds (directional lights reach everything). The lists go to an index buffer. */
#include <math.h>
#include <string.h>

#include "lights.h"
#include "scene_gpu.h"

static int tl__sphere_box(const float c[3], float radius, const float lo[3], const float hi[3])
{
    float d2 = 0.0f;
    for (int k = 0; k < 3; k++) {
        float v = c[k] < lo[k] ? lo[k] - c[k] : c[k] > hi[k] ? c[k] - hi[k] : 0.0f;
        d2 += v * v;
    }
    return d2 <= radius * radius;
}

static int tl__reaches(const float *sphere, const tl_object *o)
{
    return sphere[3] < 0.0f || tl__sphere_box(sphere, sphere[3], o->bounds_min, o->bounds_max);
}

/* The visible lights in scene order (the array holds directional lights first): the k-th. Lists
 * keep the scene's order, so a light's place in the sum does not depend on its type. */
static uint32_t tl__scene_order(const tl__lights *r, size_t *dir, size_t *local)
{
    int take_dir = *dir < r->view_dir_count &&
                   (*local >= r->view_count || r->view_index[*dir] < r->view_index[*local]);
    return take_dir ? (uint32_t)(*dir)++ : (uint32_t)(*local)++;
}

/* Counts first, then fills, into one index array; TL_ERROR_LIMIT past one storage block. */
static tl_result tl__forward_count(tl__device *dev, tl__lights *r, const tl__scene_gpu *g, size_t nvis, size_t *out)
{
    size_t total = 0, max_entries = dev->lim.storage_max / sizeof(uint32_t);
    for (size_t o = 0; o < g->object_count; o++) {
        uint32_t n = 0;
        for (size_t j = 0; j < nvis; j++) n += (uint32_t)tl__reaches(r->view_spheres[j], &g->objects[o]);
        r->fwd_first[o] = (uint32_t)total;
        r->fwd_object_count[o] = n;
        total += n;
        if (total > max_entries) /* the lists are one storage block of 4-byte entries */
            return tl__fail(dev, TL_ERROR_LIMIT,
                            "renderer: forward light lists need more than %zu entries (%zu objects, %zu visible "
                            "lights), over the storage block of %zu bytes; fewer lights or the tiled strategy",
                            max_entries, g->object_count, nvis, dev->lim.storage_max);
    }
    *out = total;
    return TL_OK;
}

tl_result tl__forward_prepare(tl__device *dev, tl__lights *r, const tl__scene_gpu *g, int per_object,
                              tl_frame_stats *st, size_t *stream_bytes)
{
    size_t nvis = per_object ? r->view_count : 0, total = 0; /* Forward+ alone reads tile lists */
    tl_result res = tl__forward_count(dev, r, g, nvis, &total);
    if (res != TL_OK) return res;
    if (total > r->fwd_capacity) {
        size_t cap = r->fwd_capacity ? r->fwd_capacity : 1024;
        while (cap < total) cap *= 2;
        uint32_t *n = (uint32_t *)tl__alloc_array(&dev->alloc, cap, sizeof *n);
        if (!n)
            return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for %zu forward light indices", total);
        tl__free(&dev->alloc, r->fwd_indices);
        r->fwd_indices = n;
        r->fwd_capacity = cap;
    }
    for (size_t o = 0; o < g->object_count; o++) {
        uint32_t *dst = r->fwd_indices + r->fwd_first[o];
        size_t dir = 0, local = r->view_dir_count;
        for (size_t k = 0; k < nvis && r->view_count; k++) {
            uint32_t j = tl__scene_order(r, &dir, &local);
            if (tl__reaches(r->view_spheres[j], &g->objects[o])) *dst++ = j;
        }
    }
    r->fwd_count = total;
    st->forward_light_pairs = total;
    *stream_bytes += (total + 1) * sizeof(uint32_t) + dev->lim.ssbo_align;
    return TL_OK;
}

/* The lists into the frame's stream, bound to the forward shader's storage block. */
void tl__forward_upload(tl__device *dev, tl__lights *r)
{
    size_t ni = r->fwd_count ? r->fwd_count : 1, io = 0;
    uint32_t *i = (uint32_t *)tl__stream_reserve(&dev->stream, ni * sizeof(uint32_t), dev->lim.ssbo_align, &io);
    if (!i) return;
    if (r->fwd_count) memcpy(i, r->fwd_indices, r->fwd_count * sizeof(uint32_t));
    else i[0] = 0;
    tl__stream_bind_range(&dev->gl, &dev->stream, GL_SHADER_STORAGE_BUFFER, TL__SSBO_FORWARD_INDICES, io,
                          ni * sizeof(uint32_t));
}
