/* Screen-space ambient occlusion (docs/effects.md): the estimator (ssao: the slides' disc estimator
 * or a normal-oriented hemisphere) from depth and RT0, the fat G-buffer's position and normal, or
 * (forward) depth alone with normals rebuilt from it; a depth-aware blur (ssao-blur); and in the
 * modes that write the ambient term in the G-buffer pass, ssao-apply, which takes the occluded
 * part of it from HDR. In thin-lpp and forward the shading pass reads the AO target itself. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gl/gl.h"
#include "pass.h"
#include "view.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

static const tl__target_def tl__target_ao_raw = {TL__TARGET(AO_RAW, "ao.raw"), .format = GL_R16F};
static const tl__target_def tl__target_ao = {TL__TARGET(AO, "ao"), .format = GL_R16F};

/* tl_ssao_desc in the option registry (docs/effects.md). */
static const tl_option_info tl__ssao_rows[] = {
    TL__OPT_BOOL(ssao.enabled, "screen-space ambient occlusion"),
    TL__OPT_ENUM(ssao.method, tl_ssao_method, TL_SSAO_COUNT_, TL_SSAO_DISC, NULL,
                 "SSAO estimator: the slides' Poisson disc, or a normal-oriented hemisphere"),
    TL__OPT_UINT(ssao.samples, 1, 64, 0, 16, "samples", "SSAO: samples per pixel"),
    TL__OPT_FLOAT(ssao.radius, TL__OPT_ABOVE_0, 1, NULL, "view units", "SSAO: radius of the neighbourhood"),
    TL__OPT_FLOAT(ssao.bias, 0.0, TL__OPT_FINITE, 0, 0, NULL, "view units", "SSAO: k_b, distance that occludes fully"),
    TL__OPT_FLOAT(ssao.falloff, TL__OPT_ABOVE_0, 0, "2 x radius", "view units", "SSAO: k_d, width of the fall-off after k_b"),
    TL__OPT_FLOAT(ssao.exponent, TL__OPT_ABOVE_0, 3, NULL, "", "SSAO: exponent x of each sample's term"),
    TL__OPT_UINT(ssao.blur_radius, 1, 8, 0, 2, "px", "SSAO: half-width of the depth-aware blur"),
    TL__OPT_BOOL(ssao.diffuse, "SSAO also scales the diffuse light (thin-lpp, forward)"),
};

/* Off: zeroed whole; the fall-off follows the radius. */
static void tl__ssao_resolve(void *options)
{
    tl_ssao_desc *s = (tl_ssao_desc *)options;
    if (!s->enabled) memset(s, 0, sizeof *s);
    else if (s->falloff == 0.0f) s->falloff = 2.0f * s->radius;
}

/* std140 block tl_ssao_block of shaders/ssao.frag.glsl: radius, k_b, k_d, exponent. */
static void tl__ssao_params(const tl_renderer_options *o, const tl__view *v, void *block)
{
    (void)v;
    const tl_ssao_desc *s = &o->ssao;
    float *b = (float *)block;
    b[0] = s->radius;
    b[1] = s->bias;
    b[2] = s->falloff;
    b[3] = s->exponent;
}

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
    tl__perm *k = &out->slot[0];
    out->used[0] = 1;
    tl__perm_flag(k, in->o->ssao.method == TL_SSAO_HEMISPHERE ? TL__F_SSAO_HEMISPHERE : TL__F_SSAO_DISC);
    tl__perm_value(k, TL__V_SSAO_SAMPLES, in->o->ssao.samples);
    tl__perm_flag(k, tl__ssao_fat(in) ? TL__F_SSAO_FAT : in->mode->forward ? TL__F_SSAO_DEPTH_NORMALS : in->rt0_flag);
}

static int tl__ssao_wanted(const tl_renderer_options *o) { return o->ssao.enabled; }

const tl__pass_def tl__pass_ssao = {
    .id = TL_PASS_SSAO,
    .name = "ssao",
    .programs = {{"ssao", "fullscreen.vert.glsl", "ssao.frag.glsl"}},
    .targets = {&tl__target_ao_raw, &tl__target_ao},
    TL__OPTIONS(ssao, tl__ssao_rows),
    .resolve = tl__ssao_resolve,
    .params_size = 4 * sizeof(float),
    .params = tl__ssao_params,
    .declare = tl__ssao_declare,
    .permute = tl__ssao_permute,
    .execute = tl__draw_fullscreen,
    .wanted = tl__ssao_wanted,
    .refuses = TL__REFUSES_MSAA,
    .refuses_why = {"SSAO reads a one-sample depth and HDR", NULL},
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
    tl__perm_value(&out->slot[0], TL__V_SSAO_BLUR_RADIUS, in->o->ssao.blur_radius);
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
    if (tl__ssao_fat(in)) tl__perm_flag(&out->slot[0], TL__F_SSAO_FAT);
}

const tl__pass_def tl__pass_ssao_apply = {
    .id = TL_PASS_SSAO_APPLY,
    .name = "ssao-apply",
    .programs = {{"ssao-apply", "fullscreen.vert.glsl", "ssao_apply.frag.glsl"}},
    .declare = tl__ssao_apply_declare,
    .permute = tl__ssao_apply_permute,
    .execute = tl__draw_fullscreen,
};
