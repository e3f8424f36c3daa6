/* Half floats (light buffer), the gloss mapping and the RT0 packings. Half rounding is checked
 * against a reference that finds the nearest half by comparing neighbours in double; gloss and
 * RT0 against double formulas and the octahedral functions they are built from. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "thinlight/codec.h"
#include "tl_test.h"

static uint32_t float_bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u;
}

static float bits_float(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/* ---------------------------------------------------------------------------------------------
 * Half float
 * ------------------------------------------------------------------------------------------- */

/* Value of a finite half from its fields, in double (exact). */
static double half_value(uint16_t h)
{
    int e = (h >> 10) & 0x1F, m = h & 0x3FF;
    double v = e == 0 ? ldexp((double)m, -24) : ldexp(1024.0 + m, e - 25);
    return (h & 0x8000u) ? -v : v;
}

/* Values of the non-negative halves 0 .. 0x7BFF, plus 0x7C00 standing for 2^16 (the next value
 * the format would round to, i.e. overflow). Sorted ascending. */
static double half_table[0x7C01];

static void build_half_table(void)
{
    for (uint32_t h = 0; h < 0x7C00; h++) half_table[h] = half_value((uint16_t)h);
    half_table[0x7C00] = 65536.0;
}

/* IEEE binary16 round-to-nearest-even of f, saturating as the header says: NaN -> +0, results
 * that would round to Inf -> +-65504. The nearest half is found by comparing the two
 * neighbours of |f| in the table; the differences are exact in double. */
static uint16_t half_reference(float f)
{
    if (isnan(f)) return 0;
    uint16_t sign = signbit(f) ? 0x8000u : 0u;
    double a = fabs((double)f);
    if (a >= 65536.0) return (uint16_t)(sign | 0x7BFFu);
    uint32_t lo = 0, hi = 0x7C00; /* half_table[lo] <= a < half_table[hi] */
    while (hi - lo > 1) {
        uint32_t mid = (lo + hi) / 2;
        if (half_table[mid] <= a) lo = mid;
        else hi = mid;
    }
    double dlo = a - half_table[lo], dhi = half_table[hi] - a;
    uint32_t h = dlo < dhi ? lo : dhi < dlo ? hi : ((lo & 1u) ? hi : lo); /* tie: even pattern */
    if (h >= 0x7C00) h = 0x7BFF;                                          /* would be Inf */
    return (uint16_t)(sign | h);
}

/* Every half: to_float is exact (checked against the field formula), and from_float maps it back
 * to itself; NaN halves come back as +0 and Inf halves as +-65504 (saturation). */
TL_TEST(half_all_65536_round_trip)
{
    uint32_t identity = 0, nan_to_zero = 0, inf_saturated = 0, bad = 0;
    for (uint32_t i = 0; i < 65536; i++) {
        uint16_t h = (uint16_t)i;
        float f = tl_half_to_float(h);
        uint16_t back = tl_half_from_float(f);
        int exp31 = ((h >> 10) & 0x1F) == 0x1F, mant = h & 0x3FF;
        if (exp31 && mant) { /* NaN half */
            TL_CHECK(isnan(f));
            if (back == 0) nan_to_zero++;
            else bad++;
        } else if (exp31) { /* Inf half */
            TL_CHECK(isinf(f) && !!signbit(f) == !!(h & 0x8000u));
            if (back == ((h & 0x8000u) | 0x7BFFu)) inf_saturated++;
            else bad++;
        } else {
            double ref = half_value(h);
            TL_CHECK((double)f == ref && !!signbit(f) == !!(h & 0x8000u));
            if (back == h) identity++;
            else {
                if (bad < 5) fprintf(stderr, "  half 0x%04x -> %a -> 0x%04x\n", h, (double)f, back);
                bad++;
            }
        }
    }
    printf("  65536 halves: %u identical after half->float->half, %u NaN -> +0, %u Inf -> +-65504, %u wrong\n",
           identity, nan_to_zero, inf_saturated, bad);
    /* all but the NaNs (2 signs x 2^10 - 1 non-zero mantissas) and the two infinities */
    TL_CHECK_EQ_U(identity, 65536u - 2u * TL_UNORM_MAX(TL_HALF_MANTISSA_BITS) - 2u);
    TL_CHECK_EQ_U(bad, 0);
    /* batch forms */
    uint16_t all[4096], back[4096];
    float f[4096];
    for (uint32_t start = 0; start < 65536; start += 4096) {
        for (uint32_t i = 0; i < 4096; i++) all[i] = (uint16_t)(start + i);
        tl_half_to_float_n(all, f, 4096);
        tl_half_from_float_n(f, back, 4096);
        for (uint32_t i = 0; i < 4096; i++) {
            float s = tl_half_to_float(all[i]);
            TL_CHECK(memcmp(&s, &f[i], sizeof s) == 0);
            TL_CHECK_EQ_U(back[i], tl_half_from_float(s));
        }
    }
}

