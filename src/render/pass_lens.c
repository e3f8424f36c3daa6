/* Effects over the finished HDR image (docs/effects.md): fog from linear depth blended over it,
 * and depth of field (a gather blur into the dof target, then copied back into HDR). */
#include <stdio.h>

#include "renderer_internal.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

/* ---- fog: HDR = HDR T + colour (1 - T) ------------------------------------------------------- */

static void tl__fog_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (in->d.options.fog.mode == TL_FOG_OFF) return;
    d->samples = TL__B(DEPTH);
    d->reads = TL__B(DEPTH) | TL__B(HDR);
    d->writes = TL__B(HDR);
    d->state = tl__pipeline_fullscreen;
    d->state.blend = TL__BLEND_ALPHA;
}

static void tl__fog_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    snprintf(out->slot[0], sizeof out->slot[0], "%s%s", in->d.options.fog.mode == TL_FOG_HEIGHT ? "TL_FOG_HEIGHT" : "TL_FOG_DISTANCE",
             in->d.options.fog.noise > 0.0f ? " TL_FOG_NOISE" : "");
}

const tl__pass_def tl__pass_fog = {
    .id = TL_PASS_FOG,
    .name = "fog",
    .programs = {{"fog", "fullscreen.vert.glsl", "fog.frag.glsl"}},
    .declare = tl__fog_declare,
    .permute = tl__fog_permute,
    .execute = tl__draw_fullscreen,
};

/* ---- depth of field -------------------------------------------------------------------------- */

static void tl__dof_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->d.options.dof.enabled) return;
    d->reads = d->samples = TL__B(DEPTH) | TL__B(HDR);
    d->writes = TL__B(DOF);
    d->state = tl__pipeline_fullscreen;
}

static void tl__dof_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    snprintf(out->slot[0], sizeof out->slot[0], "TL_DOF_SAMPLES=%u", in->d.options.dof.samples);
}

const tl__pass_def tl__pass_dof = {
    .id = TL_PASS_DOF,
    .name = "dof",
    .programs = {{"dof", "fullscreen.vert.glsl", "dof.frag.glsl"}},
    .declare = tl__dof_declare,
    .permute = tl__dof_permute,
    .execute = tl__draw_fullscreen,
};

static void tl__dof_apply_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->d.options.dof.enabled) return;
    d->reads = d->samples = TL__B(DOF);
    d->writes = TL__B(HDR);
    d->state = tl__pipeline_fullscreen;
}

const tl__pass_def tl__pass_dof_apply = {
    .id = TL_PASS_DOF_APPLY,
    .name = "dof-apply",
    .programs = {{"dof-apply", "fullscreen.vert.glsl", "dof_apply.frag.glsl"}},
    .declare = tl__dof_apply_declare,
    .permute = tl__permute_one_program,
    .execute = tl__draw_fullscreen,
};
