/* The one gloss mapping: gloss in [0,1] <-> Blinn-Phong power 2^(1 + 11 g) <-> GGX alpha. */
#include <math.h>

#include "thinlight/codec.h"

static inline float tl__clamp01(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

float tl_gloss_to_specular_power(float gloss) { return exp2f(1.0f + 11.0f * tl__clamp01(gloss)); }

float tl_specular_power_to_gloss(float power)
{
    power = power > TL_GLOSS_MIN_POWER ? (power < TL_GLOSS_MAX_POWER ? power : TL_GLOSS_MAX_POWER)
                                       : TL_GLOSS_MIN_POWER;
    return tl__clamp01((log2f(power) - 1.0f) / 11.0f);
}

float tl_gloss_to_ggx_alpha(float gloss) { return sqrtf(2.0f / (tl_gloss_to_specular_power(gloss) + 2.0f)); }

float tl_ggx_alpha_to_gloss(float alpha)
{
    /* alpha = sqrt(2 / (p + 2))  =>  p = 2 / alpha^2 - 2; NaN and alpha <= 0 mean the smoothest */
    if (!(alpha > 0.0f)) return 1.0f;
    if (alpha >= 1.0f) return 0.0f;
    return tl_specular_power_to_gloss(2.0f / (alpha * alpha) - 2.0f);
}

uint32_t tl_gloss_encode(float gloss, uint32_t bits)
{
    bits = bits < 1u ? 1u : bits > 16u ? 16u : bits;
    return (uint32_t)(tl__clamp01(gloss) * (float)((1u << bits) - 1u) + 0.5f);
}

float tl_gloss_decode(uint32_t code, uint32_t bits)
{
    bits = bits < 1u ? 1u : bits > 16u ? 16u : bits;
    uint32_t max = (1u << bits) - 1u;
    return (float)(code > max ? max : code) / (float)max;
}
