/* Scene upload: validation, geometry buffers, textures (sRGB or linear by use), materials, lights;
 * then the frame is planned from the scene's features. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "renderer_internal.h"

void tl__release_scene(tl_renderer *r)
{
    const GladGLContext *gl = &r->gl;
    if (r->vao_scene) gl->DeleteVertexArrays(1, &r->vao_scene);
    if (r->vbo_scene) gl->DeleteBuffers(1, &r->vbo_scene);
    if (r->ibo_scene) gl->DeleteBuffers(1, &r->ibo_scene);
    for (size_t i = 0; i < r->texture_count; i++) {
        if (r->tex_srgb && r->tex_srgb[i]) gl->DeleteTextures(1, &r->tex_srgb[i]);
        if (r->tex_linear && r->tex_linear[i]) gl->DeleteTextures(1, &r->tex_linear[i]);
    }
    tl__free(&r->alloc, r->tex_srgb);
    tl__free(&r->alloc, r->tex_linear);
    tl__free(&r->alloc, r->objects);
    tl__free(&r->alloc, r->materials);
    tl__free(&r->alloc, r->lights);
    tl__free(&r->alloc, r->instances);
    tl__free(&r->alloc, r->draw_order);
    tl__free(&r->alloc, r->draw_keys);
    tl__free(&r->alloc, r->fwd_lights);
    tl__free(&r->alloc, r->fwd_visible);
    tl__free(&r->alloc, r->fwd_spheres);
    tl__free(&r->alloc, r->fwd_first);
    tl__free(&r->alloc, r->fwd_count);
    r->vao_scene = r->vbo_scene = r->ibo_scene = 0;
    r->tex_srgb = r->tex_linear = NULL;
    r->objects = NULL;
    r->materials = NULL;
    r->lights = NULL;
    r->instances = NULL;
    r->draw_order = NULL;
    r->draw_keys = NULL;
    r->fwd_lights = NULL;
    r->fwd_visible = r->fwd_first = r->fwd_count = NULL;
    r->fwd_spheres = NULL;
    r->texture_count = r->object_count = r->material_count = r->light_count = r->scene_index_count = 0;
    r->has_scene = 0;
}

/* The vertex array binds only the attributes the plan needs. */
tl_result tl__scene_vao(tl_renderer *r)
{
    if (!r->vbo_scene) return TL_OK;
    const GladGLContext *gl = &r->gl;
    if (r->vao_scene) gl->DeleteVertexArrays(1, &r->vao_scene);
    gl->CreateVertexArrays(1, &r->vao_scene);
    gl->VertexArrayVertexBuffer(r->vao_scene, 0, r->vbo_scene, 0, sizeof(tl_vertex));
    gl->VertexArrayElementBuffer(r->vao_scene, r->ibo_scene);
    const GLuint offs[4] = {offsetof(tl_vertex, position), offsetof(tl_vertex, normal), offsetof(tl_vertex, uv),
                            offsetof(tl_vertex, tangent)};
    const GLint sizes[4] = {3, 3, 2, 4};
    for (GLuint a = 0; a < 4; a++) {
        if (!(r->plan.vertex_attributes & (1u << a))) continue;
        gl->EnableVertexArrayAttrib(r->vao_scene, a);
        gl->VertexArrayAttribFormat(r->vao_scene, a, sizes[a], GL_FLOAT, GL_FALSE, offs[a]);
        gl->VertexArrayAttribBinding(r->vao_scene, a, 0);
    }
    tl__gl_label(gl, GL_VERTEX_ARRAY, r->vao_scene, "vao.scene");
    return TL_OK;
}

