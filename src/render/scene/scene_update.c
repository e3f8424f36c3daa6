/* Scene updates between frames: an object's transform, material, visibility or whole record, objects
 * added and removed, geometry appended, a material's values. Nothing here uploads the scene's
 * vertices again: per-object records are written into each frame's stream anyway (draw.c), so a
 * moved object is one tl_object changed on the CPU; its bounds follow from its box in object
 * space. Ids are slots: stable until removed, reused by the next add. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scene_gpu.h"

static const float tl__identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/* World bounds of `local` through `m`: its centre through m, its half extents through |m| (exact for
 * a box, computed in double). */
static void tl__box_transform(const tl__box *local, const float m[16], float min[3], float max[3])
{
    for (int r = 0; r < 3; r++) {
        double c = m[12 + r], e = 0.0;
        for (int k = 0; k < 3; k++) {
            double mk = m[k * 4 + r];
            c += mk * 0.5 * ((double)local->min[k] + local->max[k]);
            e += fabs(mk) * 0.5 * ((double)local->max[k] - local->min[k]);
        }
        min[r] = (float)(c - e);
        max[r] = (float)(c + e);
    }
}

static int tl__material_of(const tl__scene_gpu *g, const tl_object *o)
{
    return g->material_count ? (int)o->material : 0;
}

/* An object with indices counted in (+1) or out (-1) of its material's uses and of the points and
 * lines the scene draws. */
static void tl__object_uses(tl__scene_gpu *g, const tl_object *o, int delta)
{
    if (!o->index_count) return;
    g->material_uses[tl__material_of(g, o)] += (uint32_t)delta;
    if (o->primitive != TL_PRIMITIVE_TRIANGLES) g->points_lines_objects += (size_t)(ptrdiff_t)delta;
}

/* Whether the scene's features (what the plan depends on) changed with the materials' uses. */
int tl__scene_features_refresh(tl__scene_gpu *g)
{
    tl_scene_feature_set f = {0};
    size_t nm = g->material_count ? g->material_count : 1;
    int drawn = 0;
    for (size_t m = 0; m < nm; m++) {
        if (!g->material_uses[m]) continue;
        drawn = 1;
        const tl_scene_feature_set *a = &g->material_features[m];
        f.has_specular |= a->has_specular;
        f.has_textures |= a->has_textures;
        f.has_normal_maps |= a->has_normal_maps;
        f.has_emissive |= a->has_emissive;
        f.has_alpha_mask |= a->has_alpha_mask;
        f.has_alpha_blend |= a->has_alpha_blend;
        if (a->has_alpha_blend) f.alpha_blend_objects += g->material_uses[m];
        f.has_metallic_roughness |= a->has_metallic_roughness;
        f.has_occlusion |= a->has_occlusion;
        f.has_emissive_texture |= a->has_emissive_texture;
        f.has_double_sided |= a->has_double_sided;
        f.has_microfacet |= a->has_microfacet;
        f.has_uv1 |= a->has_uv1 && g->vbo_uv1;
        f.material_models |= a->material_models;
    }
    f.has_points_lines = g->points_lines_objects > 0;
    f.has_vertex_colors = g->vbo_colors && drawn;
    tl_scene_feature_set *o = &g->features;
    f.point_lights = o->point_lights;
    f.spot_lights = o->spot_lights;
    f.directional_lights = o->directional_lights;
    f.triangle_count = g->index_count / 3;
    f.object_count = g->object_count;
    int changed = (f.has_specular != o->has_specular || f.has_textures != o->has_textures ||
                   f.has_normal_maps != o->has_normal_maps || f.has_emissive != o->has_emissive ||
                   f.has_alpha_mask != o->has_alpha_mask || f.has_alpha_blend != o->has_alpha_blend ||
                   f.has_metallic_roughness != o->has_metallic_roughness || f.has_occlusion != o->has_occlusion ||
                   f.has_emissive_texture != o->has_emissive_texture || f.has_double_sided != o->has_double_sided ||
                   f.has_microfacet != o->has_microfacet || f.alpha_blend_objects != o->alpha_blend_objects ||
                   f.has_points_lines != o->has_points_lines || f.has_vertex_colors != o->has_vertex_colors ||
                   f.has_uv1 != o->has_uv1 || f.material_models != o->material_models);
    *o = f;
    return changed;
}

