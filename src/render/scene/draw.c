/* The scene's objects in a frame: which are visible (once per frame, for every geometry pass),
 * their per-object data (model and normal matrices, forward light range) and drawing them: one
 * instanced draw per object whose instance index selects its record (shaders/object.glsl), the
 * material's uniform block bound as a range when it changes. And the full-screen triangle of the
 * post passes. */
#include <string.h>

#include "scene_gpu.h"

/* Transparent objects far to near: insertion sort, there are few. */
static void tl__sort_far_to_near(uint32_t *order, float *keys, size_t n)
{
    for (size_t i = 1; i < n; i++) {
        uint32_t oi = order[i];
        float k = keys[i];
        size_t j = i;
        for (; j > 0 && keys[j - 1] < k; j--) {
            order[j] = order[j - 1];
            keys[j] = keys[j - 1];
        }
        order[j] = oi;
        keys[j] = k;
    }
}

/* The set an object is drawn in: 0 opaque triangles, 1 blended triangles, 2 points and lines. */
static int tl__draw_set(const tl__scene_gpu *g, const tl_object *o)
{
    if (o->primitive != TL_PRIMITIVE_TRIANGLES) return 2;
    return (g->materials[o->material].flags & TL_MATERIAL_ALPHA_BLEND) != 0;
}

size_t tl__visibility(tl__scene_gpu *g, const tl__view *v)
{
    size_t n = 0;
    for (int set = 0; set < 3; set++) {
        size_t first = n;
        for (size_t i = 0; i < g->object_count; i++) {
            const tl_object *o = &g->objects[i];
            if (!o->index_count || g->object_state[i] || tl__draw_set(g, o) != set) continue; /* hidden or removed */
            if (!tl__box_visible((float(*)[4])v->planes, o->bounds_min, o->bounds_max)) continue;
            float d2 = 0.0f;
            for (int k = 0; k < 3; k++) {
                float c = 0.5f * (o->bounds_min[k] + o->bounds_max[k]) - v->eye[k];
                d2 += c * c;
            }
            g->visible[n] = (uint32_t)i;
            g->draw_keys[n++] = d2;
        }
        if (set == 0) g->visible_opaque = n;
        if (set == 1) {
            tl__sort_far_to_near(g->visible + first, g->draw_keys + first, n - first);
            g->visible_transparent = n - first;
        }
        if (set == 2) g->visible_points_lines = n - first;
    }
    return g->visible_opaque;
}

void tl__objects_fill(const tl__scene_gpu *g, const tl__view *v, const uint32_t *first, const uint32_t *count,
                      tl__object_gpu *out)
{
    for (size_t i = 0; i < g->object_count; i++) {
        tl__mat4 model, mv;
        memcpy(model.m, g->objects[i].transform, sizeof model.m);
        mv = tl__mat4_mul(&v->view, &model);
        float nm[9];
        tl__normal_matrix(&mv, nm);
        tl__object_gpu *o = &out[i];
        memcpy(o->model, model.m, sizeof o->model);
        for (int c = 0; c < 3; c++) {
            memcpy(&o->normal_view[c * 4], &nm[c * 3], 3 * sizeof(float));
            o->normal_view[c * 4 + 3] = 0.0f;
        }
        uint32_t vis[2] = {g->objects[i].first_index, g->objects[i].material}; /* uint words (object.glsl) */
        memcpy(&o->normal_view[3], &vis[0], sizeof vis[0]);
        memcpy(&o->normal_view[7], &vis[1], sizeof vis[1]);
        o->light_first = first ? first[i] : 0u;
        o->light_count = first ? count[i] : 0u;
        o->pad[0] = o->pad[1] = 0u;
    }
    /* the stipple's layers (shaders/stipple.glsl): the visible blended objects far to near get
     * layers 1, 2, 3; the plan stipples only scenes with at most that many blended objects */
    for (size_t k = 0; k < g->visible_transparent && k < TL_STIPPLE_LAYERS; k++)
        out[g->visible[g->visible_opaque + k]].pad[0] = (uint32_t)(k + 1);
}

void tl__bind_material(const GladGLContext *gl, const tl__scene_gpu *g, uint32_t index)
{
    gl->BindBufferRange(GL_UNIFORM_BUFFER, TL__UBO_MATERIAL, g->ubo_materials, (GLintptr)(index * g->material_stride),
                        (GLsizeiptr)sizeof(tl__material_ubo));
    const tl__gpu_material *m = &g->materials[index];
    for (int k = 0; k < TL__MATERIAL_TEXTURES; k++)
        if (m->textures[k]) gl->BindTextureUnit((GLuint)(TL__UNIT_ALBEDO_TEXTURE + k), m->textures[k]);
}

/* Draws visible[first, first + count) with `program`, those whose material's model is `model` (or
 * every one: UINT32_MAX): triangles cull their back faces unless double-sided; points and lines are
 * never culled. */
static void tl__draw_objects_of(const tl__pass_ctx *ctx, size_t first, size_t count, GLuint program, uint32_t model)
{
    static const GLenum modes[TL_PRIMITIVE_COUNT_] = {GL_TRIANGLES, GL_LINES, GL_POINTS};
    const GladGLContext *gl = ctx->gl;
    const tl__scene_gpu *g = ctx->scene;
    tl__state_vertex_array(gl, ctx->state, g->vao);
    tl__state_program(gl, ctx->state, program);
    uint32_t last_material = UINT32_MAX;
    for (size_t j = first; j < first + count; j++) {
        uint32_t i = g->visible[j];
        const tl_object *o = &g->objects[i];
        if (model != UINT32_MAX && g->materials[o->material].model != model) continue;
        if (o->material != last_material) {
            tl__bind_material(gl, g, o->material);
            last_material = o->material;
        }
        int double_sided = (g->materials[o->material].flags & TL_MATERIAL_DOUBLE_SIDED) != 0;
        int surface = o->primitive == TL_PRIMITIVE_TRIANGLES;
        tl__state_cull(gl, ctx->state, double_sided || !surface ? TL__CULL_OFF : TL__CULL_BACK);
        gl->DrawElementsInstancedBaseInstance(modes[o->primitive], (GLsizei)o->index_count, GL_UNSIGNED_INT,
                                              (const void *)(uintptr_t)(o->first_index * 4u), 1, i);
        ctx->out->indices += o->index_count;
        ctx->out->draw_calls++;
    }
}

static void tl__draw_objects(const tl__pass_ctx *ctx, size_t first, size_t count)
{
    tl__draw_objects_of(ctx, first, count, ctx->programs[0], UINT32_MAX);
}

void tl__draw_opaque(const tl__pass_ctx *ctx) { tl__draw_objects(ctx, 0, ctx->scene->visible_opaque); }

void tl__draw_opaque_model(const tl__pass_ctx *ctx, uint32_t model)
{
    tl__draw_objects_of(ctx, 0, ctx->scene->visible_opaque, ctx->programs[model], model);
}

void tl__draw_transparent(const tl__pass_ctx *ctx)
{
    tl__draw_objects(ctx, ctx->scene->visible_opaque, ctx->scene->visible_transparent);
}

void tl__draw_points_lines(const tl__pass_ctx *ctx)
{
    const tl__scene_gpu *g = ctx->scene;
    tl__draw_objects(ctx, g->visible_opaque + g->visible_transparent, g->visible_points_lines);
}

void tl__draw_fullscreen(const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = ctx->gl;
    tl__state_program(gl, ctx->state, ctx->programs[0]);
    tl__state_vertex_array(gl, ctx->state, ctx->fullscreen_vao);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    ctx->out->draw_calls++;
}
