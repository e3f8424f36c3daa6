/* Scene upload: validation, geometry buffers, the per-object instance ids, textures (sRGB or linear
 * by use), the materials' uniform blocks. The renderer plans the frame afterwards. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "lights.h"
#include "scene_gpu.h"

_Static_assert(TL__MATERIAL_TEXTURES == TL__MATERIAL_TEXTURE_SLOTS, "one texture unit per material texture slot");

void tl__scene_release(tl__device *dev, tl__scene_gpu *g)
{
    const GladGLContext *gl = &dev->gl;
    GLuint buffers[6] = {g->vbo, g->ibo, g->vbo_object_ids, g->ubo_materials, g->vbo_colors, g->vbo_uv1};
    for (int i = 0; i < 6; i++)
        if (buffers[i]) gl->DeleteBuffers(1, &buffers[i]);
    if (g->vao) gl->DeleteVertexArrays(1, &g->vao);
    for (size_t i = 0; i < g->texture_count; i++) {
        if (g->tex_srgb && g->tex_srgb[i]) gl->DeleteTextures(1, &g->tex_srgb[i]);
        if (g->tex_linear && g->tex_linear[i]) gl->DeleteTextures(1, &g->tex_linear[i]);
    }
    void *arrays[] = {g->tex_srgb,     g->tex_linear,   g->objects,       g->materials,
                      g->visible,      g->draw_keys,    g->object_state,  g->object_local,
                      g->material_uses, g->material_features, g->free_slots};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) tl__free(&dev->alloc, arrays[i]);
    memset(g, 0, sizeof *g);
}

/* The vertex array binds only the attributes the plan needs, plus the object id (location 4, one
 * per instance: draw i uses base instance i); vertex colours (location 5) and the second UV set
 * (location 6) come from their own buffers (bindings 2 and 3). */
void tl__scene_vao(tl__device *dev, tl__scene_gpu *g, uint32_t attributes)
{
    if (!g->vbo || (g->vao && g->vao_attributes == attributes)) return;
    const GladGLContext *gl = &dev->gl;
    if (g->vao) gl->DeleteVertexArrays(1, &g->vao);
    gl->CreateVertexArrays(1, &g->vao);
    gl->VertexArrayVertexBuffer(g->vao, 0, g->vbo, 0, sizeof(tl_vertex));
    gl->VertexArrayElementBuffer(g->vao, g->ibo);
    const GLuint offs[4] = {offsetof(tl_vertex, position), offsetof(tl_vertex, normal), offsetof(tl_vertex, uv),
                            offsetof(tl_vertex, tangent)};
    const GLint sizes[4] = {3, 3, 2, 4};
    for (GLuint a = 0; a < 4; a++) {
        if (!(attributes & (1u << a))) continue;
        gl->EnableVertexArrayAttrib(g->vao, a);
        gl->VertexArrayAttribFormat(g->vao, a, sizes[a], GL_FLOAT, GL_FALSE, offs[a]);
        gl->VertexArrayAttribBinding(g->vao, a, 0);
    }
    const struct { uint32_t bit; GLuint buffer; GLint size; } extra[2] = {
        {TL_ATTRIBUTE_COLOR, g->vbo_colors, 4}, {TL_ATTRIBUTE_UV1, g->vbo_uv1, 2}};
    for (GLuint k = 0; k < 2; k++) {
        if (!(attributes & extra[k].bit) || !extra[k].buffer) continue;
        gl->VertexArrayVertexBuffer(g->vao, 2 + k, extra[k].buffer, 0, (GLsizei)(extra[k].size * sizeof(float)));
        gl->EnableVertexArrayAttrib(g->vao, 5 + k);
        gl->VertexArrayAttribFormat(g->vao, 5 + k, extra[k].size, GL_FLOAT, GL_FALSE, 0);
        gl->VertexArrayAttribBinding(g->vao, 5 + k, 2 + k);
    }
    gl->VertexArrayVertexBuffer(g->vao, 1, g->vbo_object_ids, 0, sizeof(uint32_t));
    gl->VertexArrayBindingDivisor(g->vao, 1, 1);
    gl->EnableVertexArrayAttrib(g->vao, 4);
    gl->VertexArrayAttribIFormat(g->vao, 4, 1, GL_UNSIGNED_INT, 0);
    gl->VertexArrayAttribBinding(g->vao, 4, 1);
    tl__gl_label(gl, GL_VERTEX_ARRAY, g->vao, "vao.scene");
    g->vao_attributes = attributes;
}