void tl__scene_objects_init(tl__scene_gpu *g, const tl_scene *s)
{
    for (size_t i = 0; i < g->object_count; i++) {
        tl_object local = s->objects[i];
        memset(local.transform, 0, sizeof local.transform); /* the identity: the box in object space */
        tl__object_bounds_compute(s, &local, g->object_local[i].min, g->object_local[i].max);
        g->object_state[i] = 0;
        tl__object_uses(g, &g->objects[i], 1);
    }
    for (size_t m = 0; m < s->material_count; m++)
        tl__material_features(&s->materials[m], s->texture_count, &g->material_features[m]);
}

void tl__scene_bounds_refresh(tl__scene_gpu *g)
{
    int any = 0;
    for (size_t i = 0; i < g->object_count; i++) {
        const tl_object *o = &g->objects[i];
        if (!o->index_count || g->object_state[i]) continue; /* hidden objects frame nothing */
        for (int k = 0; k < 3; k++) {
            g->bounds_min[k] = any && g->bounds_min[k] < o->bounds_min[k] ? g->bounds_min[k] : o->bounds_min[k];
            g->bounds_max[k] = any && g->bounds_max[k] > o->bounds_max[k] ? g->bounds_max[k] : o->bounds_max[k];
        }
        any = 1;
    }
    g->has_bounds = any;
    g->bounds_dirty = 0;
}

tl_result tl__scene_object_id(tl__device *dev, const tl__scene_gpu *g, uint32_t id, const char *call)
{
    if (!g->loaded) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: no scene (set_scene first)", call);
    if (id >= g->object_count || (g->object_state[id] & TL__OBJECT_REMOVED))
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: object %u %s", call, id,
                        id >= g->object_count ? "does not exist" : "was removed");
    return TL_OK;
}

tl_result tl__scene_set_transform(tl__device *dev, tl__scene_gpu *g, uint32_t id, const float transform[16])
{
    tl_result res = tl__scene_object_id(dev, g, id, "set_object_transform");
    if (res != TL_OK) return res;
    if (!transform) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: set_object_transform: no transform");
    int zero = 1;
    for (int k = 0; k < 16; k++) {
        if (!isfinite(transform[k]))
            return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT,
                            "renderer: set_object_transform: object %u: transform[%d] = %g: not finite", id, k,
                            (double)transform[k]);
        zero &= transform[k] == 0.0f;
    }
    tl_object *o = &g->objects[id];
    memcpy(o->transform, zero ? tl__identity : transform, sizeof o->transform);
    if (o->index_count) tl__box_transform(&g->object_local[id], o->transform, o->bounds_min, o->bounds_max);
    g->bounds_dirty = 1;
    return TL_OK;
}

tl_result tl__scene_set_visible(tl__device *dev, tl__scene_gpu *g, uint32_t id, int visible)
{
    tl_result res = tl__scene_object_id(dev, g, id, "set_object_visible");
    if (res != TL_OK) return res;
    uint8_t was = g->object_state[id];
    if (visible) g->object_state[id] &= (uint8_t)~TL__OBJECT_HIDDEN;
    else g->object_state[id] |= TL__OBJECT_HIDDEN;
    g->bounds_dirty |= was != g->object_state[id];
    return TL_OK;
}

/* The object-space box of the triangles first_index .. + count: a slot's that draws the same range,
 * else read back from the index and vertex buffers (once per new range). */
