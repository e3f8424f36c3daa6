/* The lights module's own part: the scene's lights as validated copies, and each frame's light
 * data as the plan's passes declared it (TL__LIGHTS_*), prepared on the CPU and then uploaded into
 * the frame's stream by the files below it (light_volumes.c, light_lists.c, forward_lists.c,
 * tiles.c). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "lights.h"

enum { TL__LIGHTS_VISIBLE = TL__LIGHTS_VIEW | TL__LIGHTS_INDEX_BUFFER | TL__LIGHTS_OBJECT_LISTS | TL__LIGHTS_TILES };

tl_result tl__lights_count_check(tl__device *dev, size_t count)
{
    if (count <= dev->lim.max_lights) return TL_OK;
    return tl__fail(dev, TL_ERROR_LIMIT,
                    "renderer: %zu lights exceed the limit of %zu (TL_RENDERER_MAX_LIGHTS, or a storage block of %zu "
                    "bytes at %zu bytes a light)", count, dev->lim.max_lights, dev->lim.storage_max,
                    sizeof(tl__light_record));
}

static void tl__lights_free_arrays(tl__device *dev, tl__lights *l)
{
    void *arrays[] = {l->lights, l->instances, l->view, l->view_index, l->view_spheres};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) tl__free(&dev->alloc, arrays[i]);
    l->lights = NULL;
    l->instances = NULL;
    l->view = NULL;
    l->view_index = NULL;
    l->view_spheres = NULL;
    l->count = l->view_count = l->view_dir_count = l->view_cast_end = l->allocated = 0;
}

/* Negative light is clamped to none (docs/renderer-limits.md): -inf otherwise in FP16 targets;
 * directions are made unit (in double: any finite non-zero vector). */
static void tl__lights_sanitize(tl_light *copy, size_t count)
{
    for (size_t i = 0; i < count; i++) {
        double d[3], l2 = 0.0;
        for (int k = 0; k < 3; k++) {
            copy[i].color[k] = copy[i].color[k] > 0.0f ? copy[i].color[k] : 0.0f;
            d[k] = copy[i].direction[k];
            l2 += d[k] * d[k];
        }
        for (int k = 0; k < 3 && l2 > 0.0; k++) copy[i].direction[k] = (float)(d[k] / sqrt(l2));
    }
}

tl_result tl__lights_store(tl__device *dev, tl__lights *l, const tl_light *lights, size_t count)
{
    tl_result res = tl__lights_count_check(dev, count);
    if (res != TL_OK) return res;
    if (count && !lights) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %zu lights but no array", count);
    size_t kinds[TL__LIGHT_KINDS] = {0};
    for (size_t i = 0; i < count; i++) {
        char what[32], msg[TL__CHECK_MESSAGE_SIZE];
        if (tl__light_check(&lights[i], "light", msg, sizeof msg) != TL_OK) { /* named only when refused */
            snprintf(what, sizeof what, "lights[%zu]", i);
            res = tl__light_check(&lights[i], what, msg, sizeof msg);
            return tl__fail(dev, res, "renderer: %s", msg);
        }
        kinds[(lights[i].type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : lights[i].type) - 1]++;
    }
    if (l->lights && count && count <= l->allocated) { /* the same or fewer lights: the arrays stay */
        memcpy(l->lights, lights, count * sizeof *l->lights);
        tl__lights_sanitize(l->lights, count);
        l->count = count;
        l->view_count = l->view_dir_count = l->view_cast_end = 0;
        memcpy(l->kinds, kinds, sizeof kinds);
        return TL_OK;
    }
    tl_allocator *a = &dev->alloc;
    size_t n = count ? count : 1;
    tl_light *copy = (tl_light *)tl__alloc_array(a, n, sizeof *copy);
    tl__light_record *inst = (tl__light_record *)tl__alloc_array(a, n, sizeof *inst);
    tl__light_record *fl = (tl__light_record *)tl__alloc_array(a, n, sizeof *fl);
    uint32_t *vis = (uint32_t *)tl__alloc_array(a, n, sizeof *vis);
    float(*sph)[4] = (float(*)[4])tl__alloc_array(a, n, sizeof *sph);
    if (!copy || !inst || !fl || !vis || !sph) {
        void *arrays[] = {copy, inst, fl, vis, sph};
        for (size_t i = 0; i < 5; i++) tl__free(a, arrays[i]);
        return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for %zu lights", count);
    }
    if (count) memcpy(copy, lights, count * sizeof *copy);
    tl__lights_sanitize(copy, count);
    tl__lights_free_arrays(dev, l);
    l->lights = copy;
    l->instances = inst;
    l->view = fl;
    l->view_index = vis;
    l->view_spheres = sph;
    l->count = count;
    l->allocated = n;
    memcpy(l->kinds, kinds, sizeof kinds);
    return TL_OK;
}