/* Every rounding boundary of the format: each half value, each midpoint between neighbours and
 * one float ULP either side of both, with both signs. */
TL_TEST(half_from_float_every_boundary_matches_reference)
{
    build_half_table();
    uint32_t checked = 0, wrong = 0;
    for (uint32_t h = 0; h < 0x7C00; h++) {
        double v = half_table[h], mid = 0.5 * (half_table[h] + half_table[h + 1]);
        const float base[2] = {(float)v, (float)mid}; /* both exact in float */
        for (int b = 0; b < 2; b++) {
            TL_CHECK((double)base[b] == (b ? mid : v));
            const float probes[3] = {nextafterf(base[b], 0.0f), base[b], nextafterf(base[b], INFINITY)};
            for (int p = 0; p < 3; p++)
                for (int s = 0; s < 2; s++) {
                    float f = s ? -probes[p] : probes[p];
                    uint16_t got = tl_half_from_float(f), ref = half_reference(f);
                    if (got != ref) {
                        if (wrong < 10) fprintf(stderr, "  %a: got 0x%04x, expected 0x%04x\n", (double)f, got, ref);
                        wrong++;
                    }
                    checked++;
                }
        }
    }
    printf("  %u boundary floats (each half, each midpoint, +-1 ULP, both signs): %u wrong\n", checked, wrong);
    TL_CHECK_EQ_U(wrong, 0);
}

/* 10^7 random floats: half of them any bit pattern, half with exponents inside the half range
 * (where rounding actually happens). */
TL_TEST(half_from_float_random_matches_reference)
{
    build_half_table();
    tl_rng rng = {0x4A1Fu};
    uint32_t wrong = 0, saturated = 0, denormal = 0;
    const uint32_t count = 10000000u;
    for (uint32_t i = 0; i < count; i++) {
        uint64_t r = tl_rng_u64(&rng);
        uint32_t u = (uint32_t)r;
        if (i & 1u) { /* exponent 100..143: 2^-27 .. 2^16 */
            uint32_t e = 100u + (uint32_t)((r >> 32) % 44u);
            u = (u & 0x807FFFFFu) | (e << 23);
        }
        float f = bits_float(u);
        uint16_t got = tl_half_from_float(f), ref = half_reference(f);
        if (got != ref) {
            if (wrong < 10) fprintf(stderr, "  0x%08x (%a): got 0x%04x, expected 0x%04x\n", u, (double)f, got, ref);
            wrong++;
        }
        saturated += (ref & 0x7FFFu) == 0x7BFFu;
        denormal += (ref & 0x7C00u) == 0 && (ref & 0x3FFu) != 0;
    }
    printf("  %u random floats: %u wrong (%u saturated, %u denormal results among them)\n", count, wrong, saturated,
           denormal);
    TL_CHECK_EQ_U(wrong, 0);
}