/* Counts past what 32-bit indices, GL sizes and the light buffers take: checked before any array is
 * read (the renderer trusts an array to hold its count, not the count to be sane). */
static tl_result tl__scene_counts(tl__device *r, const tl_scene *s)
{
    const struct { size_t count, limit; const char *what; } c[] = {
        {s->vertex_count, UINT32_MAX, "vertices (indices are 32-bit)"},
        {s->vertex_count, (size_t)PTRDIFF_MAX / sizeof(tl_vertex), "vertices (their bytes overflow GLsizeiptr)"},
        {s->index_count, TL__MAX_SCENE_INDICES, "indices (a 2 GiB index buffer)"},
        {s->object_count, UINT32_MAX, "objects"},
        {s->material_count, UINT32_MAX, "materials"},
        {s->texture_count, UINT32_MAX, "textures (materials name texture i as map i + 1, a uint32_t)"},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++)
        if (c[i].count > c[i].limit)
            return tl__fail(r, TL_ERROR_LIMIT, "renderer: %zu %s exceed the limit of %zu", c[i].count, c[i].what,
                            c[i].limit);
    size_t max_objects = r->lim.storage_max / sizeof(tl__object_gpu); /* the frame's per-object storage block */
    if (s->object_count > max_objects)
        return tl__fail(r, TL_ERROR_LIMIT,
                        "renderer: %zu objects exceed the limit of %zu (a storage block of %zu bytes at %zu bytes an "
                        "object)", s->object_count, max_objects, r->lim.storage_max, sizeof(tl__object_gpu));
    const struct { size_t count; const void *array; const char *what; } a[] = {
        {s->vertex_count, s->vertices, "vertices"}, {s->index_count, s->indices, "indices"},
        {s->object_count, s->objects, "objects"},   {s->material_count, s->materials, "materials"},
        {s->texture_count, s->textures, "textures"},
    };
    for (size_t i = 0; i < sizeof a / sizeof a[0]; i++)
        if (a[i].count && !a[i].array)
            return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: %zu %s but no array", a[i].count, a[i].what);
    return TL_OK;
}

/* Textures (sizes against this context's GL_MAX_TEXTURE_SIZE, pixels present) and the materials'
 * indices into them, as scene/validate.h checks them for the loader too. */
static tl_result tl__scene_parts(tl__device *r, const tl_scene *s)
{
    char what[48], msg[TL__CHECK_MESSAGE_SIZE];
    tl_result res;
    for (size_t i = 0; i < s->texture_count; i++) {
        snprintf(what, sizeof what, "textures[%zu]", i);
        if ((res = tl__texture_check(&s->textures[i], what, (uint32_t)r->lim.max_texture_size, msg, sizeof msg)) != TL_OK)
            return tl__fail(r, res, "renderer: %s", msg);
    }
    for (size_t i = 0; i < s->material_count; i++) {
        snprintf(what, sizeof what, "materials[%zu]", i);
        if ((res = tl__material_check(&s->materials[i], what, s->texture_count, msg, sizeof msg)) != TL_OK)
            return tl__fail(r, res, "renderer: %s", msg);
    }
    return TL_OK;
}

