/* Scene upload: validation, geometry buffers, the per-object instance ids, textures (sRGB or linear
 * by use), the materials' uniform blocks, lights. The renderer plans the frame afterwards. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "renderer_internal.h"
#include "scene_upload.h"

_Static_assert(TL__MATERIAL_TEXTURES == TL__MATERIAL_TEXTURE_SLOTS, "one texture unit per material texture slot");

void tl__scene_release(tl_renderer *r)
{
    const GladGLContext *gl = &r->gl;
    GLuint buffers[4] = {r->vbo_scene, r->ibo_scene, r->vbo_object_ids, r->ubo_materials};
    for (int i = 0; i < 4; i++)
        if (buffers[i]) gl->DeleteBuffers(1, &buffers[i]);
    if (r->vao_scene) gl->DeleteVertexArrays(1, &r->vao_scene);
    for (size_t i = 0; i < r->texture_count; i++) {
        if (r->tex_srgb && r->tex_srgb[i]) gl->DeleteTextures(1, &r->tex_srgb[i]);
        if (r->tex_linear && r->tex_linear[i]) gl->DeleteTextures(1, &r->tex_linear[i]);
    }
    void *arrays[] = {r->tex_srgb, r->tex_linear, r->objects, r->materials, r->visible, r->draw_keys, r->fwd_first,
                      r->fwd_count};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) tl__free(&r->alloc, arrays[i]);
    r->vao_scene = r->vbo_scene = r->ibo_scene = r->vbo_object_ids = r->ubo_materials = 0;
    r->tex_srgb = r->tex_linear = NULL;
    r->objects = NULL;
    r->materials = NULL;
    r->visible = NULL;
    r->draw_keys = NULL;
    r->fwd_first = r->fwd_count = NULL;
    r->texture_count = r->object_count = r->material_count = 0;
    r->has_scene = 0;
}

void tl__lights_release(tl_renderer *r)
{
    void *arrays[] = {r->lights, r->instances, r->view_lights, r->view_light_index, r->view_light_spheres, r->fwd_indices};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) tl__free(&r->alloc, arrays[i]);
    r->lights = NULL;
    r->instances = NULL;
    r->view_lights = NULL;
    r->view_light_index = NULL;
    r->view_light_spheres = NULL;
    r->fwd_indices = NULL;
    r->fwd_index_capacity = r->light_count = 0;
}

/* The vertex array binds only the attributes the plan needs, plus the object id (location 4, one
 * per instance: draw i uses base instance i). */
void tl__scene_vao(tl_renderer *r)
{
    if (!r->vbo_scene) return;
    const GladGLContext *gl = &r->gl;
    if (r->vao_scene) gl->DeleteVertexArrays(1, &r->vao_scene);
    gl->CreateVertexArrays(1, &r->vao_scene);
    gl->VertexArrayVertexBuffer(r->vao_scene, 0, r->vbo_scene, 0, sizeof(tl_vertex));
    gl->VertexArrayElementBuffer(r->vao_scene, r->ibo_scene);
    const GLuint offs[4] = {offsetof(tl_vertex, position), offsetof(tl_vertex, normal), offsetof(tl_vertex, uv),
                            offsetof(tl_vertex, tangent)};
    const GLint sizes[4] = {3, 3, 2, 4};
    for (GLuint a = 0; a < 4; a++) {
        if (!(r->plan.pub.vertex_attributes & (1u << a))) continue;
        gl->EnableVertexArrayAttrib(r->vao_scene, a);
        gl->VertexArrayAttribFormat(r->vao_scene, a, sizes[a], GL_FLOAT, GL_FALSE, offs[a]);
        gl->VertexArrayAttribBinding(r->vao_scene, a, 0);
    }
    gl->VertexArrayVertexBuffer(r->vao_scene, 1, r->vbo_object_ids, 0, sizeof(uint32_t));
    gl->VertexArrayBindingDivisor(r->vao_scene, 1, 1);
    gl->EnableVertexArrayAttrib(r->vao_scene, 4);
    gl->VertexArrayAttribIFormat(r->vao_scene, 4, 1, GL_UNSIGNED_INT, 0);
    gl->VertexArrayAttribBinding(r->vao_scene, 4, 1);
    tl__gl_label(gl, GL_VERTEX_ARRAY, r->vao_scene, "vao.scene");
}

/* The light count against what the light buffers hold, before the array is read. */
static tl_result tl__lights_count(tl_renderer *r, size_t count)
{
    if (count <= r->max_lights) return TL_OK;
    return tl__fail(r, TL_ERROR_LIMIT,
                    "renderer: %zu lights exceed the limit of %zu (TL_RENDERER_MAX_LIGHTS, or a storage block of %zu "
                    "bytes at %zu bytes a light)", count, r->max_lights, r->storage_max, sizeof(tl__forward_light));
}

