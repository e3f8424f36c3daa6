/* Other 2-component unit-vector encodings, for comparison with the octahedral one in the codec
 * report. All share the octahedral code layout (u low, v high); Lambert and stereographic use the
 * octahedral odd snorm grid (codes 0..top), spherical a unorm grid (codes 0..2^bits - 1), and the
 * octahedral even-grid variants the previous snorm grid. */
#include <math.h>

#include "oct_core.h"

#define TL__PI 3.14159265358979323846f

static const char *const tl__normal_names[TL_NORMAL_ENCODING_COUNT_] = {
    "oct-precise", "oct", "oct-precise", "spherical", "lambert", "stereographic", "oct-even", "oct-precise-even",
};

const char *tl_normal_encoding_name(tl_normal_encoding encoding)
{
    return (unsigned)encoding < TL_NORMAL_ENCODING_COUNT_ ? tl__normal_names[encoding] : "unknown";
}

static inline uint32_t tl__unorm(float f, uint32_t max)
{
    f = f > 0.0f ? (f < 1.0f ? f : 1.0f) : 0.0f;
    return (uint32_t)(f * (float)max + 0.5f);
}

static inline uint32_t tl__pack2(uint32_t u, uint32_t v, uint32_t bits) { return u | (v << bits); }

/* Spherical: azimuth on a uniform grid over [-pi, pi], and cos(polar) = z over [-1, 1] (which
 * makes the grid equal-area in z). */
static uint32_t tl__spherical_encode(const float n[3], uint32_t max, uint32_t bits)
{
    float phi = atan2f(n[1], n[0]);
    return tl__pack2(tl__unorm((phi / TL__PI + 1.0f) * 0.5f, max), tl__unorm((n[2] + 1.0f) * 0.5f, max), bits);
}

static void tl__spherical_decode(uint32_t u, uint32_t v, uint32_t max, float n[3])
{
    float phi = ((float)u / (float)max * 2.0f - 1.0f) * TL__PI;
    float z = (float)v / (float)max * 2.0f - 1.0f;
    float r = sqrtf(fmaxf(0.0f, 1.0f - z * z));
    n[0] = r * cosf(phi);
    n[1] = r * sinf(phi);
    n[2] = z;
}

/* Lambert azimuthal equal-area from the north pole: (X, Y) = sqrt(2 / (1 + z)) (x, y), a disc of
 * radius 2 scaled into [-1, 1]^2. The south pole is the disc's whole rim; it encodes as (1, 0). */
static uint32_t tl__lambert_encode(const float n[3], uint32_t top, uint32_t bits)
{
    float f = 1.0f + n[2];
    float X = 1.0f, Y = 0.0f;
    if (f > 1e-12f) {
        float s = sqrtf(2.0f / f) * 0.5f;
        X = n[0] * s;
        Y = n[1] * s;
    }
    float half_top = 0.5f * (float)top;
    return tl__pack2(tl__oct_quant(fminf(fmaxf(X, -1.0f), 1.0f), half_top),
                     tl__oct_quant(fminf(fmaxf(Y, -1.0f), 1.0f), half_top), bits);
}

static void tl__lambert_decode(uint32_t u, uint32_t v, uint32_t top, float n[3])
{
    float inv_top = 1.0f / (float)top;
    float X = tl__oct_dequant(u, top, inv_top) * 2.0f, Y = tl__oct_dequant(v, top, inv_top) * 2.0f;
    float r2 = X * X + Y * Y;
    if (r2 > 4.0f) { /* corners of the square lie outside the disc: pull them onto the rim */
        float k = 2.0f / sqrtf(r2);
        X *= k;
        Y *= k;
        r2 = 4.0f;
    }
    float s = sqrtf(fmaxf(0.0f, 1.0f - r2 * 0.25f));
    n[0] = X * s;
    n[1] = Y * s;
    n[2] = 1.0f - r2 * 0.5f;
    tl__normalize3(&n[0], &n[1], &n[2]);
}

/* Stereographic from the south pole: (X, Y) = (x, y) / (1 + z), the unit disc for z >= 0. Lower
 * hemisphere inputs are moved to the equator (G-buffers use it for view-space normals). */
static uint32_t tl__stereo_encode(const float n[3], uint32_t top, uint32_t bits)
{
    float x = n[0], y = n[1], z = n[2];
    if (z < 0.0f) {
        float r = sqrtf(x * x + y * y);
        if (r > 0.0f) {
            x /= r;
            y /= r;
        } else {
            x = 1.0f;
            y = 0.0f;
        }
        z = 0.0f;
    }
    float half_top = 0.5f * (float)top;
    float X = x / (1.0f + z), Y = y / (1.0f + z);
    return tl__pack2(tl__oct_quant(fminf(fmaxf(X, -1.0f), 1.0f), half_top),
                     tl__oct_quant(fminf(fmaxf(Y, -1.0f), 1.0f), half_top), bits);
}

