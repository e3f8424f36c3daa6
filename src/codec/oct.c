/* Octahedral unit-vector encoding: sanitising, scalar and batch encode/decode.
 * The batch functions use SSE2 where available; they perform the same IEEE operations in the
 * same order as oct_core.h, so their results are bit-identical to the scalar ones. */
#include <math.h>

#include "oct_core.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#define TL__OCT_SSE2 1
#endif

void tl_normal_sanitize(const float in[3], float out[3])
{
    float x = in[0], y = in[1], z = in[2];
    if (isnan(x) || isnan(y) || isnan(z)) {
        out[0] = 0.0f;
        out[1] = 0.0f;
        out[2] = 1.0f;
        return;
    }
    float m = fmaxf(fabsf(x), fmaxf(fabsf(y), fabsf(z)));
    if (m == 0.0f) {
        out[0] = 0.0f;
        out[1] = 0.0f;
        out[2] = 1.0f;
        return;
    }
    if (isinf(m)) {
        /* Only the infinite components count; their signs give the direction. */
        x = isinf(x) ? copysignf(1.0f, x) : 0.0f;
        y = isinf(y) ? copysignf(1.0f, y) : 0.0f;
        z = isinf(z) ? copysignf(1.0f, z) : 0.0f;
    } else {
        /* Dividing by the largest magnitude is exact enough and lifts denormals into range. */
        x /= m;
        y /= m;
        z /= m;
    }
    tl__normalize3(&x, &y, &z);
    out[0] = x;
    out[1] = y;
    out[2] = z;
}

/* Input as the cores see it: unchanged when usable, sanitised otherwise. */
static inline void tl__oct_input(const float n[3], float v[3])
{
    if (tl__oct_input_ok(n[0], n[1], n[2])) {
        v[0] = n[0];
        v[1] = n[1];
        v[2] = n[2];
    } else {
        tl_normal_sanitize(n, v);
    }
}

void tl_oct_project(const float n[3], float p[2])
{
    float v[3];
    tl__oct_input(n, v);
    tl__oct_project_raw(v[0], v[1], v[2], &p[0], &p[1]);
}

void tl_oct_unproject(const float p[2], float n[3])
{
    float u = p[0], v = p[1];
    u = isnan(u) ? 0.0f : fminf(fmaxf(u, -1.0f), 1.0f);
    v = isnan(v) ? 0.0f : fminf(fmaxf(v, -1.0f), 1.0f);
    float x, y, z;
    tl__oct_unproject_raw(u, v, &x, &y, &z);
    tl__normalize3(&x, &y, &z);
    n[0] = x;
    n[1] = y;
    n[2] = z;
}

uint32_t tl__oct_encode_grid(const float n[3], uint32_t bits, uint32_t top, int precise)
{
    float v[3];
    tl__oct_input(n, v);
    return precise ? tl__oct_encode_precise_core(v[0], v[1], v[2], bits, top)
                   : tl__oct_encode_core(v[0], v[1], v[2], bits, top);
}

void tl__oct_decode_grid(uint32_t code, uint32_t bits, uint32_t top, float n[3])
{
    tl__oct_decode_core(code, bits, top, n);
}

uint32_t tl_oct_encode(const float n[3], uint32_t bits)
{
    bits = tl__oct_clamp_bits(bits);
    return tl__oct_encode_grid(n, bits, tl__oct_top(bits), 0);
}

uint32_t tl_oct_encode_precise(const float n[3], uint32_t bits)
{
    bits = tl__oct_clamp_bits(bits);
    return tl__oct_encode_grid(n, bits, tl__oct_top(bits), 1);
}

void tl_oct_decode(uint32_t code, uint32_t bits, float n[3])
{
    bits = tl__oct_clamp_bits(bits);
    tl__oct_decode_core(code, bits, tl__oct_top(bits), n);
}

#if TL__OCT_SSE2

static inline __m128 tl__v_abs(__m128 a) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), a); }
static inline __m128 tl__v_sign_not_zero(__m128 a)
{
    return _mm_or_ps(_mm_and_ps(_mm_set1_ps(-0.0f), a), _mm_set1_ps(1.0f));
}
static inline __m128 tl__v_select(__m128 mask, __m128 a, __m128 b)
{
    return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}
