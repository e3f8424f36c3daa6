/* Octahedral mapping: the scalar arithmetic every path shares (scalar, SSE2 batch, GLSL mirror).
 * Each operation is written in the exact order shaders/codec.glsl uses, so that results agree
 * bit for bit; the build disables FMA contraction for the same reason. */
#ifndef TL_CODEC_OCT_CORE_H
#define TL_CODEC_OCT_CORE_H

#include <math.h>
#include <stdint.h>

#include "thinlight/codec.h"

static inline uint32_t tl__oct_clamp_bits(uint32_t bits)
{
    return bits < TL_OCT_MIN_BITS ? TL_OCT_MIN_BITS : bits > TL_OCT_MAX_BITS ? TL_OCT_MAX_BITS : bits;
}

/* The quantisation grid of a component is codes 0..top, code k standing for (2k - top) / top.
 * The library's grid is odd (top = 2^bits - 2, 2^bits - 1 levels): its centre code top / 2 is
 * exactly 0 and its ends exactly -1 and +1, so the axes and poles decode exactly; the code
 * 2^bits - 1 is unused and decodes as top. The even grid (top = 2^bits - 1, no 0) is kept for
 * comparison (TL_NORMAL_OCT_EVEN). */
static inline uint32_t tl__oct_top(uint32_t bits) { return (1u << bits) - 2u; }
static inline uint32_t tl__oct_top_even(uint32_t bits) { return (1u << bits) - 1u; }

/* Sign-not-zero from the sign bit: -0 gives -1, so the fold keeps -0 and +0 apart and the
 * round trip stays exact on the square's outer edges. */
static inline float tl__sign_not_zero(float v) { return copysignf(1.0f, v); }

/* True when (x, y, z) can be used without sanitising: its L1 norm lies in [2^-32, 2^60]. This
 * rejects NaN, Inf and zero, and keeps the precise variant's squared errors clear of overflow
 * and underflow: a losing candidate's |n x c|^2 is at least |n|^2 (2^-17)^2 at 16 bits, which
 * stays a normal float (> 2^-126) only for |n| above about 2^-46; below it, candidates' errors
 * flush to equal denormals or zero and the choice degrades to the first candidate. Anything
 * else is sanitised to a unit vector first. */
static inline int tl__oct_input_ok(float x, float y, float z)
{
    float l1 = (fabsf(x) + fabsf(y)) + fabsf(z);
    return l1 >= 0x1.0p-32f && l1 <= 0x1.0p60f;
}

static inline void tl__oct_project_raw(float x, float y, float z, float *pu, float *pv)
{
    float l1 = (fabsf(x) + fabsf(y)) + fabsf(z);
    float u = x / l1, v = y / l1;
    if (z < 0.0f) {
        float fu = (1.0f - fabsf(v)) * tl__sign_not_zero(u);
        float fv = (1.0f - fabsf(u)) * tl__sign_not_zero(v);
        u = fu;
        v = fv;
    }
    *pu = u;
    *pv = v;
}

/* Unnormalised direction for a point of the square. */
static inline void tl__oct_unproject_raw(float u, float v, float *x, float *y, float *z)
{
    float w = (1.0f - fabsf(u)) - fabsf(v);
    if (w < 0.0f) {
        float fu = (1.0f - fabsf(v)) * tl__sign_not_zero(u);
        float fv = (1.0f - fabsf(u)) * tl__sign_not_zero(v);
        u = fu;
        v = fv;
    }
    *x = u;
    *y = v;
    *z = w;
}

/* Component value of code k: (2k - top) / top, as one product with a rounded reciprocal. For
 * every top of the odd grid (2^bits - 2, bits 8..16), top * fl(1 / top) rounds to exactly 1, so
 * the ends are exactly -1 and +1 (and the centre is 0 * inv = 0). */
static inline float tl__oct_dequant(uint32_t k, uint32_t top, float inv_top)
{
    return (float)((int32_t)(2u * k) - (int32_t)top) * inv_top;
}

/* Nearest code for a component in [-1,1]: q = (p + 1) * (top / 2), code = trunc(q + 0.5). */
static inline uint32_t tl__oct_quant(float p, float half_top)
{
    float q = (p + 1.0f) * half_top;
    return (uint32_t)(int32_t)(q + 0.5f);
}

static inline void tl__normalize3(float *x, float *y, float *z)
{
    float inv = 1.0f / sqrtf((*x * *x + *y * *y) + *z * *z);
    *x *= inv;
    *y *= inv;
    *z *= inv;
}

