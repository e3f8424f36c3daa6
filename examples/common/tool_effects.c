/* The effect options of the tools (tool_effects.h). */
#include "tool_effects.h"

#include <float.h>
#include <stddef.h>
#include <string.h>

const char tl_tool_effects_help[] =
    "  --ssao                screen-space ambient occlusion (disc estimator); --ssao-method disc|hemisphere,\n"
    "                        --ssao-samples N (16), --ssao-radius R (1), --ssao-bias K_B (0),\n"
    "                        --ssao-falloff K_D (2 R), --ssao-exponent X (3), --ssao-blur PX (2),\n"
    "                        --ssao-diffuse (AO scales the diffuse light too: thin-lpp, forward)\n"
    "  --fog                 distance fog; --fog-mode distance|height, --fog-density D (0.05),\n"
    "                        --fog-color R,G,B (0,0,0), --fog-height Y (0), --fog-falloff K (0.5),\n"
    "                        --fog-noise 0..1 (0)\n"
    "  --dof                 depth of field; --dof-focus DIST (camera target), --dof-aperture A (0.01 of\n"
    "                        the height), --dof-max M (2 A), --dof-samples N (48)\n"
    "  --bloom               bloom; --bloom-threshold T (1; 0: everything), --bloom-knee K (0.5 of T),\n"
    "                        --bloom-intensity I (0.5), --bloom-scatter S (0.7), --bloom-levels N (6, 1..8)\n"
    "  --ssr                 screen-space reflections (thin-lpp, thin-deferred, fat); --ssr-steps N (48),\n"
    "                        --ssr-distance D (16), --ssr-thickness T (0.4), --ssr-min-gloss G (0.4),\n"
    "                        --ssr-intensity I (1)\n";

/* Each valued option's id is the offset of its field in tl_renderer_desc (options.ssao.radius, ...). */
#define FX(field) ((int)offsetof(tl_renderer_desc, options.field))
/* Zero means "the default" in the descriptor: an explicit 0 is written as -1 (exactly 0). */
#define FX_ZERO_IS_NEGATIVE TL_OPT_USER
#define FX_POSITIVE .min = 0.0, .max = FLT_MAX, .flags = TL_OPT_MIN_OPEN
#define FX_NONNEGATIVE .min = 0.0, .max = FLT_MAX

_Static_assert(sizeof(tl_ssao_method) == sizeof(int) && sizeof(tl_fog_mode) == sizeof(int), "enum fields are ints");

static const char *const fx_ssao_methods[] = {"disc", "hemisphere", NULL};
static const int fx_ssao_values[] = {TL_SSAO_DISC, TL_SSAO_HEMISPHERE};
static const char *const fx_fog_modes[] = {"distance", "height", NULL};
static const int fx_fog_values[] = {TL_FOG_DISTANCE, TL_FOG_HEIGHT};