static inline __m128i tl__vi_select(__m128 mask, __m128i a, __m128i b)
{
    __m128i m = _mm_castps_si128(mask);
    return _mm_or_si128(_mm_and_si128(m, a), _mm_andnot_si128(m, b));
}

/* 4 xyz triples (12 floats) to x, y, z vectors. */
static inline void tl__v_load_xyz(const float *p, __m128 *x, __m128 *y, __m128 *z)
{
    __m128 a = _mm_loadu_ps(p), b = _mm_loadu_ps(p + 4), c = _mm_loadu_ps(p + 8);
    __m128 t0 = _mm_shuffle_ps(b, c, _MM_SHUFFLE(2, 1, 3, 2));
    __m128 t1 = _mm_shuffle_ps(a, b, _MM_SHUFFLE(1, 0, 2, 1));
    *x = _mm_shuffle_ps(a, t0, _MM_SHUFFLE(2, 0, 3, 0));
    *y = _mm_shuffle_ps(t1, t0, _MM_SHUFFLE(3, 1, 2, 0));
    *z = _mm_shuffle_ps(t1, c, _MM_SHUFFLE(3, 0, 3, 1));
}

static inline void tl__v_store_xyz(float *p, __m128 x, __m128 y, __m128 z)
{
    __m128 xy_lo = _mm_unpacklo_ps(x, y), xy_hi = _mm_unpackhi_ps(x, y);
    __m128 yz_lo = _mm_unpacklo_ps(y, z), yz_hi = _mm_unpackhi_ps(y, z);
    __m128 t = _mm_shuffle_ps(z, x, _MM_SHUFFLE(1, 1, 0, 0));
    __m128 t2 = _mm_shuffle_ps(z, x, _MM_SHUFFLE(3, 3, 2, 2));
    _mm_storeu_ps(p, _mm_shuffle_ps(xy_lo, t, _MM_SHUFFLE(2, 0, 1, 0)));
    _mm_storeu_ps(p + 4, _mm_shuffle_ps(yz_lo, xy_hi, _MM_SHUFFLE(1, 0, 3, 2)));
    _mm_storeu_ps(p + 8, _mm_shuffle_ps(t2, yz_hi, _MM_SHUFFLE(3, 2, 2, 0)));
}

/* Lanes whose input needs sanitising (see tl__oct_input_ok); NaN compares false, so it is bad. */
static inline int tl__v_bad_mask(__m128 x, __m128 y, __m128 z)
{
    __m128 l1 = _mm_add_ps(_mm_add_ps(tl__v_abs(x), tl__v_abs(y)), tl__v_abs(z));
    __m128 ok = _mm_and_ps(_mm_cmpge_ps(l1, _mm_set1_ps(0x1.0p-32f)),
                           _mm_cmple_ps(l1, _mm_set1_ps(0x1.0p60f)));
    return _mm_movemask_ps(ok) ^ 0xF;
}

static inline void tl__v_project(__m128 x, __m128 y, __m128 z, __m128 *pu, __m128 *pv)
{
    __m128 l1 = _mm_add_ps(_mm_add_ps(tl__v_abs(x), tl__v_abs(y)), tl__v_abs(z));
    __m128 u = _mm_div_ps(x, l1), v = _mm_div_ps(y, l1);
    __m128 one = _mm_set1_ps(1.0f);
    __m128 fu = _mm_mul_ps(_mm_sub_ps(one, tl__v_abs(v)), tl__v_sign_not_zero(u));
    __m128 fv = _mm_mul_ps(_mm_sub_ps(one, tl__v_abs(u)), tl__v_sign_not_zero(v));
    __m128 lower = _mm_cmplt_ps(z, _mm_setzero_ps());
    *pu = tl__v_select(lower, fu, u);
    *pv = tl__v_select(lower, fv, v);
}