/* The header's saturating promises, spelled out. */
TL_TEST(half_saturation_nan_inf_and_signed_zero)
{
    build_half_table();
    static const struct { float f; uint16_t h; } cases[] = {
        {65504.0f, 0x7BFFu},       {65519.99609375f, 0x7BFFu}, {65520.0f, 0x7BFFu}, {65536.0f, 0x7BFFu},
        {1e10f, 0x7BFFu},          {FLT_MAX, 0x7BFFu},         {INFINITY, 0x7BFFu}, {-65504.0f, 0xFBFFu},
        {-65520.0f, 0xFBFFu},      {-FLT_MAX, 0xFBFFu},        {-INFINITY, 0xFBFFu}, {0.0f, 0x0000u},
        {-0.0f, 0x8000u},          {-1e-30f, 0x8000u},         {-FLT_TRUE_MIN, 0x8000u}, {1.0f, 0x3C00u},
        {0x1.0p-24f, 0x0001u},     {0x1.0p-25f, 0x0000u},      {0x1.000002p-25f, 0x0001u}, {0x1.8p-24f, 0x0002u},
        {0x1.0p-14f, 0x0400u},     {0x1.ffcp-15f, 0x0400u},    {0x1.ff8p-15f, 0x03FFu},
        {0x1.002p+0f, 0x3C00u},    {0x1.006p+0f, 0x3C02u},     {2049.0f, 0x6800u}, {2051.0f, 0x6802u},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        uint16_t got = tl_half_from_float(cases[i].f);
        if (got != cases[i].h)
            fprintf(stderr, "  %a: got 0x%04x, expected 0x%04x\n", (double)cases[i].f, got, cases[i].h);
        TL_CHECK_EQ_U(got, cases[i].h);
        TL_CHECK_EQ_U(half_reference(cases[i].f), cases[i].h); /* the reference agrees with IEEE */
    }
    const uint32_t nans[] = {0x7FC00000u, 0xFFC00000u, 0x7F800001u, 0xFFFFFFFFu, 0x7FBFFFFFu};
    for (size_t i = 0; i < sizeof nans / sizeof nans[0]; i++) TL_CHECK_EQ_U(tl_half_from_float(bits_float(nans[i])), 0);
    /* the largest float below the saturation threshold rounds to 65504 like everything above */
    TL_CHECK_EQ_U(float_bits(65520.0f), 0x477FF000u);
    TL_CHECK_EQ_U(tl_half_from_float(bits_float(0x477FEFFFu)), 0x7BFFu);
    /* no half ever decodes to a value that re-encodes as Inf or NaN */
    printf("  %zu spelled-out cases: saturation at 65520, Inf -> +-65504, NaN -> +0, -0 keeps its sign\n",
           sizeof cases / sizeof cases[0]);
}

/* ---------------------------------------------------------------------------------------------
 * Gloss
 * ------------------------------------------------------------------------------------------- */

#define GLOSS_SWEEP (1u << 20)
/* Worst |decode(encode(g)) - g| in steps of a `max`-code grid: half a step, plus the float
 * rounding of g and of the decoded k / max (2^-24 relative each, i.e. up to max 2^-24 steps). */
#define HALF_STEP(max) (0.5 + 2.0 * (double)(max) * 0x1.0p-24)