static const tl_opt fx_opts[] = {
    {"--ssao", TL_OPT_FLAG, .id = 0},
    {"--ssao-diffuse", TL_OPT_FLAG, .id = 0},
    {"--fog", TL_OPT_FLAG, .id = 0},
    {"--dof", TL_OPT_FLAG, .id = 0},
    {"--bloom", TL_OPT_FLAG, .id = 0},
    {"--ssr", TL_OPT_FLAG, .id = 0},
    {"--ssao-method", TL_OPT_TEXT, .id = FX(ssao.method), .choices = fx_ssao_methods, .values = fx_ssao_values},
    {"--ssao-samples", TL_OPT_UINT, .id = FX(ssao.samples), .lo = 1, .hi = 64},
    {"--ssao-radius", TL_OPT_REAL, .id = FX(ssao.radius), FX_POSITIVE},
    {"--ssao-bias", TL_OPT_REAL, .id = FX(ssao.bias), FX_NONNEGATIVE},
    {"--ssao-falloff", TL_OPT_REAL, .id = FX(ssao.falloff), FX_POSITIVE},
    {"--ssao-exponent", TL_OPT_REAL, .id = FX(ssao.exponent), FX_POSITIVE},
    {"--ssao-blur", TL_OPT_UINT, .id = FX(ssao.blur_radius), .lo = 1, .hi = 8},
    {"--fog-mode", TL_OPT_TEXT, .id = FX(fog.mode), .choices = fx_fog_modes, .values = fx_fog_values},
    {"--fog-density", TL_OPT_REAL, .id = FX(fog.density), FX_POSITIVE},
    {"--fog-height", TL_OPT_REAL, .id = FX(fog.height), .min = -FLT_MAX, .max = FLT_MAX},
    {"--fog-falloff", TL_OPT_REAL, .id = FX(fog.height_falloff), FX_POSITIVE},
    {"--fog-noise", TL_OPT_REAL, .id = FX(fog.noise), .min = 0.0, .max = 1.0},
    {"--fog-color", TL_OPT_REALS, .id = FX(fog.color), FX_NONNEGATIVE, .items = 3},
    {"--dof-focus", TL_OPT_REAL, .id = FX(dof.focus_distance), FX_POSITIVE},
    {"--dof-aperture", TL_OPT_REAL, .id = FX(dof.aperture), .min = 0.0, .max = 1.0, .flags = TL_OPT_MIN_OPEN},
    {"--dof-max", TL_OPT_REAL, .id = FX(dof.max_radius), .min = 0.0, .max = 1.0, .flags = TL_OPT_MIN_OPEN},
    {"--dof-samples", TL_OPT_UINT, .id = FX(dof.samples), .lo = 8, .hi = 128},
    {"--bloom-threshold", TL_OPT_REAL, .id = FX(bloom.threshold), .min = 0.0, .max = FLT_MAX,
     .flags = FX_ZERO_IS_NEGATIVE},
    {"--bloom-knee", TL_OPT_REAL, .id = FX(bloom.knee), .min = 0.0, .max = 1.0, .flags = FX_ZERO_IS_NEGATIVE},
    {"--bloom-intensity", TL_OPT_REAL, .id = FX(bloom.intensity), FX_POSITIVE},
    {"--bloom-scatter", TL_OPT_REAL, .id = FX(bloom.scatter), .min = 0.0, .max = 1.0, .flags = TL_OPT_MIN_OPEN},
    {"--bloom-levels", TL_OPT_UINT, .id = FX(bloom.levels), .lo = 1, .hi = 8},
    {"--ssr-steps", TL_OPT_UINT, .id = FX(ssr.steps), .lo = 4, .hi = 256},
    {"--ssr-distance", TL_OPT_REAL, .id = FX(ssr.max_distance), FX_POSITIVE},
    {"--ssr-thickness", TL_OPT_REAL, .id = FX(ssr.thickness), FX_POSITIVE},
    {"--ssr-min-gloss", TL_OPT_REAL, .id = FX(ssr.min_gloss), .min = 0.0, .max = 1.0,
     .flags = TL_OPT_MAX_OPEN | FX_ZERO_IS_NEGATIVE},
    {"--ssr-intensity", TL_OPT_REAL, .id = FX(ssr.intensity), FX_POSITIVE},
};

const tl_opt_table tl_tool_effect_options = TL_OPT_TABLE(fx_opts);

int tl_tool_effect_flag(tl_renderer_desc *d, const char *flag)
{
    if (!strcmp(flag, "--ssao")) {
        if (d->options.ssao.method == TL_SSAO_OFF) d->options.ssao.method = TL_SSAO_DISC;
    } else if (!strcmp(flag, "--ssao-diffuse")) d->options.ssao.diffuse = 1;
    else if (!strcmp(flag, "--fog")) {
        if (d->options.fog.mode == TL_FOG_OFF) d->options.fog.mode = TL_FOG_DISTANCE;
    } else if (!strcmp(flag, "--dof")) d->options.dof.enabled = 1;
    else if (!strcmp(flag, "--bloom")) d->options.bloom.enabled = 1;
    else if (!strcmp(flag, "--ssr")) d->options.ssr.enabled = 1;
    else return 0;
    return 1;
}

int tl_tool_effect_apply(tl_renderer_desc *d, const tl_opt *o, const tl_opt_value *v)
{
    if (!tl_opt_in(o, tl_tool_effect_options)) return 0;
    if (o->kind == TL_OPT_FLAG) return tl_tool_effect_flag(d, o->name);
    unsigned char *field = (unsigned char *)d + o->id;
    if (o->kind == TL_OPT_TEXT) {
        int e = (int)v->u[0];
        memcpy(field, &e, sizeof e);
    } else if (o->kind == TL_OPT_UINT) {
        uint32_t u = (uint32_t)v->u[0];
        memcpy(field, &u, sizeof u);
    } else {
        for (size_t i = 0; i < v->count; i++) {
            float f = (float)v->f[i];
            if (f == 0.0f && (o->flags & FX_ZERO_IS_NEGATIVE)) f = -1.0f;
            memcpy(field + i * sizeof f, &f, sizeof f);
        }
    }
    return 1;
}