/* A component's code: its `bits` bits, clamped to the grid (the odd grid's unused code). */
static inline uint32_t tl__oct_component(uint32_t code, uint32_t bits, uint32_t top)
{
    uint32_t k = code & ((1u << bits) - 1u);
    return k > top ? top : k;
}

static inline void tl__oct_decode_core(uint32_t code, uint32_t bits, uint32_t top, float n[3])
{
    float inv_top = 1.0f / (float)top;
    float u = tl__oct_dequant(tl__oct_component(code, bits, top), top, inv_top);
    float v = tl__oct_dequant(tl__oct_component(code >> bits, bits, top), top, inv_top);
    float x, y, z;
    tl__oct_unproject_raw(u, v, &x, &y, &z);
    tl__normalize3(&x, &y, &z);
    n[0] = x;
    n[1] = y;
    n[2] = z;
}

static inline uint32_t tl__oct_encode_core(float x, float y, float z, uint32_t bits, uint32_t top)
{
    float half_top = 0.5f * (float)top;
    float u, v;
    tl__oct_project_raw(x, y, z, &u, &v);
    return tl__oct_quant(u, half_top) | (tl__oct_quant(v, half_top) << bits);
}

/* Error of a candidate code: |n x c|^2 / |c|^2 = |n|^2 sin^2(angle). The sine keeps its relative
 * precision at tiny angles, where 1 - cos falls below float resolution (at 12 bits and more the
 * candidates' cosines differ by a few ULP). Smaller is better. */
static inline float tl__oct_candidate_error(float x, float y, float z, float cu, float cv)
{
    float dx, dy, dz;
    tl__oct_unproject_raw(cu, cv, &dx, &dy, &dz);
    float ex = y * dz - z * dy, ey = z * dx - x * dz, ez = x * dy - y * dx;
    float e = (ex * ex + ey * ey) + ez * ez;
    float l = (dx * dx + dy * dy) + dz * dz;
    return e / l;
}

static inline uint32_t tl__oct_encode_precise_core(float x, float y, float z, uint32_t bits, uint32_t top)
{
    float half_top = 0.5f * (float)top;
    float inv_top = 1.0f / (float)top;
    float u, v;
    tl__oct_project_raw(x, y, z, &u, &v);
    uint32_t u0 = (uint32_t)(int32_t)((u + 1.0f) * half_top);
    uint32_t v0 = (uint32_t)(int32_t)((v + 1.0f) * half_top);
    u0 = u0 > top - 1u ? top - 1u : u0;
    v0 = v0 > top - 1u ? top - 1u : v0;
    /* Per component, a = the plain-rounded code (always u0 or u0 + 1), b = the other one. */
    uint32_t ua = tl__oct_quant(u, half_top), va = tl__oct_quant(v, half_top);
    uint32_t ub = (2u * u0 + 1u) - ua, vb = (2u * v0 + 1u) - va;
    float cua = tl__oct_dequant(ua, top, inv_top), cub = tl__oct_dequant(ub, top, inv_top);
    float cva = tl__oct_dequant(va, top, inv_top), cvb = tl__oct_dequant(vb, top, inv_top);
    /* Candidates in a fixed order, the plain-rounded one first; a later one wins only when
     * strictly better. Exact ties happen where two codes are mirror images of one direction on
     * the square's outer edge (they differ only in a zero's sign); the plain-rounded code keeps
     * the sign the input had, so decode -> encode stays exact there. */
    float best = tl__oct_candidate_error(x, y, z, cua, cva);
    uint32_t bu = ua, bv = va;
    float e = tl__oct_candidate_error(x, y, z, cub, cva);
    if (e < best) { best = e; bu = ub; bv = va; }
    e = tl__oct_candidate_error(x, y, z, cua, cvb);
    if (e < best) { best = e; bu = ua; bv = vb; }
    e = tl__oct_candidate_error(x, y, z, cub, cvb);
    if (e < best) { bu = ub; bv = vb; }
    return bu | (bv << bits);
}

/* Batch encode and decode on a given grid (oct.c, SSE2 where available); the public batch
 * functions use the odd grid, normal_alt.c the even one too. */
void tl__oct_encode_grid_n(const float *n, uint32_t *codes, size_t count, uint32_t bits, uint32_t top, int precise);
void tl__oct_decode_grid_n(const uint32_t *codes, float *n, size_t count, uint32_t bits, uint32_t top);
/* Scalar encode and decode on a given grid, any input (sanitised as the public functions do). */
uint32_t tl__oct_encode_grid(const float n[3], uint32_t bits, uint32_t top, int precise);
void tl__oct_decode_grid(uint32_t code, uint32_t bits, uint32_t top, float n[3]);

#endif
