/* IEEE binary16 conversion for the light buffer: round to nearest even, saturating. */
#include <string.h>

#include "thinlight/codec.h"

uint16_t tl_half_from_float(float f)
{
    uint32_t x;
    memcpy(&x, &f, sizeof x);
    uint16_t sign = (uint16_t)((x >> 16) & 0x8000u);
    uint32_t a = x & 0x7FFFFFFFu;
    if (a > 0x7F800000u) return 0; /* NaN -> +0: no NaN may reach a target */
    /* 65520 = 0x477FF000 is the midpoint between TL_HALF_MAX and 2^16: it and anything larger
     * (Inf included) would round to Inf, so saturate instead. */
    if (a >= 0x477FF000u) return (uint16_t)(sign | 0x7BFFu);
    if (a >= 0x38800000u) { /* normal half: exponent >= -14 */
        uint32_t mant = a & 0x7FFFFFu;
        uint32_t exp = (a >> 23) - 112u; /* rebias 127 -> 15 */
        uint32_t h = (exp << 10) | (mant >> 13);
        uint32_t rest = mant & 0x1FFFu;
        if (rest > 0x1000u || (rest == 0x1000u && (h & 1u))) h++; /* may carry into the exponent */
        return (uint16_t)(sign | h);
    }
    if (a < 0x33000000u) return sign; /* below half the smallest denormal (2^-25): rounds to 0 */
    /* Denormal half: value = m * 2^-24 with m = round(f * 2^24). */
    uint32_t e = a >> 23;                       /* 102 .. 112 */
    uint32_t mant = (a & 0x7FFFFFu) | 0x800000u; /* implicit 1 */
    uint32_t shift = 126u - e;                  /* 14 .. 24 */
    uint32_t h = mant >> shift;
    uint32_t rest = mant & ((1u << shift) - 1u), halfway = 1u << (shift - 1u);
    if (rest > halfway || (rest == halfway && (h & 1u))) h++;
    return (uint16_t)(sign | h);
}

float tl_half_to_float(uint16_t h)
{
    uint32_t sign = (uint32_t)(h & 0x8000u) << 16;
    uint32_t exp = (h >> 10) & 0x1Fu, mant = h & 0x3FFu;
    uint32_t x;
    if (exp == 0x1Fu) {
        x = sign | 0x7F800000u | (mant << 13);
    } else if (exp != 0) {
        x = sign | ((exp + 112u) << 23) | (mant << 13);
    } else if (mant == 0) {
        x = sign;
    } else { /* denormal: normalise */
        uint32_t e = 113u;
        while (!(mant & 0x400u)) {
            mant <<= 1;
            e--;
        }
        x = sign | (e << 23) | ((mant & 0x3FFu) << 13);
    }
    float f;
    memcpy(&f, &x, sizeof f);
    return f;
}

void tl_half_from_float_n(const float *f, uint16_t *h, size_t count)
{
    if (!f || !h) return;
    for (size_t i = 0; i < count; i++) h[i] = tl_half_from_float(f[i]);
}

void tl_half_to_float_n(const uint16_t *h, float *f, size_t count)
{
    if (!f || !h) return;
    for (size_t i = 0; i < count; i++) f[i] = tl_half_to_float(h[i]);
}
