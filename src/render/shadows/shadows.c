/* The shadow atlas on the GPU (docs/shadows.md): one D32F depth texture with a depth-compare
 * sampler state, its framebuffer, the lookup block (shadow.glsl) and a buffer of the views'
 * matrices for the shadow pass. Each frame the views shadow_views.c marked are rendered (their
 * tile scissored, cleared and drawn with the casters in their frustum); the others keep what an
 * earlier frame drew. The rendering is the shadows pass of the frame (pass_shadows.c), timed like
 * every pass. */
#include <string.h>

#include "shadows.h"

_Static_assert(sizeof(tl__shadow_block) + TL__SHADOW_MAX_VIEWS * sizeof(tl__shadow_view_gpu) <= 65536,
               "the shadow lookup block fits a 64 KiB uniform block");

static void tl__atlas_release(const GladGLContext *gl, tl__shadows *s)
{
    if (s->fbo) gl->DeleteFramebuffers(1, &s->fbo);
    if (s->atlas) gl->DeleteTextures(1, &s->atlas);
    s->fbo = s->atlas = 0;
    s->atlas_size = 0;
    s->kept_count = 0;
}

/* The atlas for `size` (reversed depth: far 0, nearer greater); 1 when it was made again (every tile
 * is empty). */
static int tl__atlas_make(tl__device *dev, tl__shadows *s, uint32_t size)
{
    const GladGLContext *gl = &dev->gl;
    if (s->atlas && s->atlas_size == size) return 0;
    tl__atlas_release(gl, s);
    gl->CreateTextures(GL_TEXTURE_2D, 1, &s->atlas);
    gl->TextureStorage2D(s->atlas, 1, GL_DEPTH_COMPONENT32F, (GLsizei)size, (GLsizei)size);
    gl->TextureParameteri(s->atlas, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl->TextureParameteri(s->atlas, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->TextureParameteri(s->atlas, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->TextureParameteri(s->atlas, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->TextureParameteri(s->atlas, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    gl->TextureParameteri(s->atlas, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL); /* 1: lit */
    tl__gl_label(gl, GL_TEXTURE, s->atlas, "shadow.atlas");
    gl->CreateFramebuffers(1, &s->fbo);
    gl->NamedFramebufferTexture(s->fbo, GL_DEPTH_ATTACHMENT, s->atlas, 0);
    gl->NamedFramebufferDrawBuffer(s->fbo, GL_NONE);
    tl__gl_label(gl, GL_FRAMEBUFFER, s->fbo, "shadow.atlas");
    s->atlas_size = size;
    return 1;
}

static void tl__shadow_buffers(tl__device *dev, tl__shadows *s)
{
    const GladGLContext *gl = &dev->gl;
    if (s->lookup) return;
    size_t bytes = sizeof(tl__shadow_block) + TL__SHADOW_MAX_VIEWS * sizeof(tl__shadow_view_gpu);
    gl->CreateBuffers(1, &s->lookup);
    gl->NamedBufferStorage(s->lookup, (GLsizeiptr)bytes, NULL, GL_DYNAMIC_STORAGE_BIT);
    tl__gl_label(gl, GL_BUFFER, s->lookup, "shadow.lookup");
    s->ubo_stride = (64 + dev->lim.ubo_align - 1) / dev->lim.ubo_align * dev->lim.ubo_align;
    gl->CreateBuffers(1, &s->ubo);
    gl->NamedBufferStorage(s->ubo, (GLsizeiptr)(s->ubo_stride * TL__SHADOW_MAX_VIEWS), NULL, GL_DYNAMIC_STORAGE_BIT);
    tl__gl_label(gl, GL_BUFFER, s->ubo, "shadow.views");
    gl->CreateSamplers(1, &s->depth_sampler);
    gl->SamplerParameteri(s->depth_sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl->SamplerParameteri(s->depth_sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl->SamplerParameteri(s->depth_sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->SamplerParameteri(s->depth_sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->SamplerParameteri(s->depth_sampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    tl__gl_label(gl, GL_SAMPLER, s->depth_sampler, "shadow.depth");
}

void tl__shadows_release(tl__device *dev, tl__shadows *s)
{
    const GladGLContext *gl = &dev->gl;
    tl__atlas_release(gl, s);
    if (s->lookup) {
        gl->DeleteBuffers(1, &s->lookup);
        gl->DeleteBuffers(1, &s->ubo);
        gl->DeleteSamplers(1, &s->depth_sampler);
    }
    void *a[] = {s->slots, s->fade, s->score, s->order};
    for (int i = 0; i < 4; i++) tl__free(&dev->alloc, a[i]);
    memset(s, 0, sizeof *s);
}

typedef struct tl__caster_draw {
    const GladGLContext *gl;
    const tl__scene_gpu *g;
    uint32_t draws;
} tl__caster_draw;

static void tl__draw_caster(void *user, uint32_t object)
{
    tl__caster_draw *d = (tl__caster_draw *)user;
    const tl_object *o = &d->g->objects[object];
    d->gl->DrawElementsInstancedBaseInstance(GL_TRIANGLES, (GLsizei)o->index_count, GL_UNSIGNED_INT,
                                             (const void *)(uintptr_t)(o->first_index * 4u), 1, object);
    d->draws++;
}

/* The views marked for rendering: each tile scissored, cleared to the far depth, its casters drawn
 * (both faces: open meshes cast too; depth clamp keeps casters in front of the near plane). */
static uint32_t tl__shadow_draw(tl__device *dev, tl__shadows *s, const tl__scene_gpu *g, GLuint program)
{
    const GladGLContext *gl = &dev->gl;
    tl__caster_draw d = {gl, g, 0};
    tl__state_framebuffer(gl, &dev->state, s->fbo);
    tl__state_program(gl, &dev->state, program);
    tl__state_vertex_array(gl, &dev->state, g->vao);
    /* reversed depth whatever the frame's (shadow_views.c): nearer is greater; the state maps LESS to
     * GREATER only under a reversed frame */
    tl__pipeline p = {.depth_test = dev->state.reversed ? TL__DEPTH_LESS : TL__DEPTH_GEQUAL, .depth_write = 1,
                      .color_write = 0, .cull = TL__CULL_OFF, .depth_clamp = 1, .clip_zero_one = 1};
    tl__state_apply(gl, &dev->state, &p);
    gl->Enable(GL_SCISSOR_TEST);
    float far = 0.0f;
    for (size_t i = 0; i < s->view_count; i++) {
        tl__shadow_view *v = &s->views[i];
        if (!v->render) continue;
        tl__state_viewport(gl, &dev->state, (GLint)v->x, (GLint)v->y, (GLsizei)v->size, (GLsizei)v->size);
        gl->Scissor((GLint)v->x, (GLint)v->y, (GLsizei)v->size, (GLsizei)v->size);
        gl->ClearNamedFramebufferfv(s->fbo, GL_DEPTH, 0, &far);
        gl->BindBufferRange(GL_UNIFORM_BUFFER, TL__UBO_PASS, s->ubo, (GLintptr)(i * s->ubo_stride), 64);
        tl__shadow_casters(g, &v->world_clip, tl__draw_caster, &d);
    }
    gl->Disable(GL_SCISSOR_TEST);
    return d.draws;
}

uint32_t tl__shadows_render(tl__device *dev, tl__shadows *s, const tl__scene_gpu *g, tl_frame_stats *st)
{
    const GladGLContext *gl = &dev->gl;
    tl__shadow_buffers(dev, s);
    if (tl__atlas_make(dev, s, (uint32_t)(1.0f / s->block.params[0] + 0.5f))) s->kept_count = 0;
    uint32_t rendered = 0;
    for (size_t i = 0; i < s->view_count; i++) {
        tl__shadow_view *v = &s->views[i];
        if (i >= s->kept_count || s->kept[i] != v->signature) v->render = 1;
        if (!v->render) continue;
        gl->NamedBufferSubData(s->ubo, (GLintptr)(i * s->ubo_stride), 64, v->world_clip.m);
        rendered++;
    }
    gl->NamedBufferSubData(s->lookup, 0, sizeof s->block, &s->block);
    if (s->view_count)
        gl->NamedBufferSubData(s->lookup, sizeof s->block, (GLsizeiptr)(s->view_count * sizeof(tl__shadow_view_gpu)),
                               s->views_gpu);
    uint32_t draws = rendered ? tl__shadow_draw(dev, s, g, s->program) : 0u;
    for (size_t i = 0; i < s->view_count; i++) s->kept[i] = s->views[i].signature;
    s->kept_count = s->view_count;
    gl->BindBufferBase(GL_UNIFORM_BUFFER, TL__UBO_SHADOWS, s->lookup);
    gl->BindTextureUnit(TL__UNIT_SHADOW_ATLAS, s->atlas);
    /* PCSS reads depth values (blocker search) and compares itself (textureGather) */
    gl->BindSampler(TL__UNIT_SHADOW_ATLAS, s->block.flags[1] ? s->depth_sampler : 0);
    st->shadow_maps_rendered = rendered;
    st->shadow_maps_cached = (uint32_t)(s->view_count - rendered);
    return draws;
}

tl_result tl__shadows_views(const tl__shadows *s, const tl_light *lights, size_t light_count, tl_shadow_view_info *out,
                            size_t *count)
{
    size_t have = *count;
    *count = s->view_count;
    if (!out) return TL_OK;
    if (have < s->view_count) return TL_ERROR_INVALID_ARGUMENT;
    for (size_t i = 0; i < s->view_count; i++) {
        const tl__shadow_view *v = &s->views[i];
        tl_light_type t = v->light < light_count ? lights[v->light].type : TL_LIGHT_DEFAULT; /* lights set since */
        out[i] = (tl_shadow_view_info){.light = v->light, .type = t == TL_LIGHT_DEFAULT ? TL_LIGHT_POINT : t,
                                       .index = v->index, .x = v->x, .y = v->y, .size = v->size,
                                       .perspective = v->perspective, .near_z = v->near_z, .far_z = v->far_z,
                                       .split = v->split, .rendered = v->render};
    }
    return TL_OK;
}

tl_result tl__shadows_read_atlas(tl__device *dev, const tl__shadows *s, float *depth, size_t *size)
{
    size_t need = (size_t)s->atlas_size * s->atlas_size * sizeof(float);
    size_t have = *size;
    *size = need;
    if (!s->atlas)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT, "renderer: no shadow atlas (no casting light rendered)");
    if (!depth) return TL_OK;
    if (have < need)
        return tl__fail(dev, TL_ERROR_INVALID_ARGUMENT,
                        "renderer: reading the shadow atlas needs %zu bytes, the buffer has %zu", need, have);
    tl__target t = {.texture = s->atlas, .internal_format = GL_DEPTH_COMPONENT32F, .width = s->atlas_size,
                    .height = s->atlas_size, .levels = 1, .samples = 1, .bytes = need};
    char msg[256] = "";
    tl_result res = tl__target_read(&dev->gl, &t, GL_DEPTH_COMPONENT, GL_FLOAT, depth, need, msg, sizeof msg);
    return res == TL_OK ? TL_OK : tl__fail(dev, res, "renderer: reading the shadow atlas: %s", msg);
}
