/* The visibility buffer (docs/frame.md, "Visibility buffer"; Burns and Hunt, JCGT 2013): the
 * G-buffer pass writes depth and one 32-bit id per pixel (VIS_ID: the object's slot + 1 above
 * TL__VIS_TRIANGLE_BITS bits of the triangle's index within the object's draw), then two compute
 * passes shade:
 *   vis-classify  per 16 x 16 tile, the material buckets (material index mod TL__VIS_BUCKETS) its
 *                 pixels show, each appended to its bucket's list of tiles, whose count is the
 *                 bucket's indirect dispatch; empty pixels' HDR cleared;
 *   vis-resolve   per material, its bucket's tiles: each pixel of the material rebuilds its
 *                 triangle's attributes from the scene's buffers (perspective-correct barycentrics
 *                 of the pixel's view ray, and of its neighbours' for the texture derivatives),
 *                 evaluates the material with its textures bound as the other modes bind them,
 *                 lights it from the tile lists (forward's light loop and colour) into HDR.
 * Binding each material's textures per dispatch keeps bindless textures out: the buckets make the
 * dispatches cover only the tiles where a material shows. */
#include <stdio.h>

#include "gl/gl.h"
#include "lights.h"
#include "scene_gpu.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

enum {
    TL__VIS_TILE = 16,         /* classify's tiles: 16 x 16 pixels, four 8 x 8 resolve workgroups */
    TL__VIS_DISPATCH_BYTES = 16 /* a bucket's indirect dispatch: tiles, 4, 1, and a word of padding */
};

static size_t tl__vis_tile_count(uint32_t width, uint32_t height)
{
    return (size_t)((width + TL__VIS_TILE - 1) / TL__VIS_TILE) * ((height + TL__VIS_TILE - 1) / TL__VIS_TILE);
}

/* The buckets' dispatches, then each bucket's list of tiles (a tile at most once per bucket). */
static size_t tl__vis_tiles_bytes_for(size_t tiles)
{
    return (size_t)TL__VIS_BUCKETS * (TL__VIS_DISPATCH_BYTES + 4u * tiles);
}

static size_t tl__vis_tiles_bytes(const tl_frame_plan *p, const tl_renderer_options *o)
{
    (void)o;
    return tl__vis_tiles_bytes_for(tl__vis_tile_count(p->width, p->height));
}

static const tl__target_def tl__target_vis_id = {TL__TARGET(VIS_ID, "vis.id"), .format = GL_R32UI,
                                                 .samples_of = tl__gbuffer_samples, .store = TL__STORE_GBUFFER,
                                                 .read_vis_id = 1};
static const tl__target_def tl__target_vis_tiles = {TL__TARGET(VIS_TILES, "vis.tiles"),
                                                    .buffer_bytes = tl__vis_tiles_bytes, .store = TL__STORE_LISTS};

/* MSAA (per-sample edges, the mode's way): the id and depth have the samples, HDR too; both passes
 * loop over a pixel's samples (TL_GBUFFER_SAMPLES), the resolve shading each distinct triangle once. */
static void tl__vis_samples(const tl__plan_input *in, tl__perm *k)
{
    if (tl__gbuffer_samples(in->o) > 1u) tl__perm_value(k, TL__V_GBUFFER_SAMPLES, in->msaa);
}

static void tl__vis_permute_samples(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    tl__vis_samples(in, &out->slot[0]);
}

/* ---- vis-classify ---------------------------------------------------------------------------- */

static void tl__vis_classify_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->mode->visibility) return;
    d->reads = d->samples = TL__B(VIS_ID);
    d->writes = TL__B(VIS_TILES) | TL__B(HDR); /* HDR: the pixels nothing was drawn at */
    d->images = TL__B(HDR);
    d->compute = 1;
}

/* The buffer for the plan's tiles (made again when it needs more), its dispatches reset to no
 * tiles, then one workgroup per tile. */
static void tl__vis_classify_execute(const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = ctx->gl;
    tl__vis_tiles *t = &ctx->lights->vis;
    size_t bytes = tl__vis_tiles_bytes_for(tl__vis_tile_count(ctx->width, ctx->height));
    if (t->bytes < bytes) {
        if (t->buffer) gl->DeleteBuffers(1, &t->buffer);
        gl->CreateBuffers(1, &t->buffer);
        gl->NamedBufferStorage(t->buffer, (GLsizeiptr)bytes, NULL, 0);
        tl__gl_label(gl, GL_BUFFER, t->buffer, "buffer.vis.tiles");
        t->bytes = bytes;
    }
    /* zeros, from no client memory (a clear with data reads it through the application's unpack
     * state in Mesa); the classify's first workgroup writes the dispatches' y and z */
    gl->ClearNamedBufferSubData(t->buffer, GL_R32UI, 0, (GLsizeiptr)TL__VIS_BUCKETS * TL__VIS_DISPATCH_BYTES,
                                GL_RED_INTEGER, GL_UNSIGNED_INT, NULL);
    gl->MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, TL__SSBO_VIS_TILES, t->buffer);
    tl__state_program(gl, ctx->state, ctx->programs[0]);
    gl->DispatchCompute((ctx->width + TL__VIS_TILE - 1) / TL__VIS_TILE, (ctx->height + TL__VIS_TILE - 1) / TL__VIS_TILE,
                        1);
    gl->MemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

