/* The sky pass: the background colour, or the environment, where no geometry was drawn. A full-
 * screen triangle at the cleared depth (far, or 0 with reversed Z), depth-tested against the depth
 * the frame's surfaces were drawn with, so it writes exactly the background pixels of HDR (every
 * sample of them with MSAA) and nothing else. It runs after the opaque frame and before points,
 * lines and transparent surfaces, which blend over it. Planned only when the background is not
 * black or an environment is set: otherwise the frame is the one it always was. */
#include <math.h>
#include <stdio.h>

#include "pass.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

/* tl_environment_options in the option registry (docs/renderer.md, "Background and environment"). */
static const tl_option_info tl__environment_rows[] = {
    TL__OPT_FLOAT3(environment.background, 0.0, 65504.0, 0, NULL, "linear radiance",
                   "background where no geometry is drawn and no environment is set (0: black, no sky pass)"),
    TL__OPT_FLOAT(environment.intensity, 0.0, 65504.0, TL_OPTION_MIN_OPEN, 1, NULL, "",
                  "scales the environment, as sky and as light"),
};

/* std140 block tl_sky_block of shaders/sky.frag.glsl: the background, the intensity. */
static void tl__sky_params(const tl_renderer_options *o, const tl__view *v, void *block)
{
    (void)v;
    float *b = (float *)block;
    for (int k = 0; k < 3; k++) b[k] = o->environment.background[k];
    b[3] = o->environment.intensity;
}

static void tl__sky_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    const float *bg = in->o->environment.background;
    if (!in->f.has_environment && bg[0] == 0.0f && bg[1] == 0.0f && bg[2] == 0.0f) return;
    /* with the stipple, transparent layers took some of DEPTH's pixels: the opaque depth has the sky */
    d->depth_target = (uint8_t)(in->stipple ? TL_TARGET_OPAQUE_DEPTH : tl__shading_depth(in));
    d->writes = TL__B(HDR);
    d->reads = TL__B(HDR) | TL_TARGET_BIT(d->depth_target); /* drawn onto, depth-tested */
    d->attach_depth = 1;
    d->state = (tl__pipeline){.depth_test = TL__DEPTH_LEQUAL, .color_write = 1,
                              .clip_zero_one = in->o->depth_format == TL_DEPTH_FORMAT_D32F_REVERSED};
}

static void tl__sky_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    int reversed = in->o->depth_format == TL_DEPTH_FORMAT_D32F_REVERSED;
    tl__perm_value(&out->slot[0], TL__V_FULLSCREEN_DEPTH, reversed ? TL__DEPTH_FAR_ZERO : TL__DEPTH_FAR_ONE);
    if (in->f.has_environment) tl__perm_flag(&out->slot[0], TL__F_SKY_ENV);
}

const tl__pass_def tl__pass_sky = {
    .id = TL_PASS_SKY,
    .name = "sky",
    .programs = {{"sky", "fullscreen.vert.glsl", "sky.frag.glsl"}},
    TL__OPTIONS(environment, tl__environment_rows),
    .params_size = 4 * sizeof(float),
    .params = tl__sky_params,
    .declare = tl__sky_declare,
    .permute = tl__sky_permute,
    .execute = tl__draw_fullscreen,
};
