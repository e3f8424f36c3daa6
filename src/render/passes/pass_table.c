/* The pass table: every built-in pass in execution order (docs/frame.md). A new pass is one
 * entry here plus its definition (declare, permute, execute) in a pass_*.c file; the planner,
 * the compile step, the frame and the statistics derive everything else from it. */
#include <string.h>

#include "pass.h"

extern const tl__pass_def tl__pass_depth_prepass, tl__pass_gbuffer, tl__pass_light_reduce, tl__pass_light_cull, tl__pass_lights,
    tl__pass_lights_tiled, tl__pass_material, tl__pass_forward, tl__pass_transparent, tl__pass_tonemap, tl__pass_fxaa;
extern const tl__pass_def tl__pass_ssao, tl__pass_ssao_blur, tl__pass_ssao_apply, tl__pass_fog, tl__pass_dof,
    tl__pass_dof_apply, tl__pass_ssr, tl__pass_ssr_apply, tl__pass_bloom, tl__pass_vignette;
extern const tl__pass_def tl__pass_stipple_depth, tl__pass_stipple, tl__pass_stipple_resolve;
extern const tl__pass_def tl__pass_points_lines;
extern const tl__pass_def tl__pass_sky;
extern const tl__pass_def tl__pass_msaa_classify, tl__pass_lights_samples;
extern const tl__pass_def tl__pass_shadow_debug;
extern const tl__pass_def tl__pass_shadows;
extern const tl__pass_def tl__pass_light_upsample;
extern const tl__pass_def tl__pass_vis_classify, tl__pass_vis_resolve;

const tl__pass_def *const tl__pass_table[TL_PASS_COUNT] = {
    &tl__pass_shadows,       &tl__pass_depth_prepass, &tl__pass_gbuffer,   &tl__pass_ssao,      &tl__pass_ssao_blur,   &tl__pass_ssao_apply,
    &tl__pass_stipple_depth, &tl__pass_stipple,
    &tl__pass_msaa_classify, &tl__pass_light_reduce,  &tl__pass_light_cull,    &tl__pass_lights,    &tl__pass_lights_tiled,
    &tl__pass_lights_samples, &tl__pass_light_upsample, &tl__pass_vis_classify, &tl__pass_vis_resolve, &tl__pass_material, &tl__pass_forward, &tl__pass_shadow_debug, &tl__pass_sky,
    &tl__pass_points_lines,  &tl__pass_transparent,   &tl__pass_stipple_resolve, &tl__pass_ssr,       &tl__pass_ssr_apply, &tl__pass_fog,         &tl__pass_dof,
    &tl__pass_dof_apply,     &tl__pass_bloom,     &tl__pass_vignette,  &tl__pass_tonemap,   &tl__pass_fxaa,
};

/* The table's order is the frame's; a pass's public id only names it (statistics, plans). */
const char *tl_pass_name(tl_pass pass)
{
    for (int i = 0; i < TL_PASS_COUNT; i++)
        if (tl__pass_table[i]->id == pass) return tl__pass_table[i]->name;
    return "unknown";
}

tl_result tl_pass_from_name(const char *name, tl_pass *pass)
{
    int i = tl__pass_table_find(name);
    if (i < 0 || !pass) return TL_ERROR_INVALID_ARGUMENT;
    *pass = tl__pass_table[i]->id;
    return TL_OK;
}

const char *tl__passes_refuse(const tl_renderer_options *o, unsigned what)
{
    for (int i = 0; i < TL_PASS_COUNT; i++) {
        const tl__pass_def *d = tl__pass_table[i];
        if ((d->refuses & what) && d->wanted && d->wanted(o)) return d->refuses_why[what == TL__REFUSES_STIPPLE];
    }
    return NULL;
}

int tl__pass_table_find(const char *name)
{
    for (int i = 0; name && i < TL_PASS_COUNT; i++)
        if (strcmp(tl__pass_table[i]->name, name) == 0) return i;
    return -1;
}