static tl_result tl__range_box(tl__device *dev, const tl__scene_gpu *g, uint32_t first, uint32_t count, tl__box *out)
{
    for (size_t i = 0; i < g->object_count; i++) {
        const tl_object *o = &g->objects[i];
        if (o->first_index == first && o->index_count == count && !(g->object_state[i] & TL__OBJECT_REMOVED)) {
            *out = g->object_local[i];
            return TL_OK;
        }
    }
    const GladGLContext *gl = &dev->gl;
    uint32_t *idx = (uint32_t *)tl__alloc_array(&dev->alloc, count, sizeof *idx);
    if (!idx) return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for %u indices' bounds", count);
    gl->GetNamedBufferSubData(g->ibo, (GLintptr)first * 4, (GLsizeiptr)count * 4, idx);
    uint32_t lo = UINT32_MAX, hi = 0;
    for (uint32_t i = 0; i < count; i++) {
        lo = idx[i] < lo ? idx[i] : lo;
        hi = idx[i] > hi ? idx[i] : hi;
    }
    size_t span = (size_t)hi - lo + 1;
    tl_vertex *v = (tl_vertex *)tl__alloc_array(&dev->alloc, span, sizeof *v);
    if (!v) {
        tl__free(&dev->alloc, idx);
        return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for %zu vertices' bounds", span);
    }
    gl->GetNamedBufferSubData(g->vbo, (GLintptr)(lo * sizeof *v), (GLsizeiptr)(span * sizeof *v), v);
    for (int k = 0; k < 3; k++) {
        out->min[k] = HUGE_VALF;
        out->max[k] = -HUGE_VALF;
    }
    for (uint32_t i = 0; i < count; i++) {
        const float *p = v[idx[i] - lo].position;
        for (int k = 0; k < 3; k++) {
            out->min[k] = p[k] < out->min[k] ? p[k] : out->min[k];
            out->max[k] = p[k] > out->max[k] ? p[k] : out->max[k];
        }
    }
    tl__free(&dev->alloc, v);
    tl__free(&dev->alloc, idx);
    return TL_OK;
}

/* A tl_object as given to set_object or add_object, checked against the scene on the GPU and
 * resolved: zero transform the identity, zero bounds from its box in object space. */
static tl_result tl__object_resolve(tl__device *dev, const tl__scene_gpu *g, const tl_object *in, const char *call,
                                    tl_object *out, tl__box *local)
{
    if (!in) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: no object", call);
    char msg[TL__CHECK_MESSAGE_SIZE];
    tl_result res = tl__object_check(in, "object", msg, sizeof msg);
    if (res != TL_OK) return tl__fail(dev, res, "renderer: %s: %s", call, msg);
    uint64_t end = (uint64_t)in->first_index + in->index_count;
    if (end > g->index_count)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT,
                        "renderer: %s: object.first_index + index_count = %u + %u = %llu: past the scene's %zu indices",
                        call, in->first_index, in->index_count, (unsigned long long)end, g->index_count);
    if (in->index_count % tl__primitive_indices(in->primitive))
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: object.index_count = %u: not whole %s (a multiple of %u)",
                        call, in->index_count, tl__primitive_name(in->primitive), tl__primitive_indices(in->primitive));
    if (in->material >= g->material_count && !(g->material_count == 0 && in->material == 0))
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: object.material = %u: past the scene's %zu "
                        "materials", call, in->material, g->material_count);
    *out = *in;
    if (tl__transform_is_zero(out->transform)) memcpy(out->transform, tl__identity, sizeof out->transform);
    memset(local, 0, sizeof *local);
    if (!in->index_count) {
        memset(out->bounds_min, 0, sizeof out->bounds_min);
        memset(out->bounds_max, 0, sizeof out->bounds_max);
        return TL_OK;
    }
    if ((res = tl__range_box(dev, g, in->first_index, in->index_count, local)) != TL_OK) return res;
    if (tl__bounds_are_zero(in)) tl__box_transform(local, out->transform, out->bounds_min, out->bounds_max);
    return TL_OK;
}

/* Puts `o` (resolved) in slot `id`, counting the materials' uses; returns whether the features changed. */
static int tl__slot_put(tl__scene_gpu *g, uint32_t id, const tl_object *o, const tl__box *local)
{
    tl_object *old = &g->objects[id];
    if (!(g->object_state[id] & TL__OBJECT_REMOVED)) tl__object_uses(g, old, -1);
    *old = *o;
    g->object_local[id] = *local;
    g->object_state[id] = 0;
    tl__object_uses(g, o, 1);
    g->bounds_dirty = 1;
    return tl__scene_features_refresh(g);
}