tl_result tl_renderer_set_lights(tl_renderer *r, const tl_light *lights, size_t count)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    if (count && !lights) return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: %zu lights but no array", count);
    if (count > (size_t)1 << 20)
        return tl__fail(r, TL_ERROR_LIMIT, "renderer: %zu lights exceed the limit of %u", count, 1u << 20);
    size_t kinds[TL__LIGHT_KINDS] = {0};
    for (size_t i = 0; i < count; i++) {
        const tl_light *l = &lights[i];
        int bad = (unsigned)l->type >= TL_LIGHT_TYPE_COUNT_;
        for (int k = 0; k < 3; k++)
            bad |= !isfinite(l->position[k]) || !isfinite(l->direction[k]) || !isfinite(l->color[k]);
        if (l->type != TL_LIGHT_DIRECTIONAL) bad |= !(l->radius >= 0.0f) || !isfinite(l->radius);
        if (bad) return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: light %zu has a non-finite or invalid field", i);
        if (!bad) kinds[(l->type == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : l->type) - 1]++;
    }
    size_t n = count ? count : 1;
    tl_light *copy = (tl_light *)tl__alloc(&r->alloc, n * sizeof *copy);
    tl__instance *inst = (tl__instance *)tl__alloc(&r->alloc, n * sizeof *inst);
    tl__forward_light *fl = (tl__forward_light *)tl__alloc(&r->alloc, n * sizeof *fl);
    uint32_t *vis = (uint32_t *)tl__alloc(&r->alloc, n * sizeof *vis);
    float(*sph)[4] = (float(*)[4])tl__alloc(&r->alloc, n * sizeof *sph);
    if (!copy || !inst || !fl || !vis || !sph) {
        tl__free(&r->alloc, copy);
        tl__free(&r->alloc, inst);
        tl__free(&r->alloc, fl);
        tl__free(&r->alloc, vis);
        tl__free(&r->alloc, sph);
        return tl__fail(r, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for %zu lights", count);
    }
    if (count) memcpy(copy, lights, count * sizeof *copy);
    tl__free(&r->alloc, r->lights);
    tl__free(&r->alloc, r->instances);
    tl__free(&r->alloc, r->fwd_lights);
    tl__free(&r->alloc, r->fwd_visible);
    tl__free(&r->alloc, r->fwd_spheres);
    r->lights = copy;
    r->instances = inst;
    r->fwd_lights = fl;
    r->fwd_visible = vis;
    r->fwd_spheres = sph;
    r->light_count = count;
    if (!r->has_scene) return TL_OK;
    /* light types decide passes and programs: re-plan when they change */
    if (r->features.point_lights != kinds[0] || r->features.spot_lights != kinds[1] ||
        r->features.directional_lights != kinds[2]) {
        int had[3] = {r->features.point_lights > 0, r->features.spot_lights > 0, r->features.directional_lights > 0};
        r->features.point_lights = kinds[0];
        r->features.spot_lights = kinds[1];
        r->features.directional_lights = kinds[2];
        if (had[0] != (kinds[0] > 0) || had[1] != (kinds[1] > 0) || had[2] != (kinds[2] > 0)) return tl__replan(r);
    }
    return TL_OK;
}

