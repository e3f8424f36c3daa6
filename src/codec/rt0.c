/* RT0 packing: octahedral normal + gloss in RGBA8 (2x12 + 8) or RGB10A2 (2x10 + 10 + 2 flags). */
#include "thinlight/codec.h"

void tl_rt0_encode_rgba8(const float n[3], float gloss, uint8_t texel[4])
{
    uint32_t code = tl_oct_encode_precise(n, 12);
    uint32_t u = code & 0xFFFu, v = code >> 12;
    texel[0] = (uint8_t)(u >> 4);
    texel[1] = (uint8_t)(v >> 4);
    texel[2] = (uint8_t)(((u & 0xFu) << 4) | (v & 0xFu));
    texel[3] = (uint8_t)tl_gloss_encode(gloss, 8);
}

void tl_rt0_decode_rgba8(const uint8_t texel[4], float n[3], float *gloss)
{
    uint32_t u = ((uint32_t)texel[0] << 4) | (texel[2] >> 4);
    uint32_t v = ((uint32_t)texel[1] << 4) | (texel[2] & 0xFu);
    tl_oct_decode(u | (v << 12), 12, n);
    if (gloss) *gloss = tl_gloss_decode(texel[3], 8);
}

void tl_rt0_encode_rgba8_n(const float *n, const float *gloss, uint8_t *texels, size_t count)
{
    if (!n || !texels) return;
    for (size_t i = 0; i < count; i++) tl_rt0_encode_rgba8(n + 3 * i, gloss ? gloss[i] : 0.0f, texels + 4 * i);
}

void tl_rt0_decode_rgba8_n(const uint8_t *texels, float *n, float *gloss, size_t count)
{
    if (!n || !texels) return;
    for (size_t i = 0; i < count; i++) tl_rt0_decode_rgba8(texels + 4 * i, n + 3 * i, gloss ? gloss + i : NULL);
}

uint32_t tl_rt0_encode_rgb10a2(const float n[3], float gloss, uint32_t flags)
{
    uint32_t code = tl_oct_encode_precise(n, 10); /* u | v << 10 */
    return code | (tl_gloss_encode(gloss, 10) << 20) | ((flags & 3u) << 30);
}

void tl_rt0_decode_rgb10a2(uint32_t texel, float n[3], float *gloss, uint32_t *flags)
{
    tl_oct_decode(texel & 0xFFFFFu, 10, n);
    if (gloss) *gloss = tl_gloss_decode((texel >> 20) & 0x3FFu, 10);
    if (flags) *flags = texel >> 30;
}