tl_result tl__scene_camera(tl__device *r, const tl_scene *s, tl_depth_format depth, tl__scene_frame *out)
{
    out->has_bounds = tl__scene_objects_bounds(s, out->bounds_min, out->bounds_max); /* zero bounds computed */
    tl_result res = tl__camera_resolve(&s->camera, "scene.camera", depth,
                                       out->has_bounds ? out->bounds_min : NULL, out->has_bounds ? out->bounds_max : NULL,
                                       &out->camera, out->warning, sizeof out->warning);
    if (res != TL_OK) return tl__fail(r, res, "renderer: %s", out->warning);
    if (!out->camera.near_raised) out->warning[0] = '\0';
    return TL_OK;
}

/* Object i: its index range, its material, its own fields, whole primitives; each refusal names
 * the one field that fails. */
static tl_result tl__scene_object_check(tl__device *r, const tl_scene *s, size_t i)
{
    const tl_object *o = &s->objects[i];
    uint64_t end = (uint64_t)o->first_index + o->index_count;
    if (end > s->index_count)
        return tl__fail(r, TL_ERROR_INVALID_ARGUMENT,
                        "renderer: objects[%zu].first_index + index_count = %u + %u = %llu: past the scene's %zu indices",
                        i, o->first_index, o->index_count, (unsigned long long)end, s->index_count);
    if (o->material >= s->material_count && !(s->material_count == 0 && o->material == 0))
        return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: objects[%zu].material = %u: past the scene's %zu materials",
                        i, o->material, s->material_count);
    char what[32], msg[TL__CHECK_MESSAGE_SIZE];
    snprintf(what, sizeof what, "objects[%zu]", i);
    tl_result res = tl__object_check(o, what, msg, sizeof msg);
    if (res != TL_OK) return tl__fail(r, res, "renderer: %s", msg);
    uint32_t per = tl__primitive_indices(o->primitive);
    if (o->index_count % per)
        return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: objects[%zu].index_count = %u: not whole %s (a multiple of %u)",
                        i, o->index_count, tl__primitive_name(o->primitive), per);
    return TL_OK;
}

tl_result tl__scene_validate(tl__device *r, const tl_scene *s)
{
    tl_result res = tl__scene_counts(r, s);
    if (res != TL_OK) return res;
    if ((res = tl__lights_count_check(r, s->light_count)) != TL_OK) return res;
    for (size_t i = 0; i < s->object_count; i++)
        if ((res = tl__scene_object_check(r, s, i)) != TL_OK) return res;
    for (size_t i = 0; i < s->index_count; i++)
        if (s->indices[i] >= s->vertex_count)
            return tl__fail(r, TL_ERROR_INVALID_ARGUMENT,
                            "renderer: indices[%zu] = %u: past the scene's %zu vertices (0..%zu)", i, s->indices[i],
                            s->vertex_count, s->vertex_count ? s->vertex_count - 1 : 0);
    for (size_t i = 0; i < s->vertex_count; i++) {
        const float *p = s->vertices[i].position;
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
            return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: vertices[%zu].position = (%g, %g, %g): not finite",
                            i, (double)p[0], (double)p[1], (double)p[2]);
    }
    /* NaN in a vertex colour or the second UV set would reach every target it shades */
    const struct { const float *v; size_t n; const char *what; } extra[2] = {{s->colors, 4, "colors"}, {s->uv1, 2, "uv1"}};
    for (int a = 0; a < 2; a++)
        for (size_t i = 0; extra[a].v && i < s->vertex_count * extra[a].n; i++)
            if (!isfinite(extra[a].v[i]))
                return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: %s[%zu] = %g: not finite (vertex %zu)",
                                extra[a].what, i, (double)extra[a].v[i], i / extra[a].n);
    return tl__scene_parts(r, s);
}

static void tl__texture_sampling(const GladGLContext *gl, GLuint id, const char *label)
{
    gl->GenerateTextureMipmap(id);
    gl->TextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl->TextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl->TextureParameteri(id, GL_TEXTURE_WRAP_T, GL_REPEAT);
    tl__gl_label(gl, GL_TEXTURE, id, label);
}

