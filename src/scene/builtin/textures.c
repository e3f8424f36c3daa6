/* Procedural albedo textures for the built-in scene: flagstones, ashlar masonry, veined marble and
 * a chequered tile pavement. All tile seamlessly (the noise is periodic over the texture), hold
 * sRGB-encoded colour with alpha 255, and depend on nothing but their index. */
#include <math.h>

#include "scene_internal.h"

#define TL__TAU 6.28318530717958647692

typedef struct tl__texture_info {
    const char *name;
    uint32_t size;
    float metres;
} tl__texture_info;

static const tl__texture_info tl__textures[TL__TEX_COUNT] = {
    [TL__TEX_FLAGSTONE] = {"flagstone", 512, 4.0f},
    [TL__TEX_ASHLAR] = {"ashlar", 512, 2.0f},
    [TL__TEX_MARBLE] = {"marble", 512, 2.0f},
    [TL__TEX_TILES] = {"tiles", 256, 2.0f},
};

uint32_t tl__texture_size(int which) { return tl__textures[which].size; }
float tl__texture_metres(int which) { return tl__textures[which].metres; }
const char *tl__texture_name(int which) { return tl__textures[which].name; }

/* ---- periodic value noise --------------------------------------------------------------------- */

static uint32_t tl__hash3(uint32_t x, uint32_t y, uint32_t seed)
{
    uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return h;
}

static float tl__hash_unit(uint32_t x, uint32_t y, uint32_t seed)
{
    return (float)(tl__hash3(x, y, seed) >> 8) * (1.0f / 16777216.0f);
}

/* Value noise in [0, 1) at (x, y) lattice units, periodic with `period` cells in both directions. */
static float tl__vnoise(float x, float y, uint32_t period, uint32_t seed)
{
    float fx = floorf(x), fy = floorf(y);
    float tx = x - fx, ty = y - fy;
    int64_t ix = (int64_t)fx, iy = (int64_t)fy;
    uint32_t x0 = (uint32_t)(((ix % period) + period) % period), y0 = (uint32_t)(((iy % period) + period) % period);
    uint32_t x1 = (x0 + 1) % period, y1 = (y0 + 1) % period;
    tx = tx * tx * (3.0f - 2.0f * tx);
    ty = ty * ty * (3.0f - 2.0f * ty);
    float a = tl__hash_unit(x0, y0, seed), b = tl__hash_unit(x1, y0, seed);
    float c = tl__hash_unit(x0, y1, seed), d = tl__hash_unit(x1, y1, seed);
    float top = a + (b - a) * tx, bottom = c + (d - c) * tx;
    return top + (bottom - top) * ty;
}

/* Fractal sum over u, v in [0, 1) (one texture repeat), roughly in [0, 1). */
static float tl__fbm(float u, float v, uint32_t period, int octaves, uint32_t seed)
{
    float sum = 0.0f, amp = 0.5f, norm = 0.0f;
    for (int o = 0; o < octaves; o++) {
        sum += amp * tl__vnoise(u * (float)period, v * (float)period, period, seed + (uint32_t)o * 101u);
        norm += amp;
        amp *= 0.5f;
        period *= 2;
    }
    return sum / norm;
}

static uint8_t tl__to_u8(float v)
{
    if (!(v > 0.0f)) return 0;
    if (v >= 255.0f) return 255;
    return (uint8_t)(v + 0.5f);
}

static void tl__put(uint8_t *px, float r, float g, float b)
{
    px[0] = tl__to_u8(r);
    px[1] = tl__to_u8(g);
    px[2] = tl__to_u8(b);
    px[3] = 255;
}

/* ---- stones laid in courses ------------------------------------------------------------------- */

/* Courses of stones of random length (between min_len and max_len, as fractions of the repeat);
 * per texel: the stone's id and the distance to its nearest joint, in texels. */
typedef struct tl__bond {
    uint32_t rows;
    uint32_t size;
    float min_len, max_len;
    uint32_t seed;
} tl__bond;

#define TL__BOND_MAX_CUTS 32