static inline void tl__v_unproject(__m128 u, __m128 v, __m128 *x, __m128 *y, __m128 *z)
{
    __m128 one = _mm_set1_ps(1.0f);
    __m128 au = tl__v_abs(u), av = tl__v_abs(v);
    __m128 w = _mm_sub_ps(_mm_sub_ps(one, au), av);
    __m128 fu = _mm_mul_ps(_mm_sub_ps(one, av), tl__v_sign_not_zero(u));
    __m128 fv = _mm_mul_ps(_mm_sub_ps(one, au), tl__v_sign_not_zero(v));
    __m128 lower = _mm_cmplt_ps(w, _mm_setzero_ps());
    *x = tl__v_select(lower, fu, u);
    *y = tl__v_select(lower, fv, v);
    *z = w;
}

static inline __m128 tl__v_dequant(__m128i k, __m128i top, __m128 inv_top)
{
    return _mm_mul_ps(_mm_cvtepi32_ps(_mm_sub_epi32(_mm_add_epi32(k, k), top)), inv_top);
}

/* min(k, top) for non-negative k, without SSE4.1's pminsd */
static inline __m128i tl__vi_min(__m128i k, __m128i top)
{
    __m128i gt = _mm_cmpgt_epi32(k, top);
    return _mm_or_si128(_mm_and_si128(gt, top), _mm_andnot_si128(gt, k));
}

static inline __m128 tl__v_error(__m128 x, __m128 y, __m128 z, __m128 cu, __m128 cv)
{
    __m128 dx, dy, dz;
    tl__v_unproject(cu, cv, &dx, &dy, &dz);
    __m128 ex = _mm_sub_ps(_mm_mul_ps(y, dz), _mm_mul_ps(z, dy));
    __m128 ey = _mm_sub_ps(_mm_mul_ps(z, dx), _mm_mul_ps(x, dz));
    __m128 ez = _mm_sub_ps(_mm_mul_ps(x, dy), _mm_mul_ps(y, dx));
    __m128 e = _mm_add_ps(_mm_add_ps(_mm_mul_ps(ex, ex), _mm_mul_ps(ey, ey)), _mm_mul_ps(ez, ez));
    __m128 l = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
    return _mm_div_ps(e, l);
}

static void tl__oct_encode_block(const float *n, uint32_t *codes, uint32_t bits, uint32_t top, int precise)
{
    __m128 x, y, z, u, v;
    tl__v_load_xyz(n, &x, &y, &z);
    tl__v_project(x, y, z, &u, &v);
    __m128 half_top = _mm_set1_ps(0.5f * (float)top);
    __m128 one = _mm_set1_ps(1.0f), h = _mm_set1_ps(0.5f);
    /* the plain-rounded codes, trunc(q + 0.5) */
    __m128i ua = _mm_cvttps_epi32(_mm_add_ps(_mm_mul_ps(_mm_add_ps(u, one), half_top), h));
    __m128i va = _mm_cvttps_epi32(_mm_add_ps(_mm_mul_ps(_mm_add_ps(v, one), half_top), h));
    __m128i code = _mm_or_si128(ua, _mm_sll_epi32(va, _mm_cvtsi32_si128((int)bits)));
    if (precise) {
        __m128i vtop = _mm_set1_epi32((int32_t)top), below = _mm_set1_epi32((int32_t)top - 1);
        __m128i ione = _mm_set1_epi32(1);
        __m128 inv_top = _mm_set1_ps(1.0f / (float)top);
        __m128i u0 = tl__vi_min(_mm_cvttps_epi32(_mm_mul_ps(_mm_add_ps(u, one), half_top)), below);
        __m128i v0 = tl__vi_min(_mm_cvttps_epi32(_mm_mul_ps(_mm_add_ps(v, one), half_top)), below);
        /* plain-rounded code first (see tl__oct_encode_precise_core), the other one second */
        __m128i ub = _mm_sub_epi32(_mm_add_epi32(_mm_add_epi32(u0, u0), ione), ua);
        __m128i vb = _mm_sub_epi32(_mm_add_epi32(_mm_add_epi32(v0, v0), ione), va);
        __m128 cua = tl__v_dequant(ua, vtop, inv_top), cub = tl__v_dequant(ub, vtop, inv_top);
        __m128 cva = tl__v_dequant(va, vtop, inv_top), cvb = tl__v_dequant(vb, vtop, inv_top);
        __m128 best = tl__v_error(x, y, z, cua, cva);
        __m128i bu = ua, bv = va;
        __m128 s = tl__v_error(x, y, z, cub, cva);
        __m128 m = _mm_cmplt_ps(s, best);
        best = tl__v_select(m, s, best);
        bu = tl__vi_select(m, ub, bu);
        bv = tl__vi_select(m, va, bv);
        s = tl__v_error(x, y, z, cua, cvb);
        m = _mm_cmplt_ps(s, best);
        best = tl__v_select(m, s, best);
        bu = tl__vi_select(m, ua, bu);
        bv = tl__vi_select(m, vb, bv);
        s = tl__v_error(x, y, z, cub, cvb);
        m = _mm_cmplt_ps(s, best);
        bu = tl__vi_select(m, ub, bu);
        bv = tl__vi_select(m, vb, bv);
        code = _mm_or_si128(bu, _mm_sll_epi32(bv, _mm_cvtsi32_si128((int)bits)));
    }
    _mm_storeu_si128((__m128i *)(void *)codes, code);
    int bad = tl__v_bad_mask(x, y, z);
    if (bad) {
        for (int i = 0; i < 4; i++)
            if (bad & (1 << i)) codes[i] = tl__oct_encode_grid(n + 3 * i, bits, top, precise);
    }
}

