/* Screen-space reflections (docs/effects.md): the ray march from depth and RT0 (fat: its position
 * and normal targets) into the ssr target, then ssr-apply adds it to HDR. Forward mode has no
 * gloss to read and plans neither. */
#include <stdio.h>

#include "renderer_internal.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static int tl__ssr_fat(const tl__plan_input *in) { return (in->mode->gbuffer_writes & TL__B(FAT_POSITION)) != 0; }

static int tl__ssr_on(const tl__plan_input *in) { return in->d.options.ssr.enabled && !in->mode->forward; }

static void tl__ssr_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!tl__ssr_on(in)) return;
    d->samples = TL__B(HDR) | (tl__ssr_fat(in) ? TL__B(FAT_POSITION) | TL__B(FAT_NORMAL) : TL__B(DEPTH) | TL__B(RT0));
    d->reads = d->samples;
    d->writes = TL__B(SSR);
    d->state = tl__pipeline_fullscreen;
}

static void tl__ssr_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    snprintf(out->slot[0], sizeof out->slot[0], "TL_SSR_STEPS=%u TL_SSR_REFINE=%u %s", in->d.options.ssr.steps,
             in->d.options.ssr.refine, tl__ssr_fat(in) ? "TL_SSAO_FAT" : in->rt0_define);
}

const tl__pass_def tl__pass_ssr = {
    .id = TL_PASS_SSR,
    .name = "ssr",
    .programs = {{"ssr", "fullscreen.vert.glsl", "ssr.frag.glsl"}},
    .declare = tl__ssr_declare,
    .permute = tl__ssr_permute,
    .execute = tl__draw_fullscreen,
};

static void tl__ssr_apply_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!tl__ssr_on(in)) return;
    d->reads = d->samples = TL__B(SSR);
    d->reads |= TL__B(HDR);
    d->writes = TL__B(HDR);
    d->state = tl__pipeline_fullscreen;
    d->state.blend = TL__BLEND_ADD;
}

const tl__pass_def tl__pass_ssr_apply = {
    .id = TL_PASS_SSR_APPLY,
    .name = "ssr-apply",
    .programs = {{"ssr-apply", "fullscreen.vert.glsl", "ssr_apply.frag.glsl"}},
    .declare = tl__ssr_apply_declare,
    .permute = tl__permute_one_program,
    .execute = tl__draw_fullscreen,
};
