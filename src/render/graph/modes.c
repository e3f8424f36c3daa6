/* The render modes as one table (pass.h): how each lays out its G-buffer and light pass. Adding a
 * mode means adding a row here and its name (option_check.h, TL__OPTION_ENUMS). */
#include <string.h>

#include "pass.h"

#define TL__B(t) TL_TARGET_BIT(TL_TARGET_##t)
#define TL__FAT (TL__B(FAT_POSITION) | TL__B(FAT_NORMAL) | TL__B(FAT_ALBEDO) | TL__B(FAT_MATERIAL))

const tl__mode_def tl__modes[TL_MODE_COUNT_] = {
    [TL_MODE_DEFAULT] = {TL__B(RT0), TL__B(DEPTH) | TL__B(RT0), TL__B(DEPTH) | TL__B(RT0),
                         TL__B(LIGHT_DIFFUSE) | TL__B(LIGHT_SPECULAR) | TL__B(LIGHT_FRESNEL), TL__F_LIGHT_ACCUM, 1, 0},
    [TL_MODE_THIN_LPP] = {TL__B(RT0), TL__B(DEPTH) | TL__B(RT0), TL__B(DEPTH) | TL__B(RT0),
                          TL__B(LIGHT_DIFFUSE) | TL__B(LIGHT_SPECULAR) | TL__B(LIGHT_FRESNEL), TL__F_LIGHT_ACCUM, 1, 0},
    /* emissive and ambient go straight to HDR in the G-buffer pass; lights add to it */
    [TL_MODE_THIN_DEFERRED] = {TL__B(RT0) | TL__B(RT1) | TL__B(HDR),
                               TL__B(DEPTH) | TL__B(RT0) | TL__B(RT1), TL__B(DEPTH) | TL__B(RT0) | TL__B(RT1),
                               TL__B(HDR), TL__F_LIGHT_SHADE_THIN, 0, 0},
    [TL_MODE_FAT] = {TL__FAT | TL__B(HDR), TL__B(DEPTH) | TL__FAT, TL__FAT, TL__B(HDR), TL__F_LIGHT_SHADE_FAT, 0, 0},
    [TL_MODE_FORWARD] = {0, 0, 0, 0, TL__F_NONE, 0, 1},
    /* the id, and RT0 only for an effect that reads normals (SSAO, SSR, shadow-debug): optional */
    [TL_MODE_VISIBILITY] = {TL__B(VIS_ID) | TL__B(RT0), 0, 0, 0, TL__F_NONE, 0, 0, 1},
};

/* ---- what a mode plans, asked by several passes (pass.h) ------------------------------------- */

const tl__pipeline tl__pipeline_fullscreen = {.color_write = 1, .depth_write = 1};

void tl__permute_one_program(const tl__plan_input *in, const tl__pass_decl *d, tl__pass_defines *out)
{
    (void)in;
    (void)d;
    out->used[0] = 1;
}

int tl__forward_plus(const tl__plan_input *in) { return in->lights && in->strategy == TL_LIGHT_STRATEGY_TILED; }

int tl__forward_prepass(const tl__plan_input *in) { return in->o->forward_depth_prepass != TL_SWITCH_OFF || tl__forward_plus(in); }

int tl__ssao_pass(const tl__plan_input *in)
{
    if (!in->o->ssao.enabled) return 0;
    if (in->mode->forward) return tl__forward_prepass(in) ? 1 : 0;
    return in->mode->material_pass || in->mode->visibility ? 1 : 2; /* visibility: vis-resolve samples it */
}

void tl__ssao_perm(const tl__plan_input *in, const tl__pass_decl *d, tl__perm *k)
{
    if (!(d->samples & TL__B(AO))) return;
    tl__perm_flag(k, TL__F_SSAO_AMBIENT);
    if (in->o->ssao.diffuse) tl__perm_flag(k, TL__F_SSAO_DIFFUSE);
}