tl_result tl__scene_set_object(tl__device *dev, tl__scene_gpu *g, uint32_t id, const tl_object *o, int *replan)
{
    tl_result res = tl__scene_object_id(dev, g, id, "set_object");
    if (res != TL_OK) return res;
    tl_object resolved;
    tl__box local;
    if ((res = tl__object_resolve(dev, g, o, "set_object", &resolved, &local)) != TL_OK) return res;
    uint8_t hidden = g->object_state[id] & TL__OBJECT_HIDDEN; /* visibility is its own setter's */
    *replan = tl__slot_put(g, id, &resolved, &local);
    g->object_state[id] = hidden;
    return TL_OK;
}

/* Room for `need` slots: every per-slot array and the object-id buffer, doubled. */
static tl_result tl__objects_grow(tl__device *dev, tl__scene_gpu *g, size_t need)
{
    if (need <= g->object_capacity) return TL_OK;
    size_t limit = dev->lim.storage_max / sizeof(tl__object_gpu); /* the frame's per-object storage block */
    if (limit > UINT32_MAX) limit = UINT32_MAX;
    if (need > limit)
        return tl__fail(dev, TL_ERROR_LIMIT, "renderer: add_object: %zu objects exceed the limit of %zu", need, limit);
    size_t cap = g->object_capacity * 2 > need ? g->object_capacity * 2 : need;
    if (cap > limit) cap = limit;
    tl_allocator *a = &dev->alloc;
    struct { void **array; size_t size; } arrays[] = {
        {(void **)&g->objects, sizeof *g->objects},         {(void **)&g->object_state, sizeof *g->object_state},
        {(void **)&g->object_local, sizeof *g->object_local}, {(void **)&g->visible, sizeof *g->visible},
        {(void **)&g->draw_keys, sizeof *g->draw_keys},      {(void **)&g->free_slots, sizeof *g->free_slots},
    };
    enum { N = sizeof arrays / sizeof arrays[0] };
    void *fresh[N] = {0};
    uint32_t *ids = (uint32_t *)tl__alloc_array(a, cap, sizeof *ids);
    int ok = ids != NULL;
    for (size_t i = 0; i < N && ok; i++) ok = (fresh[i] = tl__calloc(a, cap, arrays[i].size)) != NULL;
    if (!ok) {
        for (size_t i = 0; i < N; i++) tl__free(a, fresh[i]);
        tl__free(a, ids);
        return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: add_object: out of memory for %zu objects", cap);
    }
    for (size_t i = 0; i < N; i++) {
        if (*arrays[i].array) memcpy(fresh[i], *arrays[i].array, g->object_capacity * arrays[i].size);
        tl__free(a, *arrays[i].array);
        *arrays[i].array = fresh[i];
    }
    for (size_t i = 0; i < cap; i++) ids[i] = (uint32_t)i;
    const GladGLContext *gl = &dev->gl;
    GLuint buffer = 0;
    gl->CreateBuffers(1, &buffer);
    gl->NamedBufferStorage(buffer, (GLsizeiptr)(cap * sizeof *ids), ids, 0);
    tl__gl_label(gl, GL_BUFFER, buffer, "buffer.object_ids");
    tl__free(a, ids);
    gl->DeleteBuffers(1, &g->vbo_object_ids);
    g->vbo_object_ids = buffer;
    if (g->vao) gl->VertexArrayVertexBuffer(g->vao, 1, buffer, 0, sizeof(uint32_t));
    g->object_capacity = cap;
    return TL_OK;
}

