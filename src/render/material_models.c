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

const char *tl__models_define(const tl_scene_feature_set *f)
{
    return (tl__plan_models(f) & ~(1u << TL_MATERIAL_MODEL_STANDARD)) ? " TL_MATERIAL_MODELS" : "";
}

/* TL_CLEARCOAT_SUMS (docs/lighting.md, "Material models"): the coat's own sums, planned only in
 * thin-lpp with a clearcoat drawn and lights, with the light buffer at the frame's one sample per
 * pixel (no light scale, MSAA or stipple, whose re-lit pixels would need the coat's lights too);
 * otherwise the approximation, and a scene without a clearcoat plans exactly as before. */
int tl__plan_coat_sums(const tl__plan_input *in)
{
    return in->o->clearcoat == TL_CLEARCOAT_SUMS && in->mode->material_pass && in->lights &&
           (tl__plan_models(&in->f) & (1u << TL_MATERIAL_MODEL_CLEARCOAT)) && !in->light_shift && in->msaa <= 1u &&
           !in->stipple;
}

void tl__material_model_slots(const tl__plan_input *in, const char *defines, tl__pass_defines *out)
{
    uint32_t models = tl__plan_models(&in->f);
    for (uint32_t m = 0; m < TL_MATERIAL_MODEL_COUNT_; m++) {
        if (!(models & (1u << m))) continue;
        out->used[m] = 1;
        int n = m == TL_MATERIAL_MODEL_STANDARD
                    ? snprintf(out->slot[m], sizeof out->slot[m], "%s", defines)
                    : snprintf(out->slot[m], sizeof out->slot[m], "TL_MODEL=%u %s", (unsigned)m, defines);
        if (n < 0 || (size_t)n >= sizeof out->slot[m]) out->overflow = 1;
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