static GLuint tl__texture_storage(const GladGLContext *gl, uint32_t width, uint32_t height, int srgb)
{
    GLuint id;
    gl->CreateTextures(GL_TEXTURE_2D, 1, &id);
    uint32_t levels = 1, m = width > height ? width : height;
    while (m >>= 1) levels++;
    gl->TextureStorage2D(id, (GLsizei)levels, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, (GLsizei)width, (GLsizei)height);
    return id;
}

/* A texture tl__scene_parts accepted. */
static GLuint tl__upload_texture(tl__device *dev, const tl_texture *tx, int srgb)
{
    const GladGLContext *gl = &dev->gl;
    GLuint id = tl__texture_storage(gl, tx->width, tx->height, srgb);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    /* rows top to bottom with uv (0,0) at the top-left, as glTF: upload as is, v samples downward */
    gl->TextureSubImage2D(id, 0, 0, 0, (GLsizei)tx->width, (GLsizei)tx->height, GL_RGBA, GL_UNSIGNED_BYTE, tx->rgba);
    tl__texture_sampling(gl, id, tx->name[0] ? tx->name : "texture");
    return id;
}

static GLuint tl__slot_texture(tl__device *dev, tl__scene_gpu *g, const tl_scene *s, uint32_t index, int srgb)
{
    if (index == TL__NO_TEXTURE) return 0;
    GLuint *slot = srgb ? &g->tex_srgb[index] : &g->tex_linear[index];
    if (!*slot) *slot = tl__upload_texture(dev, &s->textures[index], srgb);
    return *slot;
}

/* A scene texture after set_scene, when the pixels are the caller's no longer: as uploaded, or its
 * bytes copied on the GPU from the other colour space's upload (sRGB and linear RGBA8 share them);
 * 0 when no material used it at set_scene. */
static GLuint tl__kept_texture(tl__device *dev, tl__scene_gpu *g, uint32_t index, int srgb)
{
    GLuint *slot = srgb ? &g->tex_srgb[index] : &g->tex_linear[index];
    GLuint other = srgb ? g->tex_linear[index] : g->tex_srgb[index];
    if (*slot || !other) return *slot;
    const GladGLContext *gl = &dev->gl;
    GLint w = 0, h = 0;
    gl->GetTextureLevelParameteriv(other, 0, GL_TEXTURE_WIDTH, &w);
    gl->GetTextureLevelParameteriv(other, 0, GL_TEXTURE_HEIGHT, &h);
    *slot = tl__texture_storage(gl, (uint32_t)w, (uint32_t)h, srgb);
    gl->CopyImageSubData(other, GL_TEXTURE_2D, 0, 0, 0, 0, *slot, GL_TEXTURE_2D, 0, 0, 0, 0, w, h, 1);
    tl__texture_sampling(gl, *slot, "texture");
    return *slot;
}

static void tl__material_record(const tl_material *m, int texture_mask, uint32_t index, tl__material_ubo *u)
{
    memset(u, 0, sizeof *u);
    memcpy(u->albedo, m->albedo, sizeof u->albedo);
    memcpy(u->specular, m->specular, sizeof u->specular);
    memcpy(u->emissive, m->emissive, sizeof u->emissive);
    u->gloss = m->gloss;
    u->alpha = (m->flags & (TL_MATERIAL_ALPHA_MASK | TL_MATERIAL_ALPHA_BLEND)) ? m->alpha : 1.0f;
    u->alpha_cutoff = m->alpha_cutoff;
    u->metallic = m->metallic;
    u->roughness = m->roughness;
    u->normal_scale = m->normal_scale != 0.0f ? m->normal_scale : 1.0f;
    u->occlusion_strength = m->occlusion_strength != 0.0f ? m->occlusion_strength : 1.0f;
    u->flags = (int32_t)m->flags;
    u->texture_mask = texture_mask;
    u->uv1_mask = (int32_t)(m->uv1_maps & (uint32_t)texture_mask);
    u->model = (int32_t)m->model;
    memcpy(u->dielectric_f0, m->dielectric_f0, sizeof u->dielectric_f0);
    memcpy(u->sheen_color, m->sheen_color, sizeof u->sheen_color);
    u->clearcoat = m->clearcoat;
    u->clearcoat_roughness = m->clearcoat_roughness;
    u->sheen_roughness = m->sheen_roughness;
    u->wrap = m->wrap;
    u->toon_steps = (float)m->toon_steps;
    u->index = index; /* visibility's resolve: the pixels of this material */
}