tl_result tl__scene_add_object(tl__device *dev, tl__scene_gpu *g, const tl_object *o, uint32_t *id, int *replan)
{
    if (!g->loaded) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: add_object: no scene (set_scene first)");
    if (!id) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: add_object: no place for the id");
    tl_object resolved;
    tl__box local;
    tl_result res = tl__object_resolve(dev, g, o, "add_object", &resolved, &local);
    if (res != TL_OK) return res;
    uint32_t slot;
    if (g->free_count) {
        slot = g->free_slots[--g->free_count];
    } else {
        if ((res = tl__objects_grow(dev, g, g->object_count + 1)) != TL_OK) return res;
        slot = (uint32_t)g->object_count++;
        g->object_state[slot] = TL__OBJECT_REMOVED; /* nothing counted for it yet */
    }
    *replan = tl__slot_put(g, slot, &resolved, &local);
    *id = slot;
    return TL_OK;
}

tl_result tl__scene_remove_object(tl__device *dev, tl__scene_gpu *g, uint32_t id, int *replan)
{
    tl_result res = tl__scene_object_id(dev, g, id, "remove_object");
    if (res != TL_OK) return res;
    if (!g->free_slots) { /* the scene's own slots: the list is made on the first removal */
        g->free_slots = (uint32_t *)tl__calloc(&dev->alloc, g->object_capacity, sizeof *g->free_slots);
        if (!g->free_slots) return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: remove_object: out of memory");
    }
    tl_object *o = &g->objects[id];
    tl__object_uses(g, o, -1);
    memset(o, 0, sizeof *o); /* no indices: never drawn, culled or lit */
    memcpy(o->transform, tl__identity, sizeof o->transform);
    g->object_state[id] = TL__OBJECT_REMOVED;
    g->free_slots[g->free_count++] = id;
    g->bounds_dirty = 1;
    *replan = tl__scene_features_refresh(g);
    return TL_OK;
}

/* A buffer of `capacity` bytes holding the first `keep` bytes of `old` (copied on the GPU). */
static GLuint tl__buffer_grown(const GladGLContext *gl, GLuint old, size_t keep, size_t capacity, const char *label)
{
    GLuint b = 0;
    gl->CreateBuffers(1, &b);
    gl->NamedBufferStorage(b, (GLsizeiptr)capacity, NULL, GL_DYNAMIC_STORAGE_BIT);
    if (keep) gl->CopyNamedBufferSubData(old, b, 0, 0, (GLsizeiptr)keep);
    tl__gl_label(gl, GL_BUFFER, b, label);
    return b;
}

/* The scene's colour and second-UV buffers (when it has them) follow appended vertices: white, and
 * the vertices' own uv (tl_scene.colors and uv1 say what a vertex without them reads). */
static tl_result tl__extras_append(tl__device *dev, tl__scene_gpu *g, const tl_vertex *vertices, size_t n, size_t cap)
{
    const GladGLContext *gl = &dev->gl;
    struct { GLuint *buffer; size_t floats; const char *label; } x[2] = {{&g->vbo_colors, 4, "buffer.colors"},
                                                                        {&g->vbo_uv1, 2, "buffer.uv1"}};
    for (int k = 0; k < 2; k++) {
        if (!*x[k].buffer || !n) continue;
        size_t bytes = x[k].floats * sizeof(float);
        float *data = (float *)tl__alloc_array(&dev->alloc, n, bytes);
        if (!data) return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: add_geometry: out of memory");
        for (size_t i = 0; i < n; i++)
            for (size_t c = 0; c < x[k].floats; c++) data[i * x[k].floats + c] = k == 0 ? 1.0f : vertices[i].uv[c];
        if (cap != g->vertex_capacity) {
            GLuint b = tl__buffer_grown(gl, *x[k].buffer, g->vertex_count * bytes, cap * bytes, x[k].label);
            gl->DeleteBuffers(1, x[k].buffer);
            *x[k].buffer = b;
            if (g->vao) gl->VertexArrayVertexBuffer(g->vao, 2 + (GLuint)k, b, 0, (GLsizei)bytes);
        }
        gl->NamedBufferSubData(*x[k].buffer, (GLintptr)(g->vertex_count * bytes), (GLsizeiptr)(n * bytes), data);
        tl__free(&dev->alloc, data);
    }
    return TL_OK;
}

