/* Effects over the finished HDR image (docs/effects.md): fog from linear depth blended over it,
 * and depth of field (a gather blur into the dof target, then copied back into HDR). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gl/gl.h"
#include "pass.h"
#include "view.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)

/* ---- fog: HDR = HDR T + colour (1 - T) ------------------------------------------------------- */

/* tl_fog_desc in the option registry (docs/effects.md). */
static const tl_option_info tl__fog_rows[] = {
    TL__OPT_BOOL(fog.enabled, "fog"),
    TL__OPT_ENUM(fog.mode, tl_fog_mode, TL_FOG_COUNT_, TL_FOG_DISTANCE, NULL,
                 "fog density: constant, or falling off with height"),
    TL__OPT_FLOAT3(fog.color, 0.0, TL__OPT_FINITE, 0, NULL, "linear radiance", "fog colour (0: black)"),
    TL__OPT_FLOAT(fog.density, TL__OPT_ABOVE_0, 0.05, NULL, "per unit length", "fog: extinction (height fog: at fog.height)"),
    TL__OPT_FLOAT(fog.height, -TL__OPT_FINITE, TL__OPT_FINITE, 0, 0, NULL, "world units", "height fog: y of the reference density"),
    TL__OPT_FLOAT(fog.height_falloff, TL__OPT_ABOVE_0, 0.5, NULL, "per unit of height", "height fog: density fall-off"),
    TL__OPT_FLOAT(fog.noise, 0.0, 1.0, 0, 0, NULL, "", "fog: fractal-noise modulation of the density"),
    TL__OPT_FLOAT(fog.noise_scale, TL__OPT_ABOVE_0, 0.5, NULL, "per unit length", "fog noise: features"),
    TL__OPT_FLOAT(fog.noise_speed, -TL__OPT_FINITE, TL__OPT_FINITE, 0, 0.3, NULL, "units per second", "fog noise: drift"),
};

static void tl__fog_resolve(void *options)
{
    tl_fog_desc *f = (tl_fog_desc *)options;
    if (!f->enabled) memset(f, 0, sizeof *f);
}

/* std140 block tl_fog_block of shaders/fog.frag.glsl. */
typedef struct tl__fog_block {
    float color_density[4]; /* rgb, density */
    float shape[4];         /* height, height falloff, noise, noise scale */
    float motion[4];        /* noise speed, time, 0, 0 */
} tl__fog_block;

static void tl__fog_params(const tl_renderer_options *o, const tl__view *v, void *block)
{
    const tl_fog_desc *f = &o->fog;
    tl__fog_block *b = (tl__fog_block *)block;
    memset(b, 0, sizeof *b);
    memcpy(b->color_density, f->color, sizeof f->color);
    b->color_density[3] = f->density;
    b->shape[0] = f->height;
    b->shape[1] = f->height_falloff;
    b->shape[2] = f->noise;
    b->shape[3] = f->noise_scale;
    b->motion[0] = f->noise_speed;
    b->motion[1] = v ? v->time : 0.0f;
}

static void tl__fog_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->o->fog.enabled) return;
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
    tl__perm_flag(&out->slot[0], in->o->fog.mode == TL_FOG_HEIGHT ? TL__F_FOG_HEIGHT : TL__F_FOG_DISTANCE);
    if (in->o->fog.noise > 0.0f) tl__perm_flag(&out->slot[0], TL__F_FOG_NOISE);
}

static int tl__fog_wanted(const tl_renderer_options *o) { return o->fog.enabled; }

const tl__pass_def tl__pass_fog = {
    .id = TL_PASS_FOG,
    .name = "fog",
    .programs = {{"fog", "fullscreen.vert.glsl", "fog.frag.glsl"}},
    TL__OPTIONS(fog, tl__fog_rows),
    .resolve = tl__fog_resolve,
    .params_size = sizeof(tl__fog_block),
    .params = tl__fog_params,
    .declare = tl__fog_declare,
    .permute = tl__fog_permute,
    .execute = tl__draw_fullscreen,
    .wanted = tl__fog_wanted,
    .refuses = TL__REFUSES_MSAA | TL__REFUSES_STIPPLE,
    .refuses_why = {"fog reads a one-sample depth and HDR", "fog reads depth after the layers"},
};

