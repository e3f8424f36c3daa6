/* The shadow-debug pass (docs/shadows.md, "Debug views"): with tl_renderer_options.shadow_debug, a
 * full-screen pass after the frame's opaque lighting reads the surface as the light pass does
 * (depth and RT0; fat: its position and normal; forward: depth, with the faces' normals from its
 * neighbours) and writes shadow.debug: the shadow-only term, its weight, the cascade coordinate of
 * the first casting directional light and a surface flag. Its program is the only one with
 * TL_SHADOW_DEBUG; without the option the pass is not declared and the plan is the plan without it. */
#include <stdio.h>

#include "gl/gl.h"
#include "pass.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static const tl__target_def tl__target_shadow_debug = {TL__TARGET(SHADOW_DEBUG, "shadow.debug"), .format = GL_RGBA16F};

/* tl_renderer_options.shadow_debug in the option registry. */
static const tl_option_info tl__shadow_debug_rows[] = {
    TL__OPT_BOOL(shadow_debug, "the frame also writes shadow.debug (shadow term, cascade)"),
};

int tl__shadow_debug_planned(const tl__plan_input *in)
{
    /* a multisampled G-buffer or forward depth would need a sample chosen: not built */
    return in->o->shadow_debug && in->shadows && tl__gbuffer_samples(in->o) <= 1 && !(in->mode->forward && in->msaa > 1);
}

static void tl__shadow_debug_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!tl__shadow_debug_planned(in)) return;
    int fat = in->o->mode == TL_MODE_FAT;
    d->writes = d->clears = d->sinks = TL__B(SHADOW_DEBUG);
    d->reads = d->samples = fat ? TL__B(FAT_POSITION) | TL__B(FAT_NORMAL)
                            : in->mode->forward ? TL__B(DEPTH) : TL__B(DEPTH) | TL__B(RT0);
    d->light_data = TL__LIGHTS_VIEW;
    d->state = (tl__pipeline){.color_write = 1};
}

static void tl__shadow_debug_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    tl__perm *k = &out->slot[0];
    out->used[0] = 1;
    tl__perm_flag(k, TL__F_SHADOW_DEBUG);
    if (in->o->mode == TL_MODE_FAT) tl__perm_flag(k, TL__F_SHADOW_DEBUG_FAT);
    else if (in->mode->forward) tl__perm_flag(k, TL__F_SHADOW_DEBUG_DEPTH_NORMALS);
    tl__perm_merge(k, &in->spec_perm);
    tl__perm_flag(k, in->rt0_flag);
}

const tl__pass_def tl__pass_shadow_debug = {
    .id = TL_PASS_SHADOW_DEBUG,
    .name = "shadow-debug",
    .programs = {{"shadow-debug", "fullscreen.vert.glsl", "shadow_debug.frag.glsl"}},
    .targets = {&tl__target_shadow_debug},
    TL__OPTIONS(shadow_debug, tl__shadow_debug_rows),
    .declare = tl__shadow_debug_declare,
    .permute = tl__shadow_debug_permute,
    .execute = tl__draw_fullscreen,
};