tl_result tl__lights_store(tl_renderer *r, const tl_light *lights, size_t count, size_t kinds[TL__LIGHT_KINDS])
{
    tl_result res = tl__lights_count(r, count);
    if (res != TL_OK) return res;
    if (count && !lights) return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: %zu lights but no array", count);
    memset(kinds, 0, TL__LIGHT_KINDS * sizeof kinds[0]);
    for (size_t i = 0; i < count; i++) {
        char what[32], msg[TL__CHECK_MESSAGE_SIZE];
        snprintf(what, sizeof what, "lights[%zu]", i);
        if ((res = tl__light_check(&lights[i], what, msg, sizeof msg)) != TL_OK)
            return tl__fail(r, res, "renderer: %s", msg);
        kinds[(lights[i].type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : lights[i].type) - 1]++;
    }
    size_t n = count ? count : 1;
    tl_light *copy = (tl_light *)tl__alloc_array(&r->alloc, n, sizeof *copy);
    tl__instance *inst = (tl__instance *)tl__alloc_array(&r->alloc, n, sizeof *inst);
    tl__forward_light *fl = (tl__forward_light *)tl__alloc_array(&r->alloc, n, sizeof *fl);
    uint32_t *vis = (uint32_t *)tl__alloc_array(&r->alloc, n, sizeof *vis);
    float(*sph)[4] = (float(*)[4])tl__alloc_array(&r->alloc, n, sizeof *sph);
    if (!copy || !inst || !fl || !vis || !sph) {
        void *arrays[] = {copy, inst, fl, vis, sph};
        for (size_t i = 0; i < 5; i++) tl__free(&r->alloc, arrays[i]);
        return tl__fail(r, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for %zu lights", count);
    }
    if (count) memcpy(copy, lights, count * sizeof *copy);
    /* negative light is clamped to none (docs/renderer-limits.md): -inf otherwise in FP16 targets;
     * directions are made unit (in double: any finite non-zero vector) */
    for (size_t i = 0; i < count; i++) {
        double d[3], l2 = 0.0;
        for (int k = 0; k < 3; k++) {
            copy[i].color[k] = copy[i].color[k] > 0.0f ? copy[i].color[k] : 0.0f;
            d[k] = copy[i].direction[k];
            l2 += d[k] * d[k];
        }
        for (int k = 0; k < 3 && l2 > 0.0; k++) copy[i].direction[k] = (float)(d[k] / sqrt(l2));
    }
    tl__lights_release(r);
    r->lights = copy;
    r->instances = inst;
    r->view_lights = fl;
    r->view_light_index = vis;
    r->view_light_spheres = sph;
    r->light_count = count;
    return TL_OK;
}

/* Counts past what 32-bit indices, GL sizes and the light buffers take: checked before any array is
 * read (the renderer trusts an array to hold its count, not the count to be sane). */
static tl_result tl__scene_counts(tl_renderer *r, const tl_scene *s)
{
    const struct { size_t count, limit; const char *what; } c[] = {
        {s->vertex_count, UINT32_MAX, "vertices (indices are 32-bit)"},
        {s->vertex_count, (size_t)PTRDIFF_MAX / sizeof(tl_vertex), "vertices (their bytes overflow GLsizeiptr)"},
        {s->index_count, TL__MAX_SCENE_INDICES, "indices (a 2 GiB index buffer)"},
        {s->object_count, UINT32_MAX, "objects"},
        {s->material_count, UINT32_MAX, "materials"},
        {s->texture_count, UINT32_MAX - 1u, "textures"},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++)
        if (c[i].count > c[i].limit)
            return tl__fail(r, TL_ERROR_LIMIT, "renderer: %zu %s exceed the limit of %zu", c[i].count, c[i].what,
                            c[i].limit);
    size_t max_objects = r->storage_max / sizeof(tl__object_gpu); /* the frame's per-object storage block */
    if (s->object_count > max_objects)
        return tl__fail(r, TL_ERROR_LIMIT,
                        "renderer: %zu objects exceed the limit of %zu (a storage block of %zu bytes at %zu bytes an "
                        "object)", s->object_count, max_objects, r->storage_max, sizeof(tl__object_gpu));
    const struct { size_t count; const void *array; const char *what; } a[] = {
        {s->vertex_count, s->vertices, "vertices"}, {s->index_count, s->indices, "indices"},
        {s->object_count, s->objects, "objects"},   {s->material_count, s->materials, "materials"},
        {s->texture_count, s->textures, "textures"},
    };
    for (size_t i = 0; i < sizeof a / sizeof a[0]; i++)
        if (a[i].count && !a[i].array)
            return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: %zu %s but no array", a[i].count, a[i].what);
    if (s->index_count % 3)
        return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: %zu indices are not whole triangles", s->index_count);
    return TL_OK;
}

/* Textures (sizes against this context's GL_MAX_TEXTURE_SIZE, pixels present) and the materials'
 * indices into them, as scene/validate.h checks them for the loader too. */
static tl_result tl__scene_parts(tl_renderer *r, const tl_scene *s)
{
    char what[48], msg[TL__CHECK_MESSAGE_SIZE];
    tl_result res;
    for (size_t i = 0; i < s->texture_count; i++) {
        snprintf(what, sizeof what, "textures[%zu]", i);
        if ((res = tl__texture_check(&s->textures[i], what, (uint32_t)r->max_texture_size, msg, sizeof msg)) != TL_OK)
            return tl__fail(r, res, "renderer: %s", msg);
    }
    for (size_t i = 0; i < s->material_count; i++) {
        snprintf(what, sizeof what, "materials[%zu]", i);
        if ((res = tl__material_check(&s->materials[i], what, s->texture_count, msg, sizeof msg)) != TL_OK)
            return tl__fail(r, res, "renderer: %s", msg);
    }
    return TL_OK;
}

tl_result tl__scene_camera(tl_renderer *r, const tl_scene *s, tl__scene_frame *out)
{
    out->has_bounds = tl__objects_bounds(s->objects, s->object_count, out->bounds_min, out->bounds_max);
    tl_result res = tl__camera_resolve(&s->camera, "scene.camera", r->desc.options.depth_format,
                                       out->has_bounds ? out->bounds_min : NULL, out->has_bounds ? out->bounds_max : NULL,
                                       &out->camera, out->warning, sizeof out->warning);
    if (res != TL_OK) return tl__fail(r, res, "renderer: %s", out->warning);
    if (!out->camera.near_raised) out->warning[0] = '\0';
    return TL_OK;
}

tl_result tl__scene_validate(tl_renderer *r, const tl_scene *s)
{
    tl_result res = tl__scene_counts(r, s);
    if (res != TL_OK) return res;
    if ((res = tl__lights_count(r, s->light_count)) != TL_OK) return res;
    for (size_t i = 0; i < s->object_count; i++) {
        const tl_object *o = &s->objects[i];
        if ((uint64_t)o->first_index + o->index_count > s->index_count || o->material >= s->material_count)
            return tl__fail(r, TL_ERROR_INVALID_ARGUMENT,
                            "renderer: object %zu draws indices %u..%llu or material %u, outside the scene's %zu "
                            "indices and %zu materials", i, o->first_index,
                            (unsigned long long)o->first_index + o->index_count, o->material, s->index_count,
                            s->material_count);
        if (o->index_count % 3)
            return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: object %zu draws %u indices, not whole triangles",
                            i, o->index_count);
    }
    for (size_t i = 0; i < s->index_count; i++)
        if (s->indices[i] >= s->vertex_count)
            return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: index %zu (%u) is out of range (%zu vertices)", i,
                            s->indices[i], s->vertex_count);
    for (size_t i = 0; i < s->vertex_count; i++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(s->vertices[i].position[k]))
                return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: vertex %zu has a non-finite position", i);
    return tl__scene_parts(r, s);
}

