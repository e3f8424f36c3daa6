/* Screen-space reflections (docs/effects.md): the ray march from depth and RT0 (fat: its position
 * and normal targets) into the ssr target, then ssr-apply adds it to HDR. Forward mode has no
 * gloss to read and plans neither. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gl/gl.h"
#include "pass.h"
#include "view.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static const tl__target_def tl__target_ssr = {TL__TARGET(SSR, "ssr"), .format = GL_RGBA16F};

/* tl_ssr_desc in the option registry (docs/effects.md). */
static const tl_option_info tl__ssr_rows[] = {
    TL__OPT_BOOL(ssr.enabled, "screen-space reflections (thin-lpp, thin-deferred, fat)"),
    TL__OPT_UINT(ssr.steps, 4, 256, 0, 48, "steps", "SSR: linear steps along the ray"),
    TL__OPT_UINT(ssr.refine, 1, 8, 0, 4, "steps", "SSR: binary refinement steps after a hit"),
    TL__OPT_FLOAT(ssr.max_distance, TL__OPT_ABOVE_0, 16, NULL, "view units", "SSR: length of a ray"),
    TL__OPT_FLOAT(ssr.thickness, TL__OPT_ABOVE_0, 0.4, NULL, "view units",
                  "SSR: how far behind a surface a ray still hits it"),
    TL__OPT_FLOAT(ssr.min_gloss, 0.0, 1.0, TL_OPTION_MIN_OPEN | TL_OPTION_MAX_OPEN | TL_OPTION_NEGATIVE_ZERO, 0.4, NULL,
                  "", "SSR: gloss below which a pixel reflects nothing"),
    TL__OPT_FLOAT(ssr.edge_fade, 0.0, 0.5, TL_OPTION_MIN_OPEN, 0.1, NULL, "of the screen",
                  "SSR: where hits fade out at the screen's edges"),
    TL__OPT_FLOAT(ssr.intensity, TL__OPT_ABOVE_0, 1, NULL, "", "SSR: scale of the added reflection"),
};

static void tl__ssr_resolve(void *options)
{
    tl_ssr_desc *s = (tl_ssr_desc *)options;
    if (!s->enabled) memset(s, 0, sizeof *s);
}

/* std140 block tl_ssr_block of shaders/ssr.frag.glsl. */
typedef struct tl__ssr_block {
    float march[4];  /* max distance, thickness, min gloss, edge fade */
    float weight[4]; /* intensity, near plane distance, 0, 0 */
} tl__ssr_block;

static void tl__ssr_params(const tl_renderer_options *o, const tl__view *v, void *block)
{
    const tl_ssr_desc *s = &o->ssr;
    *(tl__ssr_block *)block = (tl__ssr_block){{s->max_distance, s->thickness, s->min_gloss, s->edge_fade},
                                              {s->intensity, v ? v->near_z : 0.0f, 0.0f, 0.0f}};
}

static int tl__ssr_fat(const tl__plan_input *in) { return (in->mode->gbuffer_writes & TL__B(FAT_POSITION)) != 0; }

static int tl__ssr_on(const tl__plan_input *in) { return in->o->ssr.enabled && !in->mode->forward; }

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
    tl__perm *k = &out->slot[0];
    out->used[0] = 1;
    tl__perm_value(k, TL__V_SSR_STEPS, in->o->ssr.steps);
    tl__perm_value(k, TL__V_SSR_REFINE, in->o->ssr.refine);
    tl__perm_flag(k, tl__ssr_fat(in) ? TL__F_SSAO_FAT : in->rt0_flag);
}

/* Forward runs no reflections: they cost it nothing (no MSAA given up). */
static int tl__ssr_wanted(const tl_renderer_options *o) { return o->ssr.enabled && o->mode != TL_MODE_FORWARD; }

const tl__pass_def tl__pass_ssr = {
    .id = TL_PASS_SSR,
    .name = "ssr",
    .programs = {{"ssr", "fullscreen.vert.glsl", "ssr.frag.glsl"}},
    .targets = {&tl__target_ssr},
    TL__OPTIONS(ssr, tl__ssr_rows),
    .resolve = tl__ssr_resolve,
    .params_size = sizeof(tl__ssr_block),
    .params = tl__ssr_params,
    .declare = tl__ssr_declare,
    .permute = tl__ssr_permute,
    .execute = tl__draw_fullscreen,
    .wanted = tl__ssr_wanted,
    .refuses = TL__REFUSES_MSAA | TL__REFUSES_STIPPLE,
    .refuses_why = {"reflections read a one-sample depth and HDR", "reflections read depth after the layers"},
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
