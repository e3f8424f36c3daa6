/* The shadow atlas as a pass of the frame (docs/shadows.md): first in the frame, it renders the
 * casting lights' views that changed into the atlas and binds it, with the lookup block, for the
 * lighting passes. The atlas is the shadow module's (shadows.c): it keeps unchanged maps from frame
 * to frame, so it is a target the graph accounts for (its bytes count against max_target_bytes)
 * but never allocates, and a sink (never culled). Its GPU time is the pass's, like every pass's. */
#include <stdio.h>
#include <string.h>

#include "lights.h"
#include "shadows.h"

/* The atlas's bytes: atlas_size^2 reversed D32F texels. */
static size_t tl__atlas_bytes(const tl_frame_plan *p, const tl_renderer_options *o)
{
    (void)p;
    return (size_t)o->shadows.atlas_size * o->shadows.atlas_size * 4u;
}

/* (its macro is not SHADOW_ATLAS: TL_UNIT_SHADOW_ATLAS is the unit the lookups read it on, bindings.h) */
static const tl__target_def tl__target_shadow_atlas = {.id = TL_TARGET_SHADOW_ATLAS, .name = "shadow.atlas",
                                                       .macro = "ATLAS", .buffer_bytes = tl__atlas_bytes};

/* Shadows (docs/shadows.md): only with a casting light that some lighting pass evaluates; every
 * lighting program then has TL_SHADOWS (and TL_PCSS with that filter). Without one the plan is
 * exactly the plan without shadows. */
void tl__shadows_plan(tl__plan_input *in)
{
    if (!in->lights || !in->f.shadow_lights || in->o->shadows.enabled == TL_SWITCH_OFF) return;
    in->shadows = (uint32_t)in->f.shadow_lights;
    tl__perm_flag(&in->spec_perm, TL__F_SHADOWS);
    if (in->o->shadows.filter == TL_SHADOW_FILTER_PCSS) tl__perm_flag(&in->spec_perm, TL__F_PCSS);
}

static void tl__shadows_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->shadows) return;
    d->writes = d->sinks = TL_TARGET_BIT(TL_TARGET_SHADOW_ATLAS);
    d->compute = 1; /* it draws into the module's framebuffer with its own state */
}

/* The casting lights' views (shadow_views.c) and each light's shadow slot, before the lights'
 * data is made. */
static tl_result tl__shadows_prepare_pass(const tl__pass_ctx *ctx, const tl__view *v, const tl_renderer_options *o)
{
    tl_result res = tl__shadows_prepare(ctx->device, ctx->shadows, ctx->lights, ctx->scene, v, o, ctx->stats);
    if (res == TL_OK) ctx->lights->shadow_slots = ctx->shadows->slots;
    return res;
}

/* Its program is the module's (shadow_views.c builds it with the atlas). */
static void tl__shadows_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)in;
    (void)d;
    (void)out;
}

static void tl__shadows_execute(const tl__pass_ctx *ctx)
{
    ctx->out->draw_calls += tl__shadows_render(ctx->device, ctx->shadows, ctx->scene, ctx->stats);
}

/* Its time is the maps': shadow_ms when any was rendered this frame (0 when all were cached). */
static void tl__shadows_collect(const uint64_t *results, uint64_t fragments, uint64_t pixels, double ms,
                                tl_frame_stats *st)
{
    (void)results;
    (void)fragments;
    (void)pixels;
    st->shadow_ms = st->shadow_maps_rendered && ms > 0.0 ? ms : 0.0;
}

const tl__pass_def tl__pass_shadows = {
    .id = TL_PASS_SHADOWS,
    .name = "shadows",
    .targets = {&tl__target_shadow_atlas},
    .declare = tl__shadows_declare,
    .permute = tl__shadows_permute,
    .execute = tl__shadows_execute,
    .collect = tl__shadows_collect,
    .prepare = tl__shadows_prepare_pass,
    .services = TL__PASS_SCENE | TL__PASS_LIGHTS | TL__PASS_SHADOWS,
};