/* A texture tl__scene_parts accepted. */
static GLuint tl__upload_texture(tl_renderer *r, const tl_texture *tx, int srgb)
{
    const GladGLContext *gl = &r->gl;
    GLuint id;
    gl->CreateTextures(GL_TEXTURE_2D, 1, &id);
    uint32_t levels = 1, m = tx->width > tx->height ? tx->width : tx->height;
    while (m >>= 1) levels++;
    gl->TextureStorage2D(id, (GLsizei)levels, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, (GLsizei)tx->width,
                         (GLsizei)tx->height);
    gl->PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    /* rows top to bottom with uv (0,0) at the top-left, as glTF: upload as is, v samples downward */
    gl->TextureSubImage2D(id, 0, 0, 0, (GLsizei)tx->width, (GLsizei)tx->height, GL_RGBA, GL_UNSIGNED_BYTE, tx->rgba);
    gl->GenerateTextureMipmap(id);
    gl->TextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl->TextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl->TextureParameteri(id, GL_TEXTURE_WRAP_T, GL_REPEAT);
    tl__gl_label(gl, GL_TEXTURE, id, tx->name[0] ? tx->name : "texture");
    return id;
}

static GLuint tl__slot_texture(tl_renderer *r, const tl_scene *s, uint32_t index, int srgb)
{
    if (index == TL_NO_TEXTURE) return 0;
    GLuint *slot = srgb ? &r->tex_srgb[index] : &r->tex_linear[index];
    if (!*slot) *slot = tl__upload_texture(r, &s->textures[index], srgb);
    return *slot;
}