const tl__pass_def tl__pass_vis_classify = {
    .id = TL_PASS_VIS_CLASSIFY,
    .name = "vis-classify",
    .programs = {{"vis-classify", NULL, NULL, "vis_classify.comp.glsl"}},
    .targets = {&tl__target_vis_id, &tl__target_vis_tiles},
    .declare = tl__vis_classify_declare,
    .permute = tl__vis_permute_samples,
    .execute = tl__vis_classify_execute,
    .services = TL__PASS_LIGHTS,
};

/* ---- vis-resolve ----------------------------------------------------------------------------- */

static void tl__vis_resolve_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->mode->visibility) return;
    d->samples = TL__B(VIS_ID) | (tl__ssao_pass(in) ? TL__B(AO) : 0u);
    d->reads = d->samples | TL__B(VIS_TILES) | (in->lights ? TL__B(LIGHT_LISTS) : 0u);
    d->writes = d->images = TL__B(HDR);
    d->compute = 1;
    d->light_data = in->lights ? TL__LIGHTS_VIEW | TL__LIGHTS_TILES : 0u;
}

static void tl__vis_resolve_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    tl__perm *k = &out->slot[0];
    out->used[0] = 1;
    tl__perm_flag(k, TL__F_FORWARD);
    if (d->reads & TL__B(LIGHT_LISTS)) tl__perm_flag(k, TL__F_FORWARD_TILED); /* else no light: the ambient terms */
    tl__perm_merge(k, &in->spec_perm);
    tl__perm_merge(k, &in->material);
    tl__ssao_perm(in, d, k);
    tl__vis_samples(in, k);
}

/* The id's split refused past its bits, naming the object (the visible opaque ones: those drawn). */
static tl_result tl__vis_resolve_prepare(const tl__pass_ctx *ctx, const tl__view *v, const tl_renderer_options *o)
{
    (void)v;
    (void)o;
    const tl__scene_gpu *g = ctx->scene;
    const size_t max_objects = ((size_t)1 << (32 - TL__VIS_TRIANGLE_BITS)) - 1u;
    const size_t max_triangles = (size_t)1 << TL__VIS_TRIANGLE_BITS;
    for (size_t j = 0; j < g->visible_opaque; j++) {
        uint32_t i = g->visible[j];
        if (i >= max_objects)
            return tl__fail(ctx->device, TL_ERROR_LIMIT,
                            "renderer: mode visibility: object %u is past the %zu objects the id's %d object bits hold",
                            i, max_objects, 32 - TL__VIS_TRIANGLE_BITS);
        if (g->objects[i].index_count / 3u > max_triangles)
            return tl__fail(ctx->device, TL_ERROR_LIMIT,
                            "renderer: mode visibility: object %u draws %zu triangles, more than the %zu the id's %d "
                            "triangle bits hold",
                            i, (size_t)(g->objects[i].index_count / 3u), max_triangles, TL__VIS_TRIANGLE_BITS);
    }
    return TL_OK;
}

static void tl__vis_resolve_execute(const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = ctx->gl;
    const tl__scene_gpu *g = ctx->scene;
    GLuint tiles = ctx->lights->vis.buffer;
    gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, TL__SSBO_VIS_VERTICES, g->vbo);
    gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, TL__SSBO_VIS_INDICES, g->ibo);
    gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, TL__SSBO_VIS_TILES, tiles);
    if (g->vbo_colors) gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, TL__SSBO_VIS_COLORS, g->vbo_colors);
    if (g->vbo_uv1) gl->BindBufferBase(GL_SHADER_STORAGE_BUFFER, TL__SSBO_VIS_UV1, g->vbo_uv1);
    gl->BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, tiles);
    tl__state_program(gl, ctx->state, ctx->programs[0]);
    /* each material drawn opaque, once: its bucket's tiles */
    for (size_t m = 0; m < g->material_count || (m == 0 && !g->material_count); m++) {
        if (g->material_count && (!g->material_uses[m] || (g->materials[m].flags & TL_MATERIAL_ALPHA_BLEND))) continue;
        tl__bind_material(gl, g, (uint32_t)m);
        gl->DispatchComputeIndirect((GLintptr)((m % TL__VIS_BUCKETS) * TL__VIS_DISPATCH_BYTES));
        ctx->out->draw_calls++;
    }
    gl->BindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    /* the bytes-moved estimate's vertex fetch: each pixel reads its triangle's three indices and
     * vertices (an upper bound: neighbours share them in caches) */
    ctx->out->indices += (size_t)3u * ctx->width * ctx->height;
    gl->MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

const tl__pass_def tl__pass_vis_resolve = {
    .id = TL_PASS_VIS_RESOLVE,
    .name = "vis-resolve",
    .programs = {{"vis-resolve", NULL, NULL, "vis_resolve.comp.glsl"}},
    .declare = tl__vis_resolve_declare,
    .permute = tl__vis_resolve_permute,
    .execute = tl__vis_resolve_execute,
    .prepare = tl__vis_resolve_prepare,
    /* the shadows service also hands the device, where prepare's refusal is logged */
    .services = TL__PASS_SCENE | TL__PASS_LIGHTS | TL__PASS_SHADOWS,
};