static void tl__oct_decode_block(const uint32_t *codes, float *n, uint32_t bits, uint32_t top)
{
    __m128i c = _mm_loadu_si128((const __m128i *)(const void *)codes);
    __m128i mask = _mm_set1_epi32((int32_t)((1u << bits) - 1u)), vtop = _mm_set1_epi32((int32_t)top);
    __m128 inv_top = _mm_set1_ps(1.0f / (float)top);
    __m128i ku = tl__vi_min(_mm_and_si128(c, mask), vtop);
    __m128i kv = tl__vi_min(_mm_and_si128(_mm_srl_epi32(c, _mm_cvtsi32_si128((int)bits)), mask), vtop);
    __m128 u = tl__v_dequant(ku, vtop, inv_top);
    __m128 v = tl__v_dequant(kv, vtop, inv_top);
    __m128 x, y, z;
    tl__v_unproject(u, v, &x, &y, &z);
    __m128 len2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_mul_ps(z, z));
    __m128 inv = _mm_div_ps(_mm_set1_ps(1.0f), _mm_sqrt_ps(len2));
    tl__v_store_xyz(n, _mm_mul_ps(x, inv), _mm_mul_ps(y, inv), _mm_mul_ps(z, inv));
}

#endif /* TL__OCT_SSE2 */

void tl__oct_encode_grid_n(const float *n, uint32_t *codes, size_t count, uint32_t bits, uint32_t top, int precise)
{
    if (!n || !codes) return;
    size_t i = 0;
#if TL__OCT_SSE2
    for (; i + 4 <= count; i += 4) tl__oct_encode_block(n + 3 * i, codes + i, bits, top, precise);
#endif
    for (; i < count; i++) codes[i] = tl__oct_encode_grid(n + 3 * i, bits, top, precise);
}

void tl__oct_decode_grid_n(const uint32_t *codes, float *n, size_t count, uint32_t bits, uint32_t top)
{
    if (!n || !codes) return;
    size_t i = 0;
#if TL__OCT_SSE2
    for (; i + 4 <= count; i += 4) tl__oct_decode_block(codes + i, n + 3 * i, bits, top);
#endif
    for (; i < count; i++) tl__oct_decode_core(codes[i], bits, top, n + 3 * i);
}

void tl_oct_encode_n(const float *n, uint32_t *codes, size_t count, uint32_t bits)
{
    bits = tl__oct_clamp_bits(bits);
    tl__oct_encode_grid_n(n, codes, count, bits, tl__oct_top(bits), 0);
}

void tl_oct_encode_precise_n(const float *n, uint32_t *codes, size_t count, uint32_t bits)
{
    bits = tl__oct_clamp_bits(bits);
    tl__oct_encode_grid_n(n, codes, count, bits, tl__oct_top(bits), 1);
}

void tl_oct_decode_n(const uint32_t *codes, float *n, size_t count, uint32_t bits)
{
    bits = tl__oct_clamp_bits(bits);
    tl__oct_decode_grid_n(codes, n, count, bits, tl__oct_top(bits));
}
