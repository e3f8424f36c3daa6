/* The tiled strategy's passes (docs/frame.md): light-cull (a compute pass: per-tile depth
 * bounds and light lists, tiles.c) and the tiled light pass (every pixel once, looping over its
 * tile's lights: a full-screen triangle, or a compute pass). The light pass reads and writes what
 * the volumes' would in the mode, so the strategies differ only in how lights are gathered. */
#include <stdio.h>

#include "lights.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static int tl__tiled(const tl__plan_input *in) { return in->lights && in->strategy == TL_LIGHT_STRATEGY_TILED; }

/* The tile lists are built for the tiled strategy, and with a light scale below 1 for light-upsample's
 * re-lit pixels whatever the strategy (pass_light_upsample.c). */
static int tl__tile_lists(const tl__plan_input *in)
{
    return tl__tiled(in) || (in->lights && in->light_shift && in->mode->material_pass);
}

/* The light lists' bytes for a number of tiles: 4 counters, (offset, count) per tile, entries. */
static size_t tl__light_lists_bytes(const tl_frame_plan *p, const tl_renderer_options *o)
{
    (void)o;
    size_t tiles = (size_t)p->tiles_x * p->tiles_y;
    return 16u + 8u * tiles + 4u * TL__TILE_START_ENTRIES * tiles;
}

static const tl__target_def tl__target_light_lists = {TL__TARGET(LIGHT_LISTS, "light.lists"),
                                                      .buffer_bytes = tl__light_lists_bytes, .store = TL__STORE_LISTS};

/* ---- light-cull -------------------------------------------------------------------------------- */

static void tl__cull_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!tl__tile_lists(in)) return;
    /* MSAA in thin-lpp: the tiles' bounds cover every sample's depth (the multisampled depth the
     * material pass tests against), so the edge samples it re-lights from the lists miss no light */
    d->reads = d->samples = TL_TARGET_BIT(tl__shading_depth(in)); /* depth.msaa, or DEPTH (per-sample edges) */
    d->writes = TL__B(LIGHT_LISTS);
    d->compute = 1;
    d->light_data = TL__LIGHTS_VIEW | TL__LIGHTS_TILES;
}

static void tl__cull_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    out->used[0] = 1;
    /* the light scale: tiles are in the frame's pixels (their depth bounds cover every pixel the
     * edge fix-up may re-light); the pairs counted are the light buffer's texels. Forward's depth is
     * multisampled with MSAA, and thin-lpp's cull reads its material pass's (pass_geometry.c) */
    if (in->msaa > 1) {
        tl__perm_value(&out->slot[0], TL__V_DEPTH_SAMPLES, in->msaa);
        if (d->samples & TL__B(DEPTH_MSAA)) tl__perm_flag(&out->slot[0], TL__F_CULL_DEPTH_MSAA);
    } else if (in->light_shift) {
        tl__perm_value(&out->slot[0], TL__V_LIGHT_SHIFT, in->light_shift);
        /* with volumes the lists serve light-upsample's re-lit pixels: the volumes count the pairs */
        if (!tl__tiled(in)) tl__perm_flag(&out->slot[0], TL__F_CULL_NO_PAIRS);
    }
}

const tl__pass_def tl__pass_light_cull = {
    .id = TL_PASS_LIGHT_CULL,
    .name = "light-cull",
    .programs = {{"light-cull", NULL, NULL, "light_cull.comp.glsl"}},
    .targets = {&tl__target_light_lists},
    .declare = tl__cull_declare,
    .permute = tl__cull_permute,
    .execute = tl__tiles_cull,
    .services = TL__PASS_LIGHTS,
};

/* ---- the tiled light pass ---------------------------------------------------------------------- */

static int tl__compute_shading(const tl__plan_input *in) { return in->tiled_compute; }

static void tl__tiled_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!tl__tiled(in) || in->mode->forward || in->mode->visibility) return; /* vis-resolve lights itself */
    tl__light_pass_targets(in, d);
    d->reads |= TL__B(LIGHT_LISTS);
    d->light_data = TL__LIGHTS_VIEW | TL__LIGHTS_TILES;
    int shade = (d->writes & TL__B(HDR)) != 0;
    if (tl__compute_shading(in)) {
        d->compute = 1;
        d->images = d->writes;
    } else {
        /* a full-screen triangle writes every pixel of the light buffer: nothing to clear; shading
         * adds to HDR once per pixel */
        d->state = (tl__pipeline){.color_write = 1, .blend = (uint8_t)(shade ? TL__BLEND_ADD : TL__BLEND_OFF)};
    }
}

static void tl__tiled_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    int slot = tl__compute_shading(in);
    tl__perm *k = &out->slot[slot];
    out->used[slot] = 1;
    tl__perm_flag(k, in->mode->light_flag);
    tl__light_pass_defines(in, d, k);
    tl__perm_merge(k, &in->spec_perm);
    if (slot)
        tl__perm_value(k, TL__V_LIGHT_IMAGE_FORMAT, in->o->light_format == TL_LIGHT_FORMAT_R11G11B10F
                                                        ? TL__IMAGE_FORMAT_R11G11B10F : TL__IMAGE_FORMAT_RGBA16F);
}

static void tl__tiled_execute(const tl__pass_ctx *ctx)
{
    const GladGLContext *gl = ctx->gl;
    if (ctx->programs[0]) { /* fragment */
        tl__state_program(gl, ctx->state, ctx->programs[0]);
        tl__state_vertex_array(gl, ctx->state, ctx->fullscreen_vao);
        gl->DrawArrays(GL_TRIANGLES, 0, 3);
        ctx->out->draw_calls++;
        return;
    }
    tl__state_program(gl, ctx->state, ctx->programs[1]);
    uint32_t k = (1u << ctx->light_shift) - 1u, w = (ctx->width + k) >> ctx->light_shift, h = (ctx->height + k) >> ctx->light_shift;
    /* MSAA per-sample edges: an invocation per sample of an edge pixel (lights_tiled.comp.glsl) */
    gl->DispatchCompute((w + 7) / 8, (h + 7) / 8, ctx->gbuffer_samples);
    gl->MemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
}

const tl__pass_def tl__pass_lights_tiled = {
    .id = TL_PASS_LIGHTS_TILED,
    .name = "lights-tiled",
    .programs = {{"lights.tiled", "fullscreen.vert.glsl", "lights_tiled.frag.glsl", NULL},
                 {"lights.tiled", NULL, NULL, "lights_tiled.comp.glsl"}},
    .declare = tl__tiled_declare,
    .permute = tl__tiled_permute,
    .execute = tl__tiled_execute,
};