TL_TEST(gloss_power_endpoints_and_monotonic)
{
    TL_CHECK(tl_gloss_to_specular_power(0.0f) == TL_GLOSS_MIN_POWER);
    TL_CHECK(tl_gloss_to_specular_power(1.0f) == TL_GLOSS_MAX_POWER);
    TL_CHECK(tl_gloss_to_specular_power(0.0f) == 2.0f && tl_gloss_to_specular_power(1.0f) == 4096.0f);
    float prev_p = 0.0f, prev_a = INFINITY;
    uint32_t not_increasing = 0, not_decreasing = 0;
    double worst_rel = 0.0, worst_alpha_rel = 0.0;
    for (uint32_t k = 0; k <= GLOSS_SWEEP; k++) {
        float g = (float)k / (float)GLOSS_SWEEP;
        float p = tl_gloss_to_specular_power(g), a = tl_gloss_to_ggx_alpha(g);
        if (k > 0 && !(p > prev_p)) not_increasing++;
        /* alpha: strictly decreasing down to its floor TL_GGX_MIN_ALPHA, constant after it */
        if (k > 0 && !(a < prev_a) && !(a == TL_GGX_MIN_ALPHA && prev_a == TL_GGX_MIN_ALPHA)) not_decreasing++;
        prev_p = p;
        prev_a = a;
        double ref = exp2(1.0 + 11.0 * (double)g), ref_a = fmax((1.0 - g) * (1.0 - g), TL_GGX_MIN_ALPHA);
        double rel = fabs(p - ref) / ref, rel_a = fabs(a - ref_a) / ref_a;
        if (rel > worst_rel) worst_rel = rel;
        if (rel_a > worst_alpha_rel) worst_alpha_rel = rel_a;
    }
    printf("  %u gloss steps: power not strictly increasing %u times, alpha not strictly decreasing %u times\n",
           GLOSS_SWEEP, not_increasing, not_decreasing);
    printf("  power vs double 2^(1 + 11 g): max relative error %.3g; alpha vs double: %.3g\n", worst_rel,
           worst_alpha_rel);
    /* per step (2^-20 in gloss) the power moves by 11 ln2 2^-20 ~ 7e-6 relative and alpha
     * (1 - g)^2 by 2 * 2^-20 / (1 - g) >= 2^-19 relative: both far above a float ULP (2^-23) */
    TL_CHECK_EQ_U(not_increasing, 0);
    TL_CHECK_EQ_U(not_decreasing, 0);
    /* 11 g rounds (2^-24 relative of up to 12, i.e. ~8 ULP of the exponent) then exp2f */
    TL_CHECK_LE(worst_rel, 16.0 * 0x1.0p-24 * 11.0 * log(2.0) + 4.0 * 0x1.0p-24);
    /* 1 - g is exact (Sterbenz for g >= 1/2; one rounding below), then one product: 2 ULP */
    TL_CHECK_LE(worst_alpha_rel, 2.0 * 0x1.0p-24 * 2.0);
    prev_a = INFINITY;
    for (uint32_t k = 0; k <= GLOSS_SWEEP; k += 64) {
        float a = tl_gloss_to_ggx_alpha((float)k / (float)GLOSS_SWEEP);
        TL_CHECK(a <= prev_a);
        prev_a = a;
    }
}

TL_TEST(gloss_power_and_alpha_round_trips)
{
    double worst_pg = 0.0, worst_ag = 0.0, worst_gp = 0.0, worst_ga = 0.0;
    for (uint32_t k = 0; k <= GLOSS_SWEEP; k++) {
        float g = (float)k / (float)GLOSS_SWEEP;
        double e1 = fabs(tl_specular_power_to_gloss(tl_gloss_to_specular_power(g)) - g);
        /* gloss -> alpha is one-to-one only above the alpha floor, i.e. g <= 1 - sqrt(floor) */
        double e2 = g <= 1.0 - sqrt(TL_GGX_MIN_ALPHA) ? fabs(tl_ggx_alpha_to_gloss(tl_gloss_to_ggx_alpha(g)) - g) : 0.0;
        if (e1 > worst_gp) worst_gp = e1;
        if (e2 > worst_ga) worst_ga = e2;
        /* the other direction: power log-uniform in [2, 4096], alpha over its range */
        float p = (float)exp2(1.0 + 11.0 * (double)k / GLOSS_SWEEP);
        float pb = tl_gloss_to_specular_power(tl_specular_power_to_gloss(p));
        double e3 = fabs((double)pb - p) / p;
        if (e3 > worst_pg) worst_pg = e3;
        float a = (float)(TL_GGX_MIN_ALPHA + (1.0 - TL_GGX_MIN_ALPHA) * k / GLOSS_SWEEP);
        float ab = tl_gloss_to_ggx_alpha(tl_ggx_alpha_to_gloss(a));
        double e4 = fabs((double)ab - a) / a;
        if (e4 > worst_ag) worst_ag = e4;
    }
    printf("  gloss->power->gloss max |err| %.3g, gloss->alpha->gloss %.3g\n", worst_gp, worst_ga);
    printf("  power->gloss->power max rel err %.3g, alpha->gloss->alpha %.3g\n", worst_pg, worst_ag);
    TL_CHECK_LE(worst_gp, 1e-5);
    TL_CHECK_LE(worst_ga, 1e-5);
    TL_CHECK_LE(worst_pg, 1e-5);
    TL_CHECK_LE(worst_ag, 1e-5);
}