static void tl__material_record(const tl_material *m, int texture_mask, tl__material_ubo *u)
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
}

/* Textures and one std140 record per material, in one immutable uniform buffer. */
static tl_result tl__upload_materials(tl_renderer *r, const tl_scene *s)
{
    size_t n = s->material_count ? s->material_count : 1;
    r->material_stride = (sizeof(tl__material_ubo) + r->ubo_align - 1) / r->ubo_align * r->ubo_align;
    uint8_t *records = (uint8_t *)tl__calloc(&r->alloc, n, r->material_stride);
    if (!records) return tl__fail(r, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for %zu materials", n);
    for (size_t i = 0; i < s->material_count; i++) {
        const tl_material *m = &s->materials[i];
        int mask = 0;
        r->materials[i].flags = m->flags;
        for (int k = 0; k < TL__MATERIAL_TEXTURES; k++) {
            r->materials[i].textures[k] =
                tl__slot_texture(r, s, tl__material_texture(m, k), tl__material_texture_slots[k].srgb);
            if (r->materials[i].textures[k]) mask |= 1 << k;
        }
        tl__material_record(m, mask, (tl__material_ubo *)(records + i * r->material_stride));
    }
    const GladGLContext *gl = &r->gl;
    gl->CreateBuffers(1, &r->ubo_materials);
    gl->NamedBufferStorage(r->ubo_materials, (GLsizeiptr)(n * r->material_stride), records, 0);
    tl__gl_label(gl, GL_BUFFER, r->ubo_materials, "buffer.materials");
    tl__free(&r->alloc, records);
    r->material_count = s->material_count;
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
void tl__ambient_resolve(const float desc[3], const float scene[3], float out[3])
{
    int set = desc[0] != 0.0f || desc[1] != 0.0f || desc[2] != 0.0f;
    for (int k = 0; k < 3; k++) out[k] = !set ? scene[k] : desc[k] < 0.0f ? 0.0f : desc[k];
}

tl_result tl__scene_upload(tl_renderer *r, const tl_scene *s)
{
    size_t no = s->object_count ? s->object_count : 1, nt = s->texture_count ? s->texture_count : 1;
    r->objects = (tl_object *)tl__alloc_array(&r->alloc, no, sizeof *r->objects);
    r->materials = (tl__gpu_material *)tl__calloc(&r->alloc, s->material_count ? s->material_count : 1,
                                                  sizeof *r->materials);
    r->tex_srgb = (GLuint *)tl__calloc(&r->alloc, nt, sizeof(GLuint));
    r->tex_linear = (GLuint *)tl__calloc(&r->alloc, nt, sizeof(GLuint));
    r->visible = (uint32_t *)tl__alloc_array(&r->alloc, no, sizeof(uint32_t));
    r->draw_keys = (float *)tl__alloc_array(&r->alloc, no, sizeof(float));
    r->fwd_first = (uint32_t *)tl__calloc(&r->alloc, no, sizeof(uint32_t));
    r->fwd_count = (uint32_t *)tl__calloc(&r->alloc, no, sizeof(uint32_t));
    uint32_t *ids = (uint32_t *)tl__alloc_array(&r->alloc, no, sizeof(uint32_t));
    if (!r->objects || !r->materials || !r->tex_srgb || !r->tex_linear || !r->visible || !r->draw_keys ||
        !r->fwd_first || !r->fwd_count || !ids) {
        tl__free(&r->alloc, ids);
        tl__scene_release(r);
        return tl__fail(r, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for the scene");
    }
    if (s->object_count) memcpy(r->objects, s->objects, s->object_count * sizeof *r->objects);
    r->object_count = s->object_count;
    r->texture_count = s->texture_count;
    tl_result res = tl__upload_materials(r, s);
    if (res != TL_OK) {
        tl__free(&r->alloc, ids);
        tl__scene_release(r);
        return res;
    }
    const GladGLContext *gl = &r->gl;
    for (size_t i = 0; i < no; i++) ids[i] = (uint32_t)i;
    r->vbo_scene = tl__static_buffer(gl, s->vertex_count * sizeof(tl_vertex), s->vertices, "buffer.vertices");
    r->ibo_scene = tl__static_buffer(gl, s->index_count * 4u, s->indices, "buffer.indices");
    r->vbo_object_ids = tl__static_buffer(gl, no * sizeof(uint32_t), ids, "buffer.object_ids");
    tl__free(&r->alloc, ids);
    r->camera = s->camera;
    memcpy(r->scene_ambient, s->ambient, sizeof r->scene_ambient);
    tl__ambient_resolve(r->desc.options.ambient, s->ambient, r->ambient);
    tl_scene_features(s, &r->features);
    return TL_OK;
}