static uint32_t tl__bond_row_cuts(const tl__bond *bond, uint32_t row, float *cuts)
{
    /* cut positions in [0, 1): stones run from cuts[k] to cuts[k + 1] (the last wraps) */
    float offset = tl__hash_unit(row, 7, bond->seed);
    float at = 0.0f;
    uint32_t n = 0;
    while (n < TL__BOND_MAX_CUTS) {
        cuts[n++] = at;
        float len = bond->min_len + (bond->max_len - bond->min_len) * tl__hash_unit(row, n, bond->seed + 1u);
        if (at + len > 1.0f - bond->min_len * 0.75f) break;
        at += len;
    }
    for (uint32_t k = 0; k < n; k++) {
        cuts[k] += offset;
        if (cuts[k] >= 1.0f) cuts[k] -= 1.0f;
    }
    return n;
}

static void tl__bond_texel(const tl__bond *bond, const float (*cuts)[TL__BOND_MAX_CUTS],
                           const uint32_t *ncuts, uint32_t x, uint32_t y, uint32_t *stone,
                           float *joint)
{
    float fs = (float)bond->size;
    float row_h = fs / (float)bond->rows;
    uint32_t row = (uint32_t)((float)y / row_h);
    if (row >= bond->rows) row = bond->rows - 1;
    float vy = (float)y + 0.5f - row_h * (float)row; /* texels into the row */
    float dy = fminf(vy, row_h - vy);
    float u = ((float)x + 0.5f) / fs;
    const float *c = cuts[row];
    uint32_t n = ncuts[row];
    /* the stone whose start is the last cut at or before u (cyclically) */
    uint32_t k = n - 1;
    float best = -1.0f;
    for (uint32_t i = 0; i < n; i++) {
        float d = u - c[i];
        if (d < 0.0f) d += 1.0f;
        if (best < 0.0f || d < best) {
            best = d;
            k = i;
        }
    }
    float start = c[k], end = c[(k + 1) % n];
    float d0 = u - start, d1 = end - u;
    if (d0 < 0.0f) d0 += 1.0f;
    if (d1 < 0.0f) d1 += 1.0f;
    float dx = fminf(d0, d1) * fs;
    *stone = row * 64u + k;
    *joint = fminf(dx, dy);
}

static void tl__bond_fill(const tl__bond *bond, float mortar, const float base[3], float tint,
                          const float mortar_rgb[3], uint8_t *rgba)
{
    float cuts[32][TL__BOND_MAX_CUTS];
    uint32_t ncuts[32];
    uint32_t rows = bond->rows > 32 ? 32 : bond->rows;
    for (uint32_t r = 0; r < rows; r++) ncuts[r] = tl__bond_row_cuts(bond, r, cuts[r]);
    uint32_t size = bond->size;
    for (uint32_t y = 0; y < size; y++) {
        for (uint32_t x = 0; x < size; x++) {
            float u = ((float)x + 0.5f) / (float)size, v = ((float)y + 0.5f) / (float)size;
            uint32_t stone;
            float joint;
            tl__bond_texel(bond, (const float (*)[TL__BOND_MAX_CUTS])cuts, ncuts, x, y, &stone, &joint);
            float grain = tl__fbm(u, v, 16, 3, bond->seed + 11u);
            float wobble = (tl__vnoise(u * 48.0f, v * 48.0f, 48, bond->seed + 23u) - 0.5f) * mortar * 1.2f;
            uint8_t *px = rgba + ((size_t)y * size + x) * 4;
            if (joint < mortar + wobble) {
                float m = 0.85f + 0.3f * grain;
                tl__put(px, mortar_rgb[0] * m, mortar_rgb[1] * m, mortar_rgb[2] * m);
                continue;
            }
            float s0 = tl__hash_unit(stone, 3, bond->seed + 5u) - 0.5f;
            float s1 = tl__hash_unit(stone, 4, bond->seed + 5u) - 0.5f;
            float shade = 1.0f + tint * s0 + 0.35f * (grain - 0.5f);
            float edge = fminf(1.0f, (joint - mortar) / (mortar * 2.5f + 1.0f)); /* worn arrises */
            shade *= 0.88f + 0.12f * edge;
            float warm = tint * 0.5f * s1;
            tl__put(px, base[0] * shade * (1.0f + warm), base[1] * shade,
                    base[2] * shade * (1.0f - warm));
        }
    }
}