TL_TEST(gloss_bad_inputs_clamp)
{
    const float lo[] = {NAN, -NAN, -1.0f, -INFINITY, -FLT_MIN, -0.0f};
    const float hi[] = {1.0f, 1.5f, 1e30f, INFINITY};
    for (size_t i = 0; i < sizeof lo / sizeof lo[0]; i++) {
        TL_CHECK(tl_gloss_to_specular_power(lo[i]) == 2.0f);
        TL_CHECK(tl_gloss_to_ggx_alpha(lo[i]) == tl_gloss_to_ggx_alpha(0.0f));
        TL_CHECK_EQ_U(tl_gloss_encode(lo[i], 8), 0);
    }
    for (size_t i = 0; i < sizeof hi / sizeof hi[0]; i++) {
        TL_CHECK(tl_gloss_to_specular_power(hi[i]) == 4096.0f);
        TL_CHECK(tl_gloss_to_ggx_alpha(hi[i]) == tl_gloss_to_ggx_alpha(1.0f));
        TL_CHECK_EQ_U(tl_gloss_encode(hi[i], 8), 255);
        TL_CHECK_EQ_U(tl_gloss_encode(hi[i], 10), 1023);
    }
    /* power outside [2, 4096] clamps; NaN counts as the lowest */
    TL_CHECK(tl_specular_power_to_gloss(NAN) == 0.0f);
    TL_CHECK(tl_specular_power_to_gloss(0.0f) == 0.0f);
    TL_CHECK(tl_specular_power_to_gloss(-5.0f) == 0.0f);
    TL_CHECK(tl_specular_power_to_gloss(1e9f) == 1.0f);
    TL_CHECK(tl_specular_power_to_gloss(INFINITY) == 1.0f);
    TL_CHECK(tl_specular_power_to_gloss(2.0f) == 0.0f);
    TL_CHECK(tl_specular_power_to_gloss(4096.0f) == 1.0f);
    /* alpha: NaN and <= 0 are the smoothest, >= 1 the roughest; gloss 0 is alpha 1, gloss >= 1 -
     * sqrt(floor) the floor */
    TL_CHECK(tl_ggx_alpha_to_gloss(NAN) == 1.0f);
    TL_CHECK(tl_ggx_alpha_to_gloss(0.0f) == 1.0f);
    TL_CHECK(tl_ggx_alpha_to_gloss(-1.0f) == 1.0f);
    TL_CHECK(tl_ggx_alpha_to_gloss(1.0f) == 0.0f);
    TL_CHECK(tl_ggx_alpha_to_gloss(INFINITY) == 0.0f);
    TL_CHECK(tl_ggx_alpha_to_gloss(1e-30f) == 1.0f);
    TL_CHECK(tl_gloss_to_ggx_alpha(0.0f) == 1.0f);
    TL_CHECK(tl_gloss_to_ggx_alpha(1.0f) == TL_GGX_MIN_ALPHA);
    TL_CHECK(tl_gloss_to_ggx_alpha(0.95f) == TL_GGX_MIN_ALPHA);
    TL_CHECK(tl_gloss_to_ggx_alpha(0.5f) == 0.25f);
    TL_CHECK(tl_ggx_alpha_to_gloss(0.25f) == 0.5f);
    /* out-of-range bit counts clamp to 1..16, codes beyond the maximum decode as the maximum */
    TL_CHECK_EQ_U(tl_gloss_encode(1.0f, 0), 1);
    TL_CHECK_EQ_U(tl_gloss_encode(1.0f, 40), 65535);
    TL_CHECK(tl_gloss_decode(300, 8) == 1.0f);
    TL_CHECK(tl_gloss_decode(0xFFFFFFFFu, 10) == 1.0f);
    TL_CHECK(isfinite(tl_gloss_decode(5, 0)));
    printf("  NaN/negative gloss -> power 2, gloss >= 1 -> 4096; power and alpha outside range clamp\n");
}