static GLuint tl__upload_texture(tl_renderer *r, const tl_texture *tx, int srgb)
{
    const GladGLContext *gl = &r->gl;
    if (!tx->rgba || !tx->width || !tx->height || tx->width > TL__MAX_SIZE || tx->height > TL__MAX_SIZE) return 0;
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

static GLuint tl__material_texture(tl_renderer *r, const tl_scene *s, uint32_t index, int srgb)
{
    if (index >= s->texture_count) return 0;
    GLuint *slot = srgb ? &r->tex_srgb[index] : &r->tex_linear[index];
    if (!*slot) *slot = tl__upload_texture(r, &s->textures[index], srgb);
    return *slot;
}

tl_result tl_renderer_set_scene(tl_renderer *r, const tl_scene *s)
{
    if (!r) return TL_ERROR_INVALID_ARGUMENT;
    if (!s) return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: no scene");
    if ((s->vertex_count && !s->vertices) || (s->index_count && !s->indices) || (s->object_count && !s->objects) ||
        (s->material_count && !s->materials) || (s->texture_count && !s->textures) || s->index_count % 3 ||
        s->vertex_count > UINT32_MAX || s->index_count > ((size_t)1 << 31) / 4)
        return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: inconsistent scene arrays");
    for (size_t i = 0; i < s->index_count; i++)
        if (s->indices[i] >= s->vertex_count)
            return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: index %zu (%u) is out of range (%zu vertices)", i,
                            s->indices[i], s->vertex_count);
    for (size_t i = 0; i < s->vertex_count; i++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(s->vertices[i].position[k]))
                return tl__fail(r, TL_ERROR_INVALID_ARGUMENT, "renderer: vertex %zu has a non-finite position", i);
    for (size_t i = 0; i < s->object_count; i++) {
        const tl_object *o = &s->objects[i];
        if ((size_t)o->first_index + o->index_count > s->index_count || o->material >= s->material_count)
            return tl__fail(r, TL_ERROR_INVALID_ARGUMENT,
                            "renderer: object %zu has an index range or material out of range", i);
    }
    tl__release_scene(r);
    const GladGLContext *gl = &r->gl;
    tl_result res = tl_renderer_set_lights(r, s->lights, s->light_count);
    if (res != TL_OK) return res;
    size_t no = s->object_count ? s->object_count : 1;
    r->objects = (tl_object *)tl__alloc(&r->alloc, no * sizeof *r->objects);
    r->materials = (tl__gpu_material *)tl__alloc(&r->alloc, (s->material_count ? s->material_count : 1) *
                                                                sizeof *r->materials);
    r->tex_srgb = (GLuint *)tl__alloc(&r->alloc, (s->texture_count ? s->texture_count : 1) * sizeof(GLuint));
    r->tex_linear = (GLuint *)tl__alloc(&r->alloc, (s->texture_count ? s->texture_count : 1) * sizeof(GLuint));
    r->draw_order = (uint32_t *)tl__alloc(&r->alloc, no * sizeof(uint32_t));
    r->draw_keys = (float *)tl__alloc(&r->alloc, no * sizeof(float));
    r->fwd_first = (uint32_t *)tl__alloc(&r->alloc, no * sizeof(uint32_t));
    r->fwd_count = (uint32_t *)tl__alloc(&r->alloc, no * sizeof(uint32_t));
    if (!r->objects || !r->materials || !r->tex_srgb || !r->tex_linear || !r->draw_order || !r->draw_keys ||
        !r->fwd_first || !r->fwd_count) {
        tl__release_scene(r);
        return tl__fail(r, TL_ERROR_OUT_OF_MEMORY, "renderer: out of memory for the scene");
    }
    if (s->object_count) memcpy(r->objects, s->objects, s->object_count * sizeof *r->objects);
    r->object_count = s->object_count;
    r->texture_count = s->texture_count;
    memset(r->tex_srgb, 0, (s->texture_count ? s->texture_count : 1) * sizeof(GLuint));
    memset(r->tex_linear, 0, (s->texture_count ? s->texture_count : 1) * sizeof(GLuint));
    for (size_t i = 0; i < s->material_count; i++) {
        tl__gpu_material *gm = &r->materials[i];
        const tl_material *m = &s->materials[i];
        gm->m = *m;
        if (gm->m.normal_scale == 0.0f) gm->m.normal_scale = 1.0f;
        if (gm->m.occlusion_strength == 0.0f) gm->m.occlusion_strength = 1.0f;
        const uint32_t idx[TL__MATERIAL_TEXTURES] = {m->albedo_texture, m->normal_texture,
                                                     m->metallic_roughness_texture, m->emissive_texture,
                                                     m->occlusion_texture};
        const int srgb[TL__MATERIAL_TEXTURES] = {1, 0, 0, 1, 0};
        gm->texture_mask = 0;
        for (int k = 0; k < TL__MATERIAL_TEXTURES; k++) {
            /* a missing or unreadable texture leaves the flat factor (a warning is the loader's job) */
            gm->textures[k] = tl__material_texture(r, s, idx[k], srgb[k]);
            if (gm->textures[k]) gm->texture_mask |= 1 << k;
        }
    }
    r->material_count = s->material_count;
    r->scene_index_count = s->index_count;
    gl->CreateBuffers(1, &r->vbo_scene);
    gl->NamedBufferStorage(r->vbo_scene, (GLsizeiptr)(s->vertex_count ? s->vertex_count * sizeof(tl_vertex) : 16),
                           s->vertex_count ? (const void *)s->vertices : NULL, 0);
    gl->CreateBuffers(1, &r->ibo_scene);
    gl->NamedBufferStorage(r->ibo_scene, (GLsizeiptr)(s->index_count ? s->index_count * 4u : 16),
                           s->index_count ? (const void *)s->indices : NULL, 0);
    r->camera = s->camera;
    memcpy(r->ambient, s->ambient, sizeof r->ambient);
    tl_scene_features(s, &r->features);
    r->has_scene = 1;
    if ((res = tl__replan(r)) != TL_OK) {
        r->has_scene = 0;
        return res;
    }
    GLenum e = gl->GetError();
    if (e != GL_NO_ERROR)
        return tl__fail(r, TL_ERROR_GL, "renderer: %s while uploading the scene", tl__gl_error_string(e));
    return TL_OK;
}
