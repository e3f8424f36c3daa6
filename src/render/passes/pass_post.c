/* Full-screen passes: tone mapping (into LDR for FXAA, or straight into the output), FXAA, and the
 * luma pass that prepares a caller's image for tl_renderer_apply_fxaa. */
#include <stdio.h>

#include "gl/gl.h"
#include "pass.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static const tl__target_def tl__target_ldr = {TL__TARGET(LDR, "ldr"), .format = GL_RGBA8};
static const tl__target_def tl__target_output = {TL__TARGET(OUTPUT, "output"), .format = GL_RGBA8, .frame_output = 1};

/* std140 block tl_tonemap_block of shaders/tonemap.frag.glsl. */
typedef struct tl__tonemap_block {
    float exposure, bloom_intensity, pad[2];
} tl__tonemap_block;

static void tl__tonemap_params(const tl_renderer_options *o, const tl__view *v, void *block)
{
    (void)v;
    tl__tonemap_block *b = (tl__tonemap_block *)block;
    *b = (tl__tonemap_block){o->exposure, o->bloom.intensity, {0, 0}};
}

/* std140 block tl_fxaa_block of shaders/fxaa.frag.glsl. */
typedef struct tl__fxaa_block {
    float subpix, edge_threshold, edge_threshold_min, pad;
} tl__fxaa_block;

static void tl__fxaa_params(const tl_renderer_options *o, const tl__view *v, void *block)
{
    (void)v;
    tl__fxaa_block *b = (tl__fxaa_block *)block;
    *b = (tl__fxaa_block){o->fxaa_subpix, o->fxaa_edge_threshold, o->fxaa_edge_threshold_min, 0};
}

/* ---- tone map -------------------------------------------------------------------------------- */

static void tl__tonemap_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    d->reads = d->samples = TL__B(HDR) | (in->o->bloom.enabled ? TL__B(BLOOM) : 0u);
    d->writes = in->o->fxaa != TL_FXAA_OFF ? TL__B(LDR) : TL__B(OUTPUT);
    d->state = tl__pipeline_fullscreen;
}

static void tl__tonemap_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    out->used[0] = 1;
    if (in->msaa > 1) tl__perm_value(&out->slot[0], TL__V_MSAA_SAMPLES, in->msaa); /* HDR is multisampled (pass_geometry.c) */
    else if (d->samples & TL__B(BLOOM)) tl__perm_flag(&out->slot[0], TL__F_BLOOM);
}

/* Into a caller's framebuffer of another size the image is resampled: linear filtering then. */
static void tl__tonemap_execute(const tl__pass_ctx *ctx)
{
    if (ctx->to_caller) ctx->gl->BindSampler(ctx->unit_of[TL_TARGET_HDR], ctx->linear_sampler); /* a multisampled HDR ignores it */
    tl__draw_fullscreen(ctx);
    if (ctx->to_caller) ctx->gl->BindSampler(ctx->unit_of[TL_TARGET_HDR], 0);
}

const tl__pass_def tl__pass_tonemap = {
    .id = TL_PASS_TONEMAP,
    .name = "tonemap",
    .programs = {{"tonemap", "fullscreen.vert.glsl", "tonemap.frag.glsl"}},
    .targets = {&tl__target_ldr, &tl__target_output},
    .params_size = sizeof(tl__tonemap_block),
    .params = tl__tonemap_params,
    .declare = tl__tonemap_declare,
    .permute = tl__tonemap_permute,
    .execute = tl__tonemap_execute,
};

/* ---- FXAA ------------------------------------------------------------------------------------ */

static void tl__fxaa_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (in->o->fxaa == TL_FXAA_OFF) return;
    d->reads = d->samples = TL__B(LDR);
    d->writes = TL__B(OUTPUT);
    d->state = tl__pipeline_fullscreen;
}

static void tl__fxaa_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    tl__perm_value(&out->slot[0], TL__V_FXAA_STEPS, in->o->fxaa == TL_FXAA_12 ? 5u : 12u);
    if (in->o->fxaa == TL_FXAA_39) tl__perm_flag(&out->slot[0], TL__F_FXAA_FINE);
}

/* FXAA samples between texels: linear filtering always. */
static void tl__fxaa_execute(const tl__pass_ctx *ctx)
{
    ctx->gl->BindSampler(ctx->unit_of[TL_TARGET_LDR], ctx->linear_sampler);
    tl__draw_fullscreen(ctx);
    ctx->gl->BindSampler(ctx->unit_of[TL_TARGET_LDR], 0);
}

const tl__pass_def tl__pass_fxaa = {
    .id = TL_PASS_FXAA,
    .name = "fxaa",
    .programs = {{"fxaa", "fullscreen.vert.glsl", "fxaa.frag.glsl"}},
    .params_size = sizeof(tl__fxaa_block),
    .params = tl__fxaa_params,
    .declare = tl__fxaa_declare,
    .permute = tl__fxaa_permute,
    .execute = tl__fxaa_execute,
};

/* ---- luma (tl_renderer_apply_fxaa): the caller's image, uploaded into OUTPUT, gets its luma ---- */

static void tl__luma_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    (void)in;
    d->reads = d->samples = TL__B(OUTPUT);
    d->writes = TL__B(LDR);
    d->state = tl__pipeline_fullscreen;
}

const tl__pass_def tl__pass_luma = {
    .id = TL_PASS_COUNT,
    .name = "luma",
    .programs = {{"luma", "fullscreen.vert.glsl", "luma.frag.glsl"}},
    .declare = tl__luma_declare,
    .permute = tl__permute_one_program,
    .execute = tl__draw_fullscreen,
};