/* Textures and one std140 record per material (a scene without materials: the zeroed one), with
 * their zero defaults resolved, in one immutable uniform buffer. */
static tl_result tl__upload_materials(tl__device *dev, tl__scene_gpu *g, const tl_scene *s)
{
    size_t n = s->material_count ? s->material_count : 1, align = dev->lim.ubo_align;
    g->material_stride = (sizeof(tl__material_ubo) + align - 1) / align * align;
    uint8_t *records = (uint8_t *)tl__calloc(&dev->alloc, n, g->material_stride);
    if (!records) return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for %zu materials", n);
    for (size_t i = 0; i < n; i++) {
        tl_material resolved;
        tl__material_defaults(s->material_count ? &s->materials[i] : &(tl_material){0}, &resolved);
        const tl_material *m = &resolved;
        int mask = 0;
        g->materials[i].flags = m->flags;
        g->materials[i].model = m->model;
        for (int k = 0; k < TL__MATERIAL_TEXTURES; k++) {
            g->materials[i].textures[k] =
                tl__slot_texture(dev, g, s, tl__material_texture(m, k), tl__material_texture_slots[k].srgb);
            if (g->materials[i].textures[k]) mask |= 1 << k;
        }
        tl__material_record(m, mask, (uint32_t)i, (tl__material_ubo *)(records + i * g->material_stride));
    }
    const GladGLContext *gl = &dev->gl;
    gl->CreateBuffers(1, &g->ubo_materials);
    gl->NamedBufferStorage(g->ubo_materials, (GLsizeiptr)(n * g->material_stride), records, GL_DYNAMIC_STORAGE_BIT);
    tl__gl_label(gl, GL_BUFFER, g->ubo_materials, "buffer.materials");
    tl__free(&dev->alloc, records);
    g->material_count = s->material_count;
    g->material_capacity = n;
    return TL_OK;
}

static GLuint tl__static_buffer(const GladGLContext *gl, size_t bytes, const void *data, const char *label)
{
    GLuint b = 0;
    gl->CreateBuffers(1, &b);
    gl->NamedBufferStorage(b, (GLsizeiptr)(bytes ? bytes : 16), bytes ? data : NULL, 0);
    tl__gl_label(gl, GL_BUFFER, b, label);
    return b;
}

/* tl_renderer_options.ambient: all zero keeps the scene's; otherwise it replaces it, negative = 0. */
void tl__ambient_resolve(const float options[3], const float scene[3], float out[3])
{
    int set = options[0] != 0.0f || options[1] != 0.0f || options[2] != 0.0f;
    for (int k = 0; k < 3; k++) out[k] = !set ? scene[k] : options[k] < 0.0f ? 0.0f : options[k];
}