/* ---- depth of field -------------------------------------------------------------------------- */

static const tl__target_def tl__target_dof = {TL__TARGET(DOF, "dof"), .format = GL_RGBA16F};

/* tl_dof_desc in the option registry (docs/effects.md). */
static const tl_option_info tl__dof_rows[] = {
    TL__OPT_BOOL(dof.enabled, "depth of field"),
    TL__OPT_FLOAT(dof.focus_distance, TL__OPT_ABOVE_0, 0, "the camera's distance to its target", "view units",
                  "depth of field: view distance in focus"),
    TL__OPT_FLOAT(dof.aperture, 0.0, 1.0, TL_OPTION_MIN_OPEN, 0.01, NULL, "of the image height",
                  "depth of field: circle of confusion's radius at infinity"),
    TL__OPT_FLOAT(dof.max_radius, 0.0, 1.0, TL_OPTION_MIN_OPEN, 0, "2 x aperture", "of the image height",
                  "depth of field: largest circle of confusion"),
    TL__OPT_UINT(dof.samples, 8, 128, 0, 48, "taps", "depth of field: gather taps"),
};

/* Off: zeroed whole; the largest circle follows the aperture (a zero focus distance stays: the
 * camera's target, per frame). */
static void tl__dof_resolve(void *options)
{
    tl_dof_desc *f = (tl_dof_desc *)options;
    if (!f->enabled) memset(f, 0, sizeof *f);
    else if (f->max_radius == 0.0f) f->max_radius = 2.0f * f->aperture;
}

/* std140 block tl_dof_block of shaders/dof.frag.glsl: focus distance, aperture, largest CoC, 0. */
static void tl__dof_params(const tl_renderer_options *o, const tl__view *v, void *block)
{
    const tl_dof_desc *d = &o->dof;
    float *b = (float *)block;
    b[0] = d->focus_distance > 0.0f ? d->focus_distance : v ? v->target_distance : 0.0f;
    b[1] = d->aperture;
    b[2] = d->max_radius;
    b[3] = 0.0f;
}

static void tl__dof_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->o->dof.enabled) return;
    d->reads = d->samples = TL__B(DEPTH) | TL__B(HDR);
    d->writes = TL__B(DOF);
    d->state = tl__pipeline_fullscreen;
}

static void tl__dof_permute(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)d;
    out->used[0] = 1;
    tl__perm_value(&out->slot[0], TL__V_DOF_SAMPLES, in->o->dof.samples);
}

static int tl__dof_wanted(const tl_renderer_options *o) { return o->dof.enabled; }

const tl__pass_def tl__pass_dof = {
    .id = TL_PASS_DOF,
    .name = "dof",
    .programs = {{"dof", "fullscreen.vert.glsl", "dof.frag.glsl"}},
    .targets = {&tl__target_dof},
    TL__OPTIONS(dof, tl__dof_rows),
    .resolve = tl__dof_resolve,
    .params_size = 4 * sizeof(float),
    .params = tl__dof_params,
    .declare = tl__dof_declare,
    .permute = tl__dof_permute,
    .execute = tl__draw_fullscreen,
    .wanted = tl__dof_wanted,
    .refuses = TL__REFUSES_MSAA | TL__REFUSES_STIPPLE,
    .refuses_why = {"depth of field reads a one-sample depth and HDR", "depth of field reads depth after the layers"},
};

static void tl__dof_apply_declare(const tl__plan_input *in, tl__pass_decl *d)
{
    if (!in->o->dof.enabled) return;
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
