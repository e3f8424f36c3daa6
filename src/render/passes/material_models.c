/* The material pass's programs per material model (docs/lighting.md, "Material models"): one
 * permutation for each model the scene's drawn materials use (TL_MODEL=<tl_material_model>; the
 * standard model's is the program of a scene without models, unchanged), and the draws that give
 * each model's objects its program. */
#include <stdio.h>

#include "pass.h"
#include "scene_gpu.h"

uint32_t tl__plan_models(const tl_scene_feature_set *f)
{
    uint32_t all = (1u << TL_MATERIAL_MODEL_COUNT_) - 1u;
    uint32_t m = f->material_models & all;
    return m ? m : 1u << TL_MATERIAL_MODEL_STANDARD;
}

int tl__plan_has_models(const tl_scene_feature_set *f)
{
    return (tl__plan_models(f) & ~(1u << TL_MATERIAL_MODEL_STANDARD)) != 0;
}

/* The clearcoat's lighting in thin-lpp (docs/lighting.md, "Material models"): the coat's own sums
 * (TL_COAT_SUMS) with a clearcoat drawn and lights, asked or by default, wherever the light buffer
 * has the frame's one sample per pixel: not at a light scale below 1 nor with MSAA, whose re-lit
 * pixels would need the coat's lights too (the stipple gathers and re-lights the coat's sum as the
 * others). Otherwise the approximation (*why says why where the sums were asked or are the
 * default), and a scene without a clearcoat plans exactly as before. */
int tl__plan_coat_sums(const tl__plan_input *in, const char **why)
{
    *why = NULL;
    if (in->o->clearcoat == TL_CLEARCOAT_APPROXIMATE || !in->mode->material_pass || !in->lights ||
        !(tl__plan_models(&in->f) & (1u << TL_MATERIAL_MODEL_CLEARCOAT)))
        return 0;
    if (in->light_shift) *why = "the reduced light buffer's re-lit pixels take one lobe";
    else if (in->msaa > 1u) *why = "MSAA's re-lit samples take one lobe";
    return *why == NULL;
}

void tl__material_model_slots(const tl__plan_input *in, const tl__perm *base, tl__pass_defines *out)
{
    uint32_t models = tl__plan_models(&in->f);
    for (uint32_t m = 0; m < TL_MATERIAL_MODEL_COUNT_; m++) {
        if (!(models & (1u << m))) continue;
        out->used[m] = 1;
        out->slot[m] = *base;
        if (m != TL_MATERIAL_MODEL_STANDARD) tl__perm_value(&out->slot[m], TL__V_MODEL, m);
    }
}

void tl__material_models_draw(const tl__pass_ctx *ctx)
{
    int others = 0;
    for (uint32_t m = 1; m < TL_MATERIAL_MODEL_COUNT_; m++) others |= ctx->programs[m] != 0;
    if (!others) { /* the standard model alone: the one draw of a scene without models */
        tl__draw_opaque(ctx);
        return;
    }
    for (uint32_t m = 0; m < TL_MATERIAL_MODEL_COUNT_; m++)
        if (ctx->programs[m]) tl__draw_opaque_model(ctx, m);
}
