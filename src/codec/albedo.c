/* Albedo as 8-bit luma plus one checkerboarded 8-bit chroma channel a pixel, and the
 * reconstruction of the missing chroma from the 4 neighbours (which all store it). */
#include <math.h>

#include "thinlight/codec.h"

static inline float tl__clamp01(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }
static inline uint8_t tl__unorm8(float v) { return (uint8_t)(tl__clamp01(v) * 255.0f + 0.5f); }

static const char *const tl__space_names[TL_COLOR_SPACE_COUNT_] = {"ycbcr", "ycbcr", "ycocg"};
static const char *const tl__filter_names[TL_CHROMA_FILTER_COUNT_] = {"edge", "nearest", "bilinear", "edge"};

const char *tl_color_space_name(tl_color_space space)
{
    return (unsigned)space < TL_COLOR_SPACE_COUNT_ ? tl__space_names[space] : "unknown";
}

const char *tl_chroma_filter_name(tl_chroma_filter filter)
{
    return (unsigned)filter < TL_CHROMA_FILTER_COUNT_ ? tl__filter_names[filter] : "unknown";
}

void tl_rgb_to_luma_chroma(tl_color_space space, const float rgb[3], float ycc[3])
{
    float r = tl__clamp01(rgb[0]), g = tl__clamp01(rgb[1]), b = tl__clamp01(rgb[2]);
    if (space == TL_COLOR_SPACE_YCOCG) {
        ycc[0] = 0.25f * r + 0.5f * g + 0.25f * b;
        ycc[1] = 0.5f * (r - b) + 0.5f;
        ycc[2] = 0.5f * g - 0.25f * (r + b) + 0.5f;
    } else { /* BT.601 full range */
        float y = 0.299f * r + 0.587f * g + 0.114f * b;
        /* Clamped: rounding takes pure cyan's Cr to -6e-8 (found by tests/fuzz/fuzz_codec). */
        ycc[0] = tl__clamp01(y);
        ycc[1] = tl__clamp01((b - y) * (0.5f / 0.886f) + 0.5f);
        ycc[2] = tl__clamp01((r - y) * (0.5f / 0.701f) + 0.5f);
    }
}

void tl_luma_chroma_to_rgb(tl_color_space space, const float ycc[3], float rgb[3])
{
    float y = isnan(ycc[0]) ? 0.0f : ycc[0];
    float c1 = (isnan(ycc[1]) ? 0.5f : ycc[1]) - 0.5f, c2 = (isnan(ycc[2]) ? 0.5f : ycc[2]) - 0.5f;
    float r, g, b;
    if (space == TL_COLOR_SPACE_YCOCG) {
        float t = y - c2;
        g = y + c2;
        r = t + c1;
        b = t - c1;
    } else {
        r = y + 1.402f * c2;
        b = y + 1.772f * c1;
        g = (y - 0.299f * r - 0.114f * b) / 0.587f;
    }
    rgb[0] = tl__clamp01(r);
    rgb[1] = tl__clamp01(g);
    rgb[2] = tl__clamp01(b);
}

void tl_albedo_encode_pixel(tl_color_space space, const float rgb[3], uint32_t x, uint32_t y, uint8_t out[2])
{
    float ycc[3];
    tl_rgb_to_luma_chroma(space, rgb, ycc);
    out[0] = tl__unorm8(ycc[0]);
    out[1] = tl__unorm8(ycc[1 + tl_chroma_parity(x, y)]);
}

static int tl__image_size_ok(uint32_t w, uint32_t h)
{
    return w > 0 && h > 0 && (size_t)w <= SIZE_MAX / 3u / (size_t)h;
}

tl_result tl_albedo_encode_image(tl_color_space space, const float *rgb, uint32_t w, uint32_t h, uint8_t *yc)
{
    if (!rgb || !yc || !tl__image_size_ok(w, h)) return TL_ERROR_INVALID_ARGUMENT;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            tl_albedo_encode_pixel(space, rgb + 3 * i, x, y, yc + 2 * i);
        }
    return TL_OK;
}

