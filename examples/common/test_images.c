/* Generated test images (see test_images.h). */
#include "test_images.h"

#include <math.h>

static const char *const tl__image_names[TL_TEST_IMAGE_COUNT] = {
    "gradient", "hard-edges", "single-pixel", "noisy", "scene",
};

const char *tl_test_image_name(tl_test_image image)
{
    return (unsigned)image < TL_TEST_IMAGE_COUNT ? tl__image_names[image] : "unknown";
}

int tl_test_image_has_edges(tl_test_image image) { return image != TL_TEST_IMAGE_GRADIENT; }

static uint32_t tl__hash(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7FEB352Du;
    x ^= x >> 15;
    x *= 0x846CA68Bu;
    x ^= x >> 16;
    return x;
}

static float tl__hash01(uint32_t a, uint32_t b, uint32_t c)
{
    return (float)(tl__hash(a * 73856093u ^ tl__hash(b * 19349663u ^ tl__hash(c * 83492791u))) >> 8) /
           16777216.0f;
}

static float tl__clamp01(float v) { return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v; }

/* Smoothly interpolated lattice noise, one octave. */
static float tl__value_noise(float x, float y, uint32_t seed)
{
    float fx = floorf(x), fy = floorf(y);
    int32_t ix = (int32_t)fx, iy = (int32_t)fy;
    float tx = x - fx, ty = y - fy;
    tx = tx * tx * (3.0f - 2.0f * tx);
    ty = ty * ty * (3.0f - 2.0f * ty);
    float a = tl__hash01((uint32_t)ix, (uint32_t)iy, seed), b = tl__hash01((uint32_t)ix + 1u, (uint32_t)iy, seed);
    float c = tl__hash01((uint32_t)ix, (uint32_t)iy + 1u, seed), d = tl__hash01((uint32_t)ix + 1u, (uint32_t)iy + 1u, seed);
    return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

static void tl__hsv(float h, float s, float v, float out[3])
{
    h = (h - floorf(h)) * 6.0f;
    float c = v * s, x = c * (1.0f - fabsf(fmodf(h, 2.0f) - 1.0f)), m = v - c;
    float r = 0, g = 0, b = 0;
    if (h < 1) { r = c; g = x; } else if (h < 2) { r = x; g = c; } else if (h < 3) { g = c; b = x; }
    else if (h < 4) { g = x; b = c; } else if (h < 5) { r = x; b = c; } else { r = c; b = x; }
    out[0] = r + m;
    out[1] = g + m;
    out[2] = b + m;
}

void tl_test_image_generate(tl_test_image image, uint32_t w, uint32_t h, float *rgb)
{
    for (uint32_t y = 0; y < h; y++)
        for (uint32_t x = 0; x < w; x++) {
            float u = (float)x / (float)(w > 1 ? w - 1 : 1), v = (float)y / (float)(h > 1 ? h - 1 : 1);
            float *p = rgb + 3 * ((size_t)y * w + x);
            switch (image) {
            case TL_TEST_IMAGE_GRADIENT:
                p[0] = u;
                p[1] = v;
                p[2] = 0.5f + 0.4f * sinf(6.2831853f * (u + v) * 0.75f);
                break;
            case TL_TEST_IMAGE_HARD_EDGES: {
                tl__hsv(0.6f, 0.2f, 0.35f, p);
                for (uint32_t k = 0; k < 24; k++) { /* later shapes cover earlier ones */
                    float cx = tl__hash01(k, 1, 7), cy = tl__hash01(k, 2, 7), r = 0.05f + 0.2f * tl__hash01(k, 3, 7);
                    int inside = (k & 1) ? (fabsf(u - cx) < r && fabsf(v - cy) < r * 0.6f)
                                         : ((u - cx) * (u - cx) + (v - cy) * (v - cy) < r * r);
                    if (inside) tl__hsv(tl__hash01(k, 4, 7), 0.6f + 0.4f * tl__hash01(k, 5, 7), 0.3f + 0.7f * tl__hash01(k, 6, 7), p);
                }
                break;
            }
            case TL_TEST_IMAGE_SINGLE_PIXEL: {
                p[0] = p[1] = p[2] = 0.08f;
                if (tl__hash01(x, y, 11) < 0.02f) tl__hsv(tl__hash01(x, y, 12), 1.0f, 1.0f, p);
                if (x % 37 == 5) tl__hsv(0.33f, 0.9f, 0.9f, p);  /* vertical 1-pixel lines */
                if (y % 41 == 9) tl__hsv(0.0f, 0.9f, 0.9f, p);   /* horizontal ones */
                if (x == y) tl__hsv(0.66f, 1.0f, 1.0f, p);       /* a diagonal */
                break;
            }
            case TL_TEST_IMAGE_NOISY: {
                float n = 0.0f, amp = 0.5f, f = 4.0f;
                for (uint32_t o = 0; o < 5; o++, amp *= 0.5f, f *= 2.0f) n += amp * tl__value_noise(u * f, v * f, o);
                float grain = 0.06f * (tl__hash01(x, y, 21) - 0.5f);
                tl__hsv(0.08f + 0.1f * n, 0.5f + 0.3f * tl__value_noise(u * 9.0f, v * 9.0f, 30), 0.25f + 0.7f * n, p);
                p[0] = tl__clamp01(p[0] + grain);
                p[1] = tl__clamp01(p[1] + 0.5f * grain);
                p[2] = tl__clamp01(p[2] - grain);
                break;
            }
            case TL_TEST_IMAGE_SCENE:
            default: {
                /* floor: a checker texture fading with distance; sky: gradient; three lit spheres */
                if (v > 0.55f) {
                    float d = 1.0f / (v - 0.5f), fu = (u - 0.5f) * d * 2.0f, fv = d * 2.0f;
                    int chk = ((int)floorf(fu) + (int)floorf(fv)) & 1;
                    float fade = tl__clamp01((v - 0.55f) * 4.0f);
                    tl__hsv(chk ? 0.1f : 0.55f, 0.5f * fade, 0.3f + 0.5f * fade * (chk ? 1.0f : 0.6f), p);
                } else {
                    p[0] = 0.45f + 0.3f * v;
                    p[1] = 0.6f + 0.2f * v;
                    p[2] = 0.9f;
                }
                static const float s[3][4] = {{0.25f, 0.45f, 0.16f, 0.0f}, {0.55f, 0.5f, 0.2f, 0.35f}, {0.8f, 0.52f, 0.12f, 0.75f}};
                for (int k = 0; k < 3; k++) {
                    float dx = (u - s[k][0]) / s[k][2], dy = (v - s[k][1]) / s[k][2], r2 = dx * dx + dy * dy;
                    if (r2 < 1.0f) {
                        float nz = sqrtf(1.0f - r2), lit = tl__clamp01(0.6f * nz - 0.5f * dx - 0.4f * dy);
                        float spec = powf(tl__clamp01(nz * 0.8f - 0.3f * dx - 0.3f * dy + 0.1f), 40.0f);
                        tl__hsv(s[k][3], 0.8f, 0.15f + 0.8f * lit, p);
                        p[0] = tl__clamp01(p[0] + spec);
                        p[1] = tl__clamp01(p[1] + spec);
                        p[2] = tl__clamp01(p[2] + spec);
                    }
                }
                break;
            }
            }
        }
}