tl_result tl__lights_objects(tl__device *dev, tl__lights *l, size_t objects)
{
    size_t n = objects ? objects : 1;
    uint32_t *first = (uint32_t *)tl__calloc(&dev->alloc, n, sizeof *first);
    uint32_t *count = (uint32_t *)tl__calloc(&dev->alloc, n, sizeof *count);
    if (!first || !count) {
        tl__free(&dev->alloc, first);
        tl__free(&dev->alloc, count);
        return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for %zu objects' light lists", n);
    }
    tl__free(&dev->alloc, l->fwd_first);
    tl__free(&dev->alloc, l->fwd_object_count);
    l->fwd_first = first;
    l->fwd_object_count = count;
    l->fwd_objects = objects;
    return TL_OK;
}

void tl__lights_release(tl__device *dev, tl__lights *l)
{
    tl__lights_free_arrays(dev, l);
    void *arrays[] = {l->fwd_indices, l->fwd_first, l->fwd_object_count};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) tl__free(&dev->alloc, arrays[i]);
    l->fwd_indices = l->fwd_first = l->fwd_object_count = NULL;
    l->fwd_capacity = l->fwd_count = l->fwd_objects = 0;
    tl__tiles_release(dev, &l->tiles);
    tl__fixup_release(dev, &l->fixup);
    if (l->vis.buffer) dev->gl.DeleteBuffers(1, &l->vis.buffer);
    l->vis.buffer = 0;
    l->vis.bytes = 0;
    tl__light_volumes_destroy(dev, l);
}

tl_result tl__lights_prepare(tl__device *dev, tl__lights *l, const tl__scene_gpu *scene, const tl__view *v,
                             unsigned needs, int fullscreen, uint64_t frame, tl_frame_stats *st, size_t *stream_bytes)
{
    tl_result res = TL_OK;
    l->view_count = l->view_dir_count = l->view_cast_end = 0;
    if (needs & TL__LIGHTS_INSTANCES) {
        l->fullscreen = fullscreen;
        tl__volumes_prepare(l, v, st, stream_bytes);
    }
    if (needs & TL__LIGHTS_VISIBLE) tl__visible_lights(dev, l, v, stream_bytes);
    if (needs & TL__LIGHTS_TILES) res = tl__tiles_prepare(dev, l, frame, st);
    if (res == TL_OK && (needs & TL__LIGHTS_INDEX_BUFFER))
        res = tl__forward_prepare(dev, l, scene, (needs & TL__LIGHTS_OBJECT_LISTS) != 0, st, stream_bytes);
    return res;
}

void tl__lights_upload(tl__device *dev, tl__lights *l, unsigned needs)
{
    if (needs & TL__LIGHTS_INSTANCES) tl__volumes_upload(dev, l);
    if (needs & TL__LIGHTS_VISIBLE) tl__visible_lights_upload(dev, l);
    if (needs & TL__LIGHTS_INDEX_BUFFER) tl__forward_upload(dev, l);
    if (needs & TL__LIGHTS_TILES) tl__tiles_upload(dev, l);
    tl__fixup_bind(dev, &l->fixup); /* the light scale's, when the plan has it */
}

void tl__lights_frame_block(const tl__lights *l, unsigned needs, uint32_t counts[3], uint32_t tiles[4])
{
    counts[0] = counts[1] = counts[2] = 0;
    if (needs & TL__LIGHTS_VISIBLE) { /* built this frame by a pass that reads them */
        counts[0] = (uint32_t)l->view_dir_count;
        counts[1] = (uint32_t)(l->view_count - l->view_dir_count);
        counts[2] = (uint32_t)l->view_cast_end;
    }
    tiles[0] = l->tiles.size;
    tiles[1] = l->tiles.x;
    tiles[2] = l->tiles.y;
    tiles[3] = (uint32_t)l->tiles.capacity;
}

GLuint tl__lights_buffer(const tl__lights *l, tl_target_id t)
{
    return t == TL_TARGET_LIGHT_LISTS   ? l->tiles.headers
           : t == TL_TARGET_LIGHT_FIXUP ? l->fixup.buffer
           : t == TL_TARGET_VIS_TILES   ? l->vis.buffer
                                        : 0u;
}

void tl__lights_read_counters(tl__device *dev, tl__lights *l, tl_target_set targets, uint32_t pixels,
                              tl_frame_stats *st)
{
    if (targets & TL_TARGET_BIT(TL_TARGET_LIGHT_LISTS)) tl__tiles_collect(dev, &l->tiles, st);
    if (targets & TL_TARGET_BIT(TL_TARGET_LIGHT_FIXUP)) tl__fixup_collect(dev, &l->fixup, pixels, st);
}