tl_result tl__scene_add_geometry(tl__device *dev, tl__scene_gpu *g, const tl_vertex *vertices, size_t vertex_count,
                                 const uint32_t *indices, size_t index_count, uint32_t *first_index)
{
    const char *call = "add_geometry";
    if (!g->loaded) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: no scene (set_scene first)", call);
    if (!first_index || (vertex_count && !vertices) || (index_count && !indices))
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: %s", call,
                        !first_index ? "no place for the first index" : "a count without its array");
    if (index_count % 3)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: %zu indices are not whole triangles", call,
                        index_count);
    if (vertex_count > UINT32_MAX - g->vertex_count || index_count > TL__MAX_SCENE_INDICES - g->index_count)
        return tl__fail(dev, TL_ERROR_LIMIT, "renderer: %s: %zu vertices and %zu indices more exceed the scene's limits "
                        "(%u vertices, %zu indices)", call, vertex_count, index_count, UINT32_MAX,
                        (size_t)TL__MAX_SCENE_INDICES);
    for (size_t i = 0; i < index_count; i++)
        if (indices[i] >= vertex_count)
            return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: indices[%zu] = %u: past the %zu vertices "
                            "given (indices count from the first of them)", call, i, indices[i], vertex_count);
    for (size_t i = 0; i < vertex_count; i++) {
        const float *p = vertices[i].position;
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
            return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: vertices[%zu].position: not finite", call, i);
    }
    uint32_t *shifted = (uint32_t *)tl__alloc_array(&dev->alloc, index_count ? index_count : 1, sizeof *shifted);
    if (!shifted) return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: %s: out of memory", call);
    for (size_t i = 0; i < index_count; i++) shifted[i] = indices[i] + (uint32_t)g->vertex_count;
    const GladGLContext *gl = &dev->gl;
    size_t vb = sizeof(tl_vertex);
    size_t cap = g->vertex_capacity;
    if (g->vertex_count + vertex_count > g->vertex_capacity) { /* grown by half: appends cost their own bytes */
        cap = g->vertex_count + vertex_count + (g->vertex_count + vertex_count) / 2;
        if (cap > UINT32_MAX) cap = UINT32_MAX;
    }
    tl_result res = tl__extras_append(dev, g, vertices, vertex_count, cap);
    if (res != TL_OK) {
        tl__free(&dev->alloc, shifted);
        return res;
    }
    if (cap != g->vertex_capacity) {
        GLuint b = tl__buffer_grown(gl, g->vbo, g->vertex_count * vb, cap * vb, "buffer.vertices");
        gl->DeleteBuffers(1, &g->vbo);
        g->vbo = b;
        g->vertex_capacity = cap;
        if (g->vao) gl->VertexArrayVertexBuffer(g->vao, 0, g->vbo, 0, sizeof(tl_vertex));
    }
    if (g->index_count + index_count > g->index_capacity) {
        size_t icap = g->index_count + index_count + (g->index_count + index_count) / 2;
        if (icap > TL__MAX_SCENE_INDICES) icap = TL__MAX_SCENE_INDICES;
        GLuint b = tl__buffer_grown(gl, g->ibo, g->index_count * 4u, icap * 4u, "buffer.indices");
        gl->DeleteBuffers(1, &g->ibo);
        g->ibo = b;
        g->index_capacity = icap;
        if (g->vao) gl->VertexArrayElementBuffer(g->vao, g->ibo);
    }
    if (vertex_count)
        gl->NamedBufferSubData(g->vbo, (GLintptr)(g->vertex_count * vb), (GLsizeiptr)(vertex_count * vb), vertices);
    if (index_count)
        gl->NamedBufferSubData(g->ibo, (GLintptr)(g->index_count * 4u), (GLsizeiptr)(index_count * 4u), shifted);
    tl__free(&dev->alloc, shifted);
    *first_index = (uint32_t)g->index_count;
    g->vertex_count += vertex_count;
    g->index_count += index_count;
    g->features.triangle_count = g->index_count / 3;
    return TL_OK;
}
