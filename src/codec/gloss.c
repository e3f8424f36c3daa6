/* The gloss mappings: gloss in [0,1] <-> Blinn-Phong power 2^(1 + 11 g), and <-> GGX alpha (1 - g)^2. */
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

float tl_gloss_to_ggx_alpha(float gloss)
{
    float r = 1.0f - tl__clamp01(gloss);
    float a = r * r;
    return a > TL_GGX_MIN_ALPHA ? a : TL_GGX_MIN_ALPHA;
}

float tl_ggx_alpha_to_gloss(float alpha)
{
    /* alpha = (1 - g)^2  =>  g = 1 - sqrt(alpha); NaN clamps to 0, the smoothest */
    return 1.0f - sqrtf(tl__clamp01(alpha));
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