/* ---- the four textures ------------------------------------------------------------------------ */

static void tl__gen_flagstone(uint8_t *rgba)
{
    const tl__bond bond = {4, 512, 0.18f, 0.42f, 0x51a9u};
    const float base[3] = {150.0f, 143.0f, 130.0f}, mortar[3] = {88.0f, 84.0f, 78.0f};
    tl__bond_fill(&bond, 2.2f, base, 0.35f, mortar, rgba);
}

static void tl__gen_ashlar(uint8_t *rgba)
{
    const tl__bond bond = {8, 512, 0.17f, 0.40f, 0xa511u};
    const float base[3] = {178.0f, 160.0f, 132.0f}, mortar[3] = {196.0f, 188.0f, 170.0f};
    tl__bond_fill(&bond, 1.8f, base, 0.25f, mortar, rgba);
}

static void tl__gen_marble(uint8_t *rgba)
{
    const uint32_t size = 512;
    for (uint32_t y = 0; y < size; y++) {
        for (uint32_t x = 0; x < size; x++) {
            float u = ((float)x + 0.5f) / (float)size, v = ((float)y + 0.5f) / (float)size;
            float turb = tl__fbm(u, v, 4, 4, 0x3a7bu);
            float cloud = tl__fbm(u, v, 8, 2, 0x77u);
            /* integer wave numbers keep the veins periodic */
            float phase = (float)TL__TAU * (2.0f * u + 1.0f * v) + 7.0f * turb;
            float vein = powf(1.0f - fabsf(sinf(phase)), 10.0f);
            float fine = powf(1.0f - fabsf(sinf((float)TL__TAU * (5.0f * u - 3.0f * v) + 9.0f * cloud)), 24.0f);
            float dark = 0.55f * vein + 0.25f * fine;
            float shade = 0.93f + 0.1f * (cloud - 0.5f);
            uint8_t *px = rgba + ((size_t)y * size + x) * 4;
            tl__put(px, (232.0f - 120.0f * dark) * shade, (229.0f - 112.0f * dark) * shade,
                    (222.0f - 95.0f * dark) * shade);
        }
    }
}

static void tl__gen_tiles(uint8_t *rgba)
{
    const uint32_t size = 256, cells = 8;
    const float cell = (float)size / (float)cells, grout = 1.6f;
    for (uint32_t y = 0; y < size; y++) {
        for (uint32_t x = 0; x < size; x++) {
            float u = ((float)x + 0.5f) / (float)size, v = ((float)y + 0.5f) / (float)size;
            uint32_t cx = (uint32_t)((float)x / cell), cy = (uint32_t)((float)y / cell);
            float lx = (float)x + 0.5f - cell * (float)cx, ly = (float)y + 0.5f - cell * (float)cy;
            float edge = fminf(fminf(lx, cell - lx), fminf(ly, cell - ly));
            float grain = tl__fbm(u, v, 16, 3, 0x71e5u);
            uint8_t *px = rgba + ((size_t)y * size + x) * 4;
            if (edge < grout) {
                tl__put(px, 78.0f, 74.0f, 70.0f);
                continue;
            }
            float var = tl__hash_unit(cx, cy, 0x9e1u) - 0.5f;
            float shade = (1.0f + 0.18f * var + 0.3f * (grain - 0.5f)) *
                          (0.9f + 0.1f * fminf(1.0f, (edge - grout) / 3.0f));
            if ((cx + cy) & 1u)
                tl__put(px, 150.0f * shade, 62.0f * shade, 42.0f * shade); /* terracotta */
            else
                tl__put(px, 212.0f * shade, 198.0f * shade, 168.0f * shade); /* cream */
        }
    }
}

void tl__texture_generate(int which, uint8_t *rgba)
{
    switch (which) {
    case TL__TEX_FLAGSTONE: tl__gen_flagstone(rgba); break;
    case TL__TEX_ASHLAR: tl__gen_ashlar(rgba); break;
    case TL__TEX_MARBLE: tl__gen_marble(rgba); break;
    case TL__TEX_TILES: tl__gen_tiles(rgba); break;
    default: break;
    }
}
