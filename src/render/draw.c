/* The scene's objects in a frame: which are visible (once per frame, for every geometry pass),
 * their per-object data (model and normal matrices, forward light range) and drawing them: one
 * instanced draw per object whose instance index selects its record (shaders/object.glsl), the
 * material's uniform block bound as a range when it changes. */
#include <string.h>

#include "renderer_internal.h"

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

void tl__visibility(tl_renderer *r, const tl__view *v, tl__frame_record *rec)
{
    size_t n = 0;
    for (int set = 0; set < 2; set++) {
        size_t first = n;
        for (size_t i = 0; i < r->object_count; i++) {
            const tl_object *o = &r->objects[i];
            int blend = (r->materials[o->material].flags & TL_MATERIAL_ALPHA_BLEND) != 0;
            if (blend != set || !o->index_count) continue;
            if (!tl__box_visible((float(*)[4])v->planes, o->bounds_min, o->bounds_max)) continue;
            float d2 = 0.0f;
            for (int k = 0; k < 3; k++) {
                float c = 0.5f * (o->bounds_min[k] + o->bounds_max[k]) - v->eye[k];
                d2 += c * c;
            }
            r->visible[n] = (uint32_t)i;
            r->draw_keys[n++] = d2;
        }
        if (set == 0) r->visible_opaque = n;
        else tl__sort_far_to_near(r->visible + first, r->draw_keys + first, n - first);
    }
    r->visible_transparent = n - r->visible_opaque;
    rec->st.objects_drawn = (uint32_t)r->visible_opaque;
}

void tl__objects_fill(const tl_renderer *r, const tl__view *v, int with_lists, tl__object_gpu *out)
{
    for (size_t i = 0; i < r->object_count; i++) {
        tl__mat4 model, mv;
        memcpy(model.m, r->objects[i].transform, sizeof model.m);
        mv = tl__mat4_mul(&v->view, &model);
        float nm[9];
        tl__normal_matrix(&mv, nm);
        tl__object_gpu *g = &out[i];
        memcpy(g->model, model.m, sizeof g->model);
        for (int c = 0; c < 3; c++) {
            memcpy(&g->normal_view[c * 4], &nm[c * 3], 3 * sizeof(float));
            g->normal_view[c * 4 + 3] = 0.0f;
        }
        g->light_first = with_lists ? r->fwd_first[i] : 0u;
        g->light_count = with_lists ? r->fwd_count[i] : 0u;
        g->pad[0] = g->pad[1] = 0u;
    }
}

static void tl__bind_material(tl_renderer *r, uint32_t index)
{
    const GladGLContext *gl = &r->gl;
    gl->BindBufferRange(GL_UNIFORM_BUFFER, TL__UBO_MATERIAL, r->ubo_materials, (GLintptr)(index * r->material_stride),
                        (GLsizeiptr)sizeof(tl__material_ubo));
    const tl__gpu_material *m = &r->materials[index];
    for (int k = 0; k < TL__MATERIAL_TEXTURES; k++)
        if (m->textures[k]) gl->BindTextureUnit((GLuint)(TL__UNIT_ALBEDO_TEXTURE + k), m->textures[k]);
}

void tl__draw_objects(tl_renderer *r, const tl__pass_ctx *ctx, tl__draw_set set)
{
    const GladGLContext *gl = &r->gl;
    tl__state_vertex_array(gl, &r->state, r->vao_scene);
    tl__state_program(gl, &r->state, ctx->cp->programs[0]);
    size_t first = set == TL__DRAW_OPAQUE ? 0 : r->visible_opaque;
    size_t count = set == TL__DRAW_OPAQUE ? r->visible_opaque : r->visible_transparent;
    uint32_t last_material = UINT32_MAX;
    for (size_t j = first; j < first + count; j++) {
        uint32_t i = r->visible[j];
        const tl_object *o = &r->objects[i];
        if (o->material != last_material) {
            tl__bind_material(r, o->material);
            last_material = o->material;
        }
        int double_sided = (r->materials[o->material].flags & TL_MATERIAL_DOUBLE_SIDED) != 0;
        tl__state_cull(gl, &r->state, double_sided ? TL__CULL_OFF : TL__CULL_BACK);
        gl->DrawElementsInstancedBaseInstance(GL_TRIANGLES, (GLsizei)o->index_count, GL_UNSIGNED_INT,
                                              (const void *)(uintptr_t)(o->first_index * 4u), 1, i);
        ctx->rec->indices[ctx->index] += o->index_count;
        ctx->rec->st.draw_calls++;
    }
}

void tl__draw_fullscreen(tl_renderer *r, const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = &r->gl;
    tl__state_program(gl, &r->state, ctx->cp->programs[0]);
    tl__state_vertex_array(gl, &r->state, r->vao_empty);
    gl->DrawArrays(GL_TRIANGLES, 0, 3);
    ctx->rec->st.draw_calls++;
}
