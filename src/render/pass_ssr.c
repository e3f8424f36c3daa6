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

/* tl_ssr_desc's defaults (docs/effects.md); 0 for values out of range. */
static int tl__ssr_resolve(void *options, const char *prefix, tl__why *why)
{
    tl_ssr_desc *s = (tl_ssr_desc *)options;
    if (!s->enabled) {
        memset(s, 0, sizeof *s);
        return 1;
    }
    s->enabled = 1;
    if (!s->steps) s->steps = 48;
    if (!s->refine) s->refine = 4;
    if (!(s->max_distance > 0.0f)) s->max_distance = 16.0f;
    if (!(s->thickness > 0.0f)) s->thickness = 0.4f;
    if (!(s->min_gloss > 0.0f)) s->min_gloss = s->min_gloss == 0.0f ? 0.4f : 0.0f;
    if (!(s->edge_fade > 0.0f)) s->edge_fade = 0.1f;
    if (!(s->intensity > 0.0f)) s->intensity = 1.0f;
    const tl__option_range rows[] = {
        TL__RANGE_INT(s->steps < 4 || s->steps > 256, "steps", s->steps, "4..256; 0: 48"),
        TL__RANGE_INT(s->refine > 8, "refine", s->refine, "1..8; 0: 4"),
        TL__RANGE_FLOAT(!isfinite(s->max_distance), "max_distance", s->max_distance, "finite; <= 0: 16"),
        TL__RANGE_FLOAT(!isfinite(s->thickness), "thickness", s->thickness, "finite; <= 0: 0.4"),
        TL__RANGE_FLOAT(!(s->min_gloss < 1.0f), "min_gloss", s->min_gloss, "[0, 1); 0: 0.4, < 0: 0"),
        TL__RANGE_FLOAT(!(s->edge_fade <= 0.5f), "edge_fade", s->edge_fade, "(0, 0.5]; <= 0: 0.1"),
        TL__RANGE_FLOAT(!isfinite(s->intensity), "intensity", s->intensity, "finite; <= 0: 1"),
    };
    return tl__option_ranges(rows, sizeof rows / sizeof rows[0], prefix, why);
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
    TL__OPTIONS(ssr),
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