tl_result tl__scene_upload(tl__device *dev, tl__scene_gpu *g, const tl_scene *s)
{
    tl_allocator *a = &dev->alloc;
    size_t no = s->object_count ? s->object_count : 1, nt = s->texture_count ? s->texture_count : 1;
    size_t nm = s->material_count ? s->material_count : 1;
    g->objects = (tl_object *)tl__alloc_array(a, no, sizeof *g->objects);
    g->materials = (tl__gpu_material *)tl__calloc(a, nm, sizeof *g->materials);
    g->tex_srgb = (GLuint *)tl__calloc(a, nt, sizeof(GLuint));
    g->tex_linear = (GLuint *)tl__calloc(a, nt, sizeof(GLuint));
    g->visible = (uint32_t *)tl__alloc_array(a, no, sizeof(uint32_t));
    g->draw_keys = (float *)tl__alloc_array(a, no, sizeof(float));
    g->object_state = (uint8_t *)tl__calloc(a, no, 1);
    g->object_local = (tl__box *)tl__alloc_array(a, no, sizeof *g->object_local);
    g->material_uses = (uint32_t *)tl__calloc(a, nm, sizeof *g->material_uses);
    g->material_features = (tl_scene_feature_set *)tl__calloc(a, nm, sizeof *g->material_features);
    uint32_t *ids = (uint32_t *)tl__alloc_array(a, no, sizeof(uint32_t));
    if (!g->objects || !g->materials || !g->tex_srgb || !g->tex_linear || !g->visible || !g->draw_keys ||
        !g->object_state || !g->object_local || !g->material_uses || !g->material_features || !ids) {
        tl__free(a, ids);
        tl__scene_release(dev, g);
        return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for the scene");
    }
    if (s->object_count) memcpy(g->objects, s->objects, s->object_count * sizeof *g->objects);
    for (size_t i = 0; i < s->object_count; i++) tl__object_defaults(s, &g->objects[i]); /* zero: identity, computed */
    g->object_count = s->object_count;
    g->object_capacity = no;
    g->texture_count = s->texture_count;
    g->texture_capacity = nt;
    tl_result res = tl__upload_materials(dev, g, s);
    if (res != TL_OK) {
        tl__free(a, ids);
        tl__scene_release(dev, g);
        return res;
    }
    tl__scene_objects_init(g, s);
    const GladGLContext *gl = &dev->gl;
    for (size_t i = 0; i < no; i++) ids[i] = (uint32_t)i;
    g->vbo = tl__static_buffer(gl, s->vertex_count * sizeof(tl_vertex), s->vertices, "buffer.vertices");
    g->ibo = tl__static_buffer(gl, s->index_count * 4u, s->indices, "buffer.indices");
    g->vbo_object_ids = tl__static_buffer(gl, no * sizeof(uint32_t), ids, "buffer.object_ids");
    if (s->colors) g->vbo_colors = tl__static_buffer(gl, s->vertex_count * 16u, s->colors, "buffer.colors");
    if (s->uv1) g->vbo_uv1 = tl__static_buffer(gl, s->vertex_count * 8u, s->uv1, "buffer.uv1");
    tl__free(a, ids);
    g->vertex_count = g->vertex_capacity = s->vertex_count;
    g->index_count = g->index_capacity = s->index_count;
    g->camera = s->camera;
    memcpy(g->ambient, s->ambient, sizeof g->ambient);
    tl_scene_features(s, &g->features);
    g->loaded = 1;
    return TL_OK;
}

void tl__scene_take_frame(tl__device *dev, tl__scene_gpu *g, const tl__scene_frame *f)
{
    memcpy(g->bounds_min, f->bounds_min, sizeof g->bounds_min);
    memcpy(g->bounds_max, f->bounds_max, sizeof g->bounds_max);
    g->has_bounds = f->has_bounds;
    g->frame_camera = f->camera;
    g->warned = f->warning[0] ? TL__WARNED_NEAR : 0;
    if (f->warning[0]) tl__log_message(&dev->log, TL_LOG_WARNING, "renderer: %s", f->warning);
}

/* Checks `m` as material `what` and writes it into record `index` (the buffer holds it): its textures
 * as the renderer keeps them, its std140 record, its flags, model and features. On failure nothing
 * that a frame draws changes (a linear copy of a kept texture may stay made, for a later use). */