/* Mirrors a coordinate back into [0, n): -1 -> 1 and n -> n - 2, which keeps the checkerboard
 * parity. Returns 0 when the mirrored coordinate is still outside (n == 1). */
static int tl__mirror(int64_t c, uint32_t n, uint32_t *out)
{
    if (c < 0) c = -c;
    if (c >= (int64_t)n) c = 2 * ((int64_t)n - 1) - c;
    if (c < 0 || c >= (int64_t)n) return 0;
    *out = (uint32_t)c;
    return 1;
}

float tl_albedo_missing_chroma(tl_chroma_filter filter, const uint8_t *yc, uint32_t w, uint32_t h,
                               uint32_t x, uint32_t y)
{
    static const int dx[4] = {-1, 1, 0, 0}, dy[4] = {0, 0, -1, 1};
    if (!yc || x >= w || y >= h) return 0.5f;
    int luma = yc[2 * ((size_t)y * w + x)];
    int nl[4], nc[4], count = 0;
    for (int i = 0; i < 4; i++) {
        uint32_t mx, my;
        if (!tl__mirror((int64_t)x + dx[i], w, &mx) || !tl__mirror((int64_t)y + dy[i], h, &my)) continue;
        const uint8_t *p = yc + 2 * ((size_t)my * w + mx);
        nl[count] = p[0];
        nc[count] = p[1];
        count++;
    }
    if (count == 0) return 0.5f;
    if (filter == TL_CHROMA_FILTER_NEAREST) return (float)nc[0] / 255.0f;
    if (filter == TL_CHROMA_FILTER_BILINEAR) {
        int sum = 0;
        for (int i = 0; i < count; i++) sum += nc[i];
        return (float)sum / (255.0f * (float)count);
    }
    /* Edge-directed: a neighbour's weight falls linearly with its luma difference and reaches 0 at
     * TL_CHROMA_EDGE_THRESHOLD, so chroma is not pulled across an edge. When no neighbour is
     * similar (a one-pixel feature), the neighbour closest in luma is used. */
    const float threshold = TL_CHROMA_EDGE_THRESHOLD * 255.0f;
    float wsum = 0.0f, csum = 0.0f;
    int closest = 0;
    for (int i = 0; i < count; i++) {
        int d = nl[i] > luma ? nl[i] - luma : luma - nl[i];
        int dc = nl[closest] > luma ? nl[closest] - luma : luma - nl[closest];
        if (d < dc) closest = i;
        float wgt = 1.0f - (float)d / threshold;
        if (wgt > 0.0f) {
            wsum += wgt;
            csum += wgt * (float)nc[i];
        }
    }
    if (wsum <= 0.0f) return (float)nc[closest] / 255.0f;
    return csum / (wsum * 255.0f);
}

tl_result tl_albedo_reconstruct(tl_color_space space, tl_chroma_filter filter, const uint8_t *yc, uint32_t w,
                                uint32_t h, float *rgb)
{
    if (!yc || !rgb || !tl__image_size_ok(w, h) || (unsigned)filter >= TL_CHROMA_FILTER_COUNT_ ||
        (unsigned)space >= TL_COLOR_SPACE_COUNT_)
        return TL_ERROR_INVALID_ARGUMENT;
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            float own = (float)yc[2 * i + 1] / 255.0f;
            float missing = tl_albedo_missing_chroma(filter, yc, w, h, x, y);
            float ycc[3];
            ycc[0] = (float)yc[2 * i] / 255.0f;
            ycc[1] = tl_chroma_parity(x, y) == 0 ? own : missing;
            ycc[2] = tl_chroma_parity(x, y) == 0 ? missing : own;
            tl_luma_chroma_to_rgb(space, ycc, rgb + 3 * i);
        }
    return TL_OK;
}

float tl_srgb_to_linear(float c)
{
    c = tl__clamp01(c);
    return c <= 0.04045f ? c / 12.92f : powf((c + 0.055f) / 1.055f, 2.4f);
}

float tl_linear_to_srgb(float c)
{
    c = tl__clamp01(c);
    return c <= 0.0031308f ? c * 12.92f : 1.055f * powf(c, 1.0f / 2.4f) - 0.055f;
}
