/* Screen-space ambient occlusion (docs/effects.md): the estimator (ssao: the slides' disc estimator
 * or a normal-oriented hemisphere) from depth and RT0, the fat G-buffer's position and normal, or
 * (forward) depth alone with normals rebuilt from it; a depth-aware blur (ssao-blur); and in the
 * modes that write the ambient term in the G-buffer pass, ssao-apply, which takes the occluded
 * part of it from HDR. In thin-lpp and forward the shading pass reads the AO target itself. */
#include <stdio.h>

#include "renderer_internal.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static int tl__ssao_fat(const tl__plan_input *in) { return (in->mode->gbuffer_writes & TL__B(FAT_POSITION)) != 0; }

/* ---- the estimator --------------------------------------------------------------------------- */

static void tl__ssao_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!tl__ssao_pass(in)) return;
    if (tl__ssao_fat(in)) d->samples = TL__B(FAT_POSITION) | TL__B(FAT_NORMAL);
    else if (in->mode->forward) d->samples = TL__B(DEPTH);
    else d->samples = TL__B(DEPTH) | TL__B(RT0);
    d->reads = d->samples;
    d->writes = TL__B(AO_RAW);
    d->state = tl__pipeline_fullscreen;
}

static void tl__ssao_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    const char *source = tl__ssao_fat(in) ? "TL_SSAO_FAT" : in->mode->forward ? "TL_SSAO_DEPTH_NORMALS" : in->rt0_define;
    out->used[0] = 1;
    snprintf(out->slot[0], sizeof out->slot[0], "%s TL_SSAO_SAMPLES=%u %s",
             in->d.options.ssao.method == TL_SSAO_HEMISPHERE ? "TL_SSAO_HEMISPHERE" : "TL_SSAO_DISC", in->d.options.ssao.samples, source);
}

const tl__pass_def tl__pass_ssao = {
    .id = TL_PASS_SSAO,
    .name = "ssao",
    .programs = {{"ssao", "fullscreen.vert.glsl", "ssao.frag.glsl"}},
    .declare = tl__ssao_declare,
    .permute = tl__ssao_permute,
    .execute = tl__draw_fullscreen,
};

/* ---- depth-aware blur ------------------------------------------------------------------------ */

static void tl__ssao_blur_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!tl__ssao_pass(in)) return;
    d->reads = d->samples = TL__B(AO_RAW) | TL__B(DEPTH);
    d->writes = TL__B(AO);
    d->state = tl__pipeline_fullscreen;
}

static void tl__ssao_blur_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    snprintf(out->slot[0], sizeof out->slot[0], "TL_SSAO_BLUR_RADIUS=%u", in->d.options.ssao.blur_radius);
}

const tl__pass_def tl__pass_ssao_blur = {
    .id = TL_PASS_SSAO_BLUR,
    .name = "ssao-blur",
    .programs = {{"ssao-blur", "fullscreen.vert.glsl", "ssao_blur.frag.glsl"}},
    .declare = tl__ssao_blur_declare,
    .permute = tl__ssao_blur_permute,
    .execute = tl__draw_fullscreen,
};

/* ---- apply (thin-deferred, fat): HDR += -(1 - AO) albedo ambient occlusion --------------------- */

static void tl__ssao_apply_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (tl__ssao_pass(in) != 2) return;
    d->samples = TL__B(AO) | (tl__ssao_fat(in) ? TL__B(FAT_ALBEDO) : TL__B(RT1));
    d->reads = d->samples | TL__B(HDR);
    d->writes = TL__B(HDR);
    d->state = tl__pipeline_fullscreen;
    d->state.blend = TL__BLEND_ADD;
}

static void tl__ssao_apply_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    snprintf(out->slot[0], sizeof out->slot[0], "%s", tl__ssao_fat(in) ? "TL_SSAO_FAT" : "");
}

const tl__pass_def tl__pass_ssao_apply = {
    .id = TL_PASS_SSAO_APPLY,
    .name = "ssao-apply",
    .programs = {{"ssao-apply", "fullscreen.vert.glsl", "ssao_apply.frag.glsl"}},
    .declare = tl__ssao_apply_declare,
    .permute = tl__ssao_apply_permute,
    .execute = tl__draw_fullscreen,
};