static tl_result tl__material_write(tl__device *dev, tl__scene_gpu *g, uint32_t index, const tl_material *m,
                                    const char *call, const char *what)
{
    char msg[TL__CHECK_MESSAGE_SIZE];
    tl_result res = tl__material_check(m, what, g->texture_count, msg, sizeof msg);
    if (res != TL_OK) return tl__fail(dev, res, "renderer: %s: %s", call, msg);
    tl_material resolved;
    tl__material_defaults(m, &resolved);
    GLuint textures[TL__MATERIAL_TEXTURES] = {0};
    int mask = 0;
    for (int k = 0; k < TL__MATERIAL_TEXTURES; k++) {
        uint32_t t = tl__material_texture(&resolved, k);
        if (t == TL__NO_TEXTURE) continue;
        textures[k] = tl__kept_texture(dev, g, t, tl__material_texture_slots[k].srgb);
        if (!textures[k])
            return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT,
                            "renderer: %s: %s.%s names texture %u, which no material used at set_scene: the renderer "
                            "kept no copy of it (name it in some material of the scene to keep it, or give it again "
                            "with tl_renderer_add_texture)",
                            call, what, tl__material_texture_slots[k].name, t);
        mask |= 1 << k;
    }
    tl__material_ubo record;
    tl__material_record(&resolved, mask, index, &record);
    dev->gl.NamedBufferSubData(g->ubo_materials, (GLintptr)(index * g->material_stride), (GLsizeiptr)sizeof record,
                               &record);
    g->materials[index].flags = resolved.flags;
    g->materials[index].model = resolved.model;
    memcpy(g->materials[index].textures, textures, sizeof textures);
    g->material_features[index] = (tl_scene_feature_set){0};
    tl__material_features(m, g->texture_count, &g->material_features[index]);
    return TL_OK;
}

tl_result tl__scene_set_material(tl__device *dev, tl__scene_gpu *g, uint32_t index, const tl_material *m, int *replan)
{
    const char *call = "set_material";
    if (!g->loaded) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: no scene (set_scene first)", call);
    if (!m) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: no material", call);
    if (index >= g->material_count)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: material %u: past the scene's %zu materials",
                        call, index, g->material_count);
    char what[48];
    snprintf(what, sizeof what, "materials[%u]", index);
    tl_result res = tl__material_write(dev, g, index, m, call, what);
    if (res != TL_OK) return res;
    *replan = tl__scene_features_refresh(g);
    return TL_OK;
}

/* Room for `need` materials: the per-material arrays and the uniform buffer of their records, whose
 * contents are copied on the GPU; doubled. */
static tl_result tl__materials_grow(tl__device *dev, tl__scene_gpu *g, size_t need)
{
    if (need <= g->material_capacity) return TL_OK;
    size_t cap = g->material_capacity * 2 > need ? g->material_capacity * 2 : need, old = g->material_capacity;
    tl_allocator *a = &dev->alloc;
    tl__gpu_material *materials = (tl__gpu_material *)tl__calloc(a, cap, sizeof *materials);
    uint32_t *uses = (uint32_t *)tl__calloc(a, cap, sizeof *uses);
    tl_scene_feature_set *features = (tl_scene_feature_set *)tl__calloc(a, cap, sizeof *features);
    if (!materials || !uses || !features) {
        tl__free(a, materials);
        tl__free(a, uses);
        tl__free(a, features);
        return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: add_material: out of memory for %zu materials", cap);
    }
    memcpy(materials, g->materials, old * sizeof *materials);
    memcpy(uses, g->material_uses, old * sizeof *uses);
    memcpy(features, g->material_features, old * sizeof *features);
    tl__free(a, g->materials);
    tl__free(a, g->material_uses);
    tl__free(a, g->material_features);
    g->materials = materials;
    g->material_uses = uses;
    g->material_features = features;
    const GladGLContext *gl = &dev->gl;
    GLuint b = 0;
    gl->CreateBuffers(1, &b);
    gl->NamedBufferStorage(b, (GLsizeiptr)(cap * g->material_stride), NULL, GL_DYNAMIC_STORAGE_BIT);
    gl->CopyNamedBufferSubData(g->ubo_materials, b, 0, 0, (GLsizeiptr)(old * g->material_stride));
    tl__gl_label(gl, GL_BUFFER, b, "buffer.materials");
    gl->DeleteBuffers(1, &g->ubo_materials);
    g->ubo_materials = b;
    g->material_capacity = cap;
    return TL_OK;
}