static void check_gloss_codes(uint32_t bits, uint32_t *worst_code_err, double *worst_value_err)
{
    uint32_t max = (1u << bits) - 1u;
    for (uint32_t k = 0; k <= max; k++) {
        float g = tl_gloss_decode(k, bits);
        TL_CHECK(g == (float)((double)k / max) || fabs(g - (double)k / max) <= 0x1.0p-24);
        uint32_t back = tl_gloss_encode(g, bits);
        uint32_t d = back > k ? back - k : k - back;
        if (d > *worst_code_err) *worst_code_err = d;
        TL_CHECK(tl_gloss_decode(back, bits) == g);
    }
    /* any gloss: decode(encode(g)) within half a step */
    for (uint32_t k = 0; k <= GLOSS_SWEEP; k += 7) {
        float g = (float)k / (float)GLOSS_SWEEP;
        double e = fabs((double)tl_gloss_decode(tl_gloss_encode(g, bits), bits) - g) * max;
        if (e > *worst_value_err) *worst_value_err = e;
    }
}

TL_TEST(gloss8_exhaustive_encode_decode)
{
    uint32_t wc = 0;
    double wv = 0.0;
    check_gloss_codes(8, &wc, &wv);
    printf("  gloss8: all 256 codes, encode(decode(k)) off by at most %u; decode(encode(g)) within %.6f steps\n", wc, wv);
    TL_CHECK_EQ_U(wc, 0);
    TL_CHECK_LE(wv, HALF_STEP(TL_UNORM_MAX(8)));
}

TL_TEST(gloss10_exhaustive_encode_decode)
{
    uint32_t wc = 0;
    double wv = 0.0;
    check_gloss_codes(10, &wc, &wv);
    printf("  gloss10: all 1024 codes, encode(decode(k)) off by at most %u; decode(encode(g)) within %.6f steps\n", wc,
           wv);
    TL_CHECK_EQ_U(wc, 0);
    TL_CHECK_LE(wv, HALF_STEP(TL_UNORM_MAX(10)));
}

TL_TEST(gloss_all_bits_1_to_16_exhaustive)
{
    uint32_t wc = 0;
    double wv = 0.0;
    for (uint32_t bits = 1; bits <= 16; bits++) check_gloss_codes(bits, &wc, &wv);
    printf("  gloss 1..16 bits: all codes round-trip (worst %u), decode(encode(g)) within %.6f steps\n", wc, wv);
    TL_CHECK_EQ_U(wc, 0);
    TL_CHECK_LE(wv, HALF_STEP(TL_UNORM_MAX(16)));
}

/* ---------------------------------------------------------------------------------------------
 * RT0
 * ------------------------------------------------------------------------------------------- */

#define RT0_COUNT 1000000u

TL_TEST(rt0_rgba8_matches_oct12_precise_and_gloss8)
{
    tl_rng rng = {0x27A8u};
    uint32_t normal_mismatch = 0;
    double worst_gloss = 0.0;
    for (uint32_t i = 0; i < RT0_COUNT; i++) {
        float n[3], d[3], ref[3], g = (float)tl_rng_unit(&rng), gd = -1.0f;
        tl_rng_direction(&rng, n);
        uint8_t t[4];
        tl_rt0_encode_rgba8(n, g, t);
        tl_rt0_decode_rgba8(t, d, &gd);
        tl_oct_decode(tl_oct_encode_precise(n, 12), 12, ref);
        if (memcmp(d, ref, sizeof d) != 0) normal_mismatch++;
        double e = fabs((double)gd - g) * TL_UNORM_MAX(8); /* in gloss8 steps */
        if (e > worst_gloss) worst_gloss = e;
    }
    printf("  RT0 RGBA8, %u normals: %u decoded normals differ from oct12 precise; gloss error max %.6f steps\n",
           RT0_COUNT, normal_mismatch, worst_gloss);
    TL_CHECK_EQ_U(normal_mismatch, 0);
    TL_CHECK_LE(worst_gloss, HALF_STEP(TL_UNORM_MAX(8)));
    /* NULL gloss pointer accepted */
    float d[3];
    const uint8_t t[4] = {1, 2, 3, 4};
    tl_rt0_decode_rgba8(t, d, NULL);
    TL_CHECK(isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2]));
}

