/* The render modes as one table (pass.h): how each lays out its G-buffer and light pass. Adding a
 * mode means adding a row here and its name. */
#include <string.h>

#include "pass.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)
#define TL__FAT (TL__B(FAT_POSITION) | TL__B(FAT_NORMAL) | TL__B(FAT_ALBEDO) | TL__B(FAT_MATERIAL))

const tl__mode_def tl__modes[TL_MODE_COUNT_] = {
    [TL_MODE_DEFAULT] = {"thin-lpp", TL__B(RT0), TL__B(DEPTH) | TL__B(RT0), TL__B(DEPTH) | TL__B(RT0),
                         TL__B(LIGHT_DIFFUSE) | TL__B(LIGHT_SPECULAR) | TL__B(LIGHT_FRESNEL), TL__F_LIGHT_ACCUM, 1, 0},
    [TL_MODE_THIN_LPP] = {"thin-lpp", TL__B(RT0), TL__B(DEPTH) | TL__B(RT0), TL__B(DEPTH) | TL__B(RT0),
                          TL__B(LIGHT_DIFFUSE) | TL__B(LIGHT_SPECULAR) | TL__B(LIGHT_FRESNEL), TL__F_LIGHT_ACCUM, 1, 0},
    /* emissive and ambient go straight to HDR in the G-buffer pass; lights add to it */
    [TL_MODE_THIN_DEFERRED] = {"thin-deferred", TL__B(RT0) | TL__B(RT1) | TL__B(HDR),
                               TL__B(DEPTH) | TL__B(RT0) | TL__B(RT1), TL__B(DEPTH) | TL__B(RT0) | TL__B(RT1),
                               TL__B(HDR), TL__F_LIGHT_SHADE_THIN, 0, 0},
    [TL_MODE_FAT] = {"fat", TL__FAT | TL__B(HDR), TL__B(DEPTH) | TL__FAT, TL__FAT, TL__B(HDR), TL__F_LIGHT_SHADE_FAT, 0, 0},
    [TL_MODE_FORWARD] = {"forward", 0, 0, 0, 0, TL__F_NONE, 0, 1},
};

const char *tl_render_mode_name(tl_render_mode mode)
{
    return (unsigned)mode < TL_MODE_COUNT_ ? tl__modes[mode].name : "unknown";
}

tl_result tl_render_mode_from_name(const char *name, tl_render_mode *mode)
{
    if (!name || !mode) return TL_ERROR_INVALID_ARGUMENT;
    for (int m = TL_MODE_THIN_LPP; m < TL_MODE_COUNT_; m++)
        if (strcmp(name, tl__modes[m].name) == 0) {
            *mode = (tl_render_mode)m;
            return TL_OK;
        }
    return TL_ERROR_INVALID_ARGUMENT;
}

static const char *const tl__strategy_names[TL_LIGHT_STRATEGY_COUNT_] = {"auto", "volumes", "tiled"};

const char *tl_light_strategy_name(tl_light_strategy s)
{
    return (unsigned)s < TL_LIGHT_STRATEGY_COUNT_ ? tl__strategy_names[s] : "unknown";
}

tl_result tl_light_strategy_from_name(const char *name, tl_light_strategy *s)
{
    if (!name || !s) return TL_ERROR_INVALID_ARGUMENT;
    for (int i = 0; i < TL_LIGHT_STRATEGY_COUNT_; i++)
        if (strcmp(name, tl__strategy_names[i]) == 0) {
            *s = (tl_light_strategy)i;
            return TL_OK;
        }
    return TL_ERROR_INVALID_ARGUMENT;
}

static const char *const tl__lighting_names[TL_LIGHTING_COUNT_] = {"auto", "blinn-phong", "ggx"};
static const char *const tl__fresnel_names[TL_FRESNEL_COUNT_] = {"two-sums", "two-sums", "nv"};

const char *tl_lighting_model_name(tl_lighting_model m)
{
    return (unsigned)m < TL_LIGHTING_COUNT_ ? tl__lighting_names[m] : "unknown";
}

tl_result tl_lighting_model_from_name(const char *name, tl_lighting_model *m)
{
    if (!name || !m) return TL_ERROR_INVALID_ARGUMENT;
    for (int i = 0; i < TL_LIGHTING_COUNT_; i++)
        if (strcmp(name, tl__lighting_names[i]) == 0) {
            *m = (tl_lighting_model)i;
            return TL_OK;
        }
    return TL_ERROR_INVALID_ARGUMENT;
}

const char *tl_fresnel_layout_name(tl_fresnel_layout f)
{
    return (unsigned)f < TL_FRESNEL_COUNT_ ? tl__fresnel_names[f] : "unknown";
}

tl_result tl_fresnel_layout_from_name(const char *name, tl_fresnel_layout *f)
{
    if (!name || !f) return TL_ERROR_INVALID_ARGUMENT;
    for (int i = TL_FRESNEL_TWO_SUMS; i < TL_FRESNEL_COUNT_; i++)
        if (strcmp(name, tl__fresnel_names[i]) == 0) {
            *f = (tl_fresnel_layout)i;
            return TL_OK;
        }
    return TL_ERROR_INVALID_ARGUMENT;
}

static const char *const tl__transparency_names[TL_TRANSPARENCY_COUNT_] = {"auto", "forward", "stipple"};

const char *tl_transparency_name(tl_transparency t)
{
    return (unsigned)t < TL_TRANSPARENCY_COUNT_ ? tl__transparency_names[t] : "unknown";
}

tl_result tl_transparency_from_name(const char *name, tl_transparency *t)
{
    if (!name || !t) return TL_ERROR_INVALID_ARGUMENT;
    for (int i = 0; i < TL_TRANSPARENCY_COUNT_; i++)
        if (strcmp(name, tl__transparency_names[i]) == 0) {
            *t = (tl_transparency)i;
            return TL_OK;
        }
    return TL_ERROR_INVALID_ARGUMENT;
}

/* ---- what a mode plans, asked by several passes (pass.h) ------------------------------------- */

const tl__pipeline tl__pipeline_fullscreen = {.color_write = 1, .depth_write = 1};

void tl__permute_one_program(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)in;
    (void)d;
    out->used[0] = 1;
}

int tl__forward_plus(const tl__plan_input *in) { return in->lights && in->strategy == TL_LIGHT_STRATEGY_TILED; }

int tl__forward_prepass(const tl__plan_input *in) { return !in->o->forward_no_depth_prepass || tl__forward_plus(in); }

int tl__ssao_pass(const tl__plan_input *in)
{
    if (in->o->ssao.method == TL_SSAO_OFF) return 0;
    if (in->mode->forward) return tl__forward_prepass(in) ? 1 : 0;
    return in->mode->material_pass ? 1 : 2;
}

void tl__ssao_perm(const tl__plan_input *in, const tl__pass_decl *d, tl__perm *k)
{
    if (!(d->samples & TL__B(AO))) return;
    tl__perm_flag(k, TL__F_SSAO_AMBIENT);
    if (in->o->ssao.diffuse) tl__perm_flag(k, TL__F_SSAO_DIFFUSE);
}
