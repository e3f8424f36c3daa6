/* The AA measurement's truth on the CPU (pure: no GL): the tone map of shaders/tonemap.frag.glsl
 * (exposure, clamp to [0, 65504], the ACES fit of Narkowicz 2015 clamped to [0, 1], sRGB encoding),
 * applied to every sample of a supersampled HDR frame, the samples of each pixel averaged in
 * tone-mapped linear space (as the renderer's MSAA resolve does) and only then encoded. Single
 * precision like the shader; the average in double. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "bench.h"

float bench_aa_tone(float c, float exposure)
{
    float x = isnan(c) ? 0.0f : c < 0.0f ? 0.0f : c > 65504.0f ? 65504.0f : c;
    x *= exposure;
    float y = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    return y < 0.0f ? 0.0f : y > 1.0f ? 1.0f : y;
}

uint8_t bench_aa_srgb8(float l)
{
    float s = l <= 0.0031308f ? l * 12.92f : 1.055f * powf(l, 1.0f / 2.4f) - 0.055f;
    s = s < 0.0f ? 0.0f : s > 1.0f ? 1.0f : s;
    return (uint8_t)lrintf(s * 255.0f);
}

void bench_aa_resolve(const float *hdr, uint32_t w, uint32_t h, uint32_t scale, float exposure, uint8_t *rgb)
{
    size_t fine_w = (size_t)w * scale;
    double inv = 1.0 / ((double)scale * scale);
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            double sum[3] = {0.0, 0.0, 0.0};
            for (uint32_t j = 0; j < scale; j++) {
                const float *row = hdr + 4 * (((size_t)y * scale + j) * fine_w + (size_t)x * scale);
                for (uint32_t i = 0; i < scale; i++)
                    for (int c = 0; c < 3; c++) sum[c] += bench_aa_tone(row[4 * i + c], exposure);
            }
            uint8_t *out = rgb + 3 * ((size_t)y * w + x);
            for (int c = 0; c < 3; c++) out[c] = bench_aa_srgb8((float)(sum[c] * inv));
        }
}

size_t bench_aa_reduce_mask(const uint8_t *fine, uint32_t w, uint32_t h, uint32_t scale, uint8_t *mask)
{
    size_t fine_w = (size_t)w * scale, count = 0;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            uint8_t any = 0;
            for (uint32_t j = 0; j < scale && !any; j++)
                for (uint32_t i = 0; i < scale && !any; i++)
                    any = fine[((size_t)y * scale + j) * fine_w + (size_t)x * scale + i] != 0;
            mask[(size_t)y * w + x] = any;
            count += any;
        }
    return count;
}