TL_TEST(rt0_rgba8_batch_matches_scalar)
{
    const size_t count = 100003;
    float *n = malloc(3 * count * sizeof *n), *g = malloc(count * sizeof *g), *d = malloc(3 * count * sizeof *d),
          *gd = malloc(count * sizeof *gd);
    uint8_t *t = malloc(4 * count);
    TL_CHECK(n && g && d && gd && t);
    if (!(n && g && d && gd && t)) return;
    tl_rng rng = {0x27A9u};
    for (size_t i = 0; i < count; i++) {
        tl_rng_direction(&rng, n + 3 * i);
        g[i] = (float)(1.2 * tl_rng_unit(&rng) - 0.1);
    }
    n[0] = NAN;
    g[1] = NAN;
    tl_rt0_encode_rgba8_n(n, g, t, count);
    tl_rt0_decode_rgba8_n(t, d, gd, count);
    uint32_t mismatch = 0;
    for (size_t i = 0; i < count; i++) {
        uint8_t s[4];
        float sd[3], sg;
        tl_rt0_encode_rgba8(n + 3 * i, g[i], s);
        tl_rt0_decode_rgba8(s, sd, &sg);
        if (memcmp(s, t + 4 * i, 4) != 0 || memcmp(sd, d + 3 * i, sizeof sd) != 0 || memcmp(&sg, gd + i, sizeof sg) != 0)
            mismatch++;
    }
    /* NULL gloss array: gloss 0 */
    tl_rt0_encode_rgba8_n(n, NULL, t, 4);
    for (size_t i = 0; i < 4; i++) TL_CHECK_EQ_U(t[4 * i + 3], 0);
    printf("  RT0 RGBA8 batch vs scalar, %zu texels: %u mismatches\n", count, mismatch);
    TL_CHECK_EQ_U(mismatch, 0);
    free(n);
    free(g);
    free(d);
    free(gd);
    free(t);
}

/* R = u[11:4], G = v[11:4], B = u[3:0] << 4 | v[3:0], A = gloss8: built by hand from a code. */
TL_TEST(rt0_rgba8_byte_layout)
{
    const uint32_t u = 0xABCu, v = 0x123u, code = u | (v << 12);
    float n[3];
    tl_oct_decode(code, 12, n);
    TL_CHECK_EQ_U(tl_oct_encode_precise(n, 12), code); /* n really is that code's direction */
    uint8_t t[4];
    tl_rt0_encode_rgba8(n, 200.0f / 255.0f, t);
    printf("  code u=0x%03x v=0x%03x gloss 200 -> bytes %02x %02x %02x %02x\n", u, v, t[0], t[1], t[2], t[3]);
    TL_CHECK_EQ_U(t[0], 0xAB);
    TL_CHECK_EQ_U(t[1], 0x12);
    TL_CHECK_EQ_U(t[2], 0xC3);
    TL_CHECK_EQ_U(t[3], 200);
    const uint8_t hand[4] = {0xAB, 0x12, 0xC3, 200};
    float d[3], g;
    tl_rt0_decode_rgba8(hand, d, &g);
    TL_CHECK(memcmp(d, n, sizeof d) == 0);
    TL_CHECK(g == 200.0f / 255.0f);
    /* corners of the byte space decode to finite unit vectors */
    for (uint32_t b = 0; b < 256; b++) {
        const uint8_t c[4] = {(uint8_t)b, (uint8_t)(255 - b), (uint8_t)(b * 7), (uint8_t)b};
        tl_rt0_decode_rgba8(c, d, &g);
        TL_CHECK(isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2]) && g >= 0.0f && g <= 1.0f);
    }
}