static void tl__stereo_decode(uint32_t u, uint32_t v, uint32_t top, float n[3])
{
    float inv_top = 1.0f / (float)top;
    float X = tl__oct_dequant(u, top, inv_top), Y = tl__oct_dequant(v, top, inv_top);
    float d = X * X + Y * Y;
    n[0] = 2.0f * X / (1.0f + d);
    n[1] = 2.0f * Y / (1.0f + d);
    n[2] = (1.0f - d) / (1.0f + d);
    tl__normalize3(&n[0], &n[1], &n[2]);
}

uint32_t tl_normal_encode(tl_normal_encoding encoding, const float n[3], uint32_t bits)
{
    bits = tl__oct_clamp_bits(bits);
    uint32_t max = (1u << bits) - 1u, top = tl__oct_top(bits);
    float s[3];
    switch (encoding) {
    case TL_NORMAL_OCT: return tl_oct_encode(n, bits);
    case TL_NORMAL_SPHERICAL: tl_normal_sanitize(n, s); return tl__spherical_encode(s, max, bits);
    case TL_NORMAL_LAMBERT: tl_normal_sanitize(n, s); return tl__lambert_encode(s, top, bits);
    case TL_NORMAL_STEREOGRAPHIC: tl_normal_sanitize(n, s); return tl__stereo_encode(s, top, bits);
    case TL_NORMAL_OCT_EVEN: return tl__oct_encode_grid(n, bits, tl__oct_top_even(bits), 0);
    case TL_NORMAL_OCT_PRECISE_EVEN: return tl__oct_encode_grid(n, bits, tl__oct_top_even(bits), 1);
    case TL_NORMAL_DEFAULT:
    case TL_NORMAL_OCT_PRECISE:
    default: return tl_oct_encode_precise(n, bits);
    }
}

void tl_normal_decode(tl_normal_encoding encoding, uint32_t code, uint32_t bits, float n[3])
{
    bits = tl__oct_clamp_bits(bits);
    uint32_t max = (1u << bits) - 1u, top = tl__oct_top(bits);
    uint32_t u = code & max, v = (code >> bits) & max;
    switch (encoding) {
    case TL_NORMAL_SPHERICAL: tl__spherical_decode(u, v, max, n); return;
    case TL_NORMAL_LAMBERT:
        tl__lambert_decode(tl__oct_component(code, bits, top), tl__oct_component(code >> bits, bits, top), top, n);
        return;
    case TL_NORMAL_STEREOGRAPHIC:
        tl__stereo_decode(tl__oct_component(code, bits, top), tl__oct_component(code >> bits, bits, top), top, n);
        return;
    case TL_NORMAL_OCT_EVEN:
    case TL_NORMAL_OCT_PRECISE_EVEN: tl__oct_decode_grid(code, bits, tl__oct_top_even(bits), n); return;
    default: tl_oct_decode(code, bits, n); return;
    }
}

static int tl__is_oct_even(tl_normal_encoding e) { return e == TL_NORMAL_OCT_EVEN || e == TL_NORMAL_OCT_PRECISE_EVEN; }

void tl_normal_encode_n(tl_normal_encoding encoding, const float *n, uint32_t *codes, size_t count,
                        uint32_t bits)
{
    if (!n || !codes) return;
    if (encoding == TL_NORMAL_OCT) {
        tl_oct_encode_n(n, codes, count, bits);
    } else if (encoding == TL_NORMAL_OCT_PRECISE || encoding == TL_NORMAL_DEFAULT) {
        tl_oct_encode_precise_n(n, codes, count, bits);
    } else if (tl__is_oct_even(encoding)) {
        bits = tl__oct_clamp_bits(bits);
        tl__oct_encode_grid_n(n, codes, count, bits, tl__oct_top_even(bits), encoding == TL_NORMAL_OCT_PRECISE_EVEN);
    } else {
        for (size_t i = 0; i < count; i++) codes[i] = tl_normal_encode(encoding, n + 3 * i, bits);
    }
}

void tl_normal_decode_n(tl_normal_encoding encoding, const uint32_t *codes, float *n, size_t count,
                        uint32_t bits)
{
    if (!n || !codes) return;
    if (encoding == TL_NORMAL_OCT || encoding == TL_NORMAL_OCT_PRECISE || encoding == TL_NORMAL_DEFAULT) {
        tl_oct_decode_n(codes, n, count, bits);
    } else if (tl__is_oct_even(encoding)) {
        bits = tl__oct_clamp_bits(bits);
        tl__oct_decode_grid_n(codes, n, count, bits, tl__oct_top_even(bits));
    } else {
        for (size_t i = 0; i < count; i++) tl_normal_decode(encoding, codes[i], bits, n + 3 * i);
    }
}