tl_result tl__scene_add_material(tl__device *dev, tl__scene_gpu *g, const tl_material *m, uint32_t *index, int *replan)
{
    const char *call = "add_material";
    if (!g->loaded) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: no scene (set_scene first)", call);
    if (!m || !index)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: %s", call,
                        !m ? "no material" : "no place for the index");
    /* a scene without materials draws the zeroed material as material 0: it becomes one, the first
     * added is 1, and the objects drawing material 0 still draw the grey one */
    size_t at = g->material_count ? g->material_count : 1;
    if (at >= UINT32_MAX)
        return tl__fail(dev, TL_ERROR_LIMIT, "renderer: %s: %zu materials: the limit (tl_object.material is 32-bit)",
                        call, at);
    tl_result res = tl__materials_grow(dev, g, at + 1);
    if (res == TL_OK) res = tl__material_write(dev, g, (uint32_t)at, m, call, "material");
    if (res != TL_OK) return res;
    if (!g->material_count) tl__material_features(&(tl_material){0}, g->texture_count, &g->material_features[0]);
    g->material_count = at + 1;
    *index = (uint32_t)at;
    *replan = tl__scene_features_refresh(g);
    return TL_OK;
}

tl_result tl__scene_add_texture(tl__device *dev, tl__scene_gpu *g, const tl_texture *t, uint32_t *index)
{
    const char *call = "add_texture";
    if (!g->loaded) return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: no scene (set_scene first)", call);
    if (!t || !index)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: %s: %s", call,
                        !t ? "no texture" : "no place for the index");
    if (g->texture_count >= UINT32_MAX) /* a map is the index + 1, a uint32_t */
        return tl__fail(dev, TL_ERROR_LIMIT, "renderer: %s: %zu textures: the limit (maps are index + 1, 32-bit)",
                        call, g->texture_count);
    char msg[TL__CHECK_MESSAGE_SIZE];
    tl_result res = tl__texture_check(t, "texture", (uint32_t)dev->lim.max_texture_size, msg, sizeof msg);
    if (res != TL_OK) return tl__fail(dev, res, "renderer: %s: %s", call, msg);
    if (g->texture_count >= g->texture_capacity) {
        size_t cap = g->texture_capacity * 2 > g->texture_count + 1 ? g->texture_capacity * 2 : g->texture_count + 1;
        GLuint *srgb = (GLuint *)tl__calloc(&dev->alloc, cap, sizeof *srgb);
        GLuint *linear = (GLuint *)tl__calloc(&dev->alloc, cap, sizeof *linear);
        if (!srgb || !linear) {
            tl__free(&dev->alloc, srgb);
            tl__free(&dev->alloc, linear);
            return tl__fail(dev, TL_ERROR_OUT_OF_MEMORY, "renderer: %s: out of memory for %zu textures", call, cap);
        }
        memcpy(srgb, g->tex_srgb, g->texture_count * sizeof *srgb);
        memcpy(linear, g->tex_linear, g->texture_count * sizeof *linear);
        tl__free(&dev->alloc, g->tex_srgb);
        tl__free(&dev->alloc, g->tex_linear);
        g->tex_srgb = srgb;
        g->tex_linear = linear;
        g->texture_capacity = cap;
    }
    /* the pixels are the caller's only during the call: kept as sRGB (colour maps are the common
     * use), the linear twin copied from it on the GPU by tl__kept_texture when a material needs it */
    g->tex_srgb[g->texture_count] = tl__upload_texture(dev, t, 1);
    g->tex_linear[g->texture_count] = 0;
    *index = (uint32_t)g->texture_count++;
    return TL_OK;
}