TL_TEST(rt0_rgb10a2_matches_oct10_precise_gloss10_flags)
{
    tl_rng rng = {0x10A2u};
    uint32_t normal_mismatch = 0, flag_mismatch = 0;
    double worst_gloss = 0.0;
    for (uint32_t i = 0; i < RT0_COUNT; i++) {
        float n[3], d[3], ref[3], g = (float)tl_rng_unit(&rng), gd = -1.0f;
        tl_rng_direction(&rng, n);
        uint32_t flags = (uint32_t)tl_rng_u64(&rng), fd = 99;
        uint32_t t = tl_rt0_encode_rgb10a2(n, g, flags);
        tl_rt0_decode_rgb10a2(t, d, &gd, &fd);
        tl_oct_decode(tl_oct_encode_precise(n, 10), 10, ref);
        if (memcmp(d, ref, sizeof d) != 0) normal_mismatch++;
        if (fd != (flags & 3u)) flag_mismatch++;
        double e = fabs((double)gd - g) * TL_UNORM_MAX(10); /* in gloss10 steps */
        if (e > worst_gloss) worst_gloss = e;
    }
    printf("  RT0 RGB10A2, %u normals: %u normal mismatches vs oct10 precise, %u flag mismatches, gloss max %.6f steps\n",
           RT0_COUNT, normal_mismatch, flag_mismatch, worst_gloss);
    TL_CHECK_EQ_U(normal_mismatch, 0);
    TL_CHECK_EQ_U(flag_mismatch, 0);
    TL_CHECK_LE(worst_gloss, HALF_STEP(TL_UNORM_MAX(10)));
    float d[3];
    tl_rt0_decode_rgb10a2(0xFFFFFFFFu, d, NULL, NULL);
    TL_CHECK(isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2]));
}

/* bits 0-9 u, 10-19 v, 20-29 gloss10, 30-31 flags: built by hand. */
TL_TEST(rt0_rgb10a2_bit_layout)
{
    const uint32_t u = 0x2A5u, v = 0x15Au, gcode = 0x3C3u;
    float n[3];
    tl_oct_decode(u | (v << 10), 10, n);
    TL_CHECK_EQ_U(tl_oct_encode_precise(n, 10), u | (v << 10));
    for (uint32_t flags = 0; flags < 4; flags++) {
        uint32_t t = tl_rt0_encode_rgb10a2(n, (float)gcode / 1023.0f, flags);
        uint32_t expect = u | (v << 10) | (gcode << 20) | (flags << 30);
        TL_CHECK_EQ_U(t, expect);
        float d[3], g;
        uint32_t f;
        tl_rt0_decode_rgb10a2(expect, d, &g, &f);
        TL_CHECK(memcmp(d, n, sizeof d) == 0);
        TL_CHECK(g == (float)gcode / 1023.0f);
        TL_CHECK_EQ_U(f, flags);
        if (flags == 2) printf("  u=0x%03x v=0x%03x gloss=0x%03x flags=2 -> 0x%08x\n", u, v, gcode, t);
    }
    TL_CHECK_EQ_U(tl_rt0_encode_rgb10a2(n, 0.0f, 7u) >> 30, 3u); /* only 2 flag bits are kept */
}

TL_TEST(rt0_extreme_inputs_finite)
{
    const float in[][3] = {{NAN, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {INFINITY, -INFINITY, 0.0f}, {0.0f, 0.0f, -1.0f},
                           {1e-40f, 0.0f, 0.0f}, {FLT_MAX, FLT_MAX, FLT_MAX}};
    const float gl[] = {NAN, -1.0f, 2.0f, INFINITY, 0.5f, -INFINITY};
    for (size_t i = 0; i < sizeof in / sizeof in[0]; i++)
        for (size_t j = 0; j < sizeof gl / sizeof gl[0]; j++) {
            uint8_t t[4];
            float d[3], g;
            uint32_t f;
            tl_rt0_encode_rgba8(in[i], gl[j], t);
            tl_rt0_decode_rgba8(t, d, &g);
            TL_CHECK(isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2]) && g >= 0.0f && g <= 1.0f);
            tl_rt0_decode_rgb10a2(tl_rt0_encode_rgb10a2(in[i], gl[j], 1u), d, &g, &f);
            TL_CHECK(isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2]) && g >= 0.0f && g <= 1.0f && f == 1u);
        }
    printf("  %zu (normal, gloss) extreme pairs through both layouts: finite normals, gloss in [0, 1]\n",
           (sizeof in / sizeof in[0]) * (sizeof gl / sizeof gl[0]));
}
