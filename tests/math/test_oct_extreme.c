/* Octahedral encoding: the extreme and stiff cases of docs/stability.md, one case each.
 * Error bounds per bit budget are the random-input worst cases asserted in test_oct.c, which
 * halve with every bit: 0.96 deg at 8 bits (0.06 deg at 12). */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "thinlight/codec.h"
#include "thinlight/metrics.h"
#include "tl_test.h"

static double bound_deg(uint32_t bits) { return 0.96 / (double)(1u << (bits - 8u)); }

/* The top component code of the odd grid (codec.h): codes 0..top. */
static uint32_t oct_top(uint32_t bits) { return (1u << bits) - 2u; }

static uint32_t comp_u(uint32_t code, uint32_t bits) { return code & ((1u << bits) - 1u); }
static uint32_t comp_v(uint32_t code, uint32_t bits) { return code >> bits; }
static uint32_t absdiff(uint32_t a, uint32_t b) { return a > b ? a - b : b - a; }

/* Codes within one step per component (the same direction reached through float rounding). */
static int codes_near(uint32_t a, uint32_t b, uint32_t bits)
{
    return absdiff(comp_u(a, bits), comp_u(b, bits)) <= 1u && absdiff(comp_v(a, bits), comp_v(b, bits)) <= 1u;
}

static double unit_error(const float v[3])
{
    return fabs(sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]) - 1.0);
}

/* Decoded output of any code: finite, unit within 1e-6. */
static int decoded_ok(const float d[3]) { return isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2]) && unit_error(d) <= 1e-6; }

typedef uint32_t (*encode_fn)(const float n[3], uint32_t bits);
static const encode_fn encoders[2] = {tl_oct_encode, tl_oct_encode_precise};
static const char *const encoder_names[2] = {"plain", "precise"};

/* Encodes `in` with both encoders at every budget; the code must decode to `expect` (a unit
 * direction) within the budget's error, with finite unit output. Returns the worst error. */
static double check_direction(const char *what, const float in[3], const float expect[3])
{
    double worst = 0.0;
    for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++)
        for (int p = 0; p < 2; p++) {
            uint32_t code = encoders[p](in, bits);
            float d[3];
            tl_oct_decode(code, bits, d);
            double err = tl_angle_deg(expect, d);
            if (err > worst && bits == 12) worst = err;
            int ok = (uint64_t)code < (1ull << (2 * bits)) && decoded_ok(d) && err <= bound_deg(bits);
            if (!ok)
                fprintf(stderr, "  %s, oct%u %s: in (%a, %a, %a) code 0x%x -> (%a, %a, %a), %.6g deg (bound %.6g)\n",
                        what, bits, encoder_names[p], in[0], in[1], in[2], code, d[0], d[1], d[2], err,
                        bound_deg(bits));
            TL_CHECK(ok);
        }
    return worst;
}

/* ---------------------------------------------------------------------------------------------
 * Poles
 * ------------------------------------------------------------------------------------------- */

TL_TEST(oct_pole_positive_z_round_trip)
{
    const float pz[3] = {0.0f, 0.0f, 1.0f}, pz_neg0[3] = {-0.0f, -0.0f, 1.0f};
    double e1 = check_direction("+Z", pz, pz), e2 = check_direction("+Z with -0 x, y", pz_neg0, pz);
    printf("  +Z at 12 bits: error %.6g deg, with -0 components %.6g deg (bound %.6g)\n", e1, e2, bound_deg(12));
    /* +Z is the square's centre, a code of the odd grid: it decodes exactly, +-0 inputs alike */
    for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++)
        for (int p = 0; p < 2; p++) {
            float d[3], d0[3];
            tl_oct_decode(encoders[p](pz, bits), bits, d);
            tl_oct_decode(encoders[p](pz_neg0, bits), bits, d0);
            TL_CHECK(d[0] == 0.0f && d[1] == 0.0f && d[2] == 1.0f);
            TL_CHECK(d0[0] == 0.0f && d0[1] == 0.0f && d0[2] == 1.0f);
        }
    TL_CHECK(e1 == 0.0 && e2 == 0.0);
}

TL_TEST(oct_pole_negative_z_decodes_to_negative_z)
{
    const float mz[4][3] = {{0.0f, 0.0f, -1.0f}, {-0.0f, 0.0f, -1.0f}, {0.0f, -0.0f, -1.0f}, {-0.0f, -0.0f, -1.0f}};
    const float expect[3] = {0.0f, 0.0f, -1.0f};
    for (int i = 0; i < 4; i++) {
        check_direction("-Z", mz[i], expect);
        /* -Z sits on a corner of the square, which every budget represents exactly */
        for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++)
            for (int p = 0; p < 2; p++) {
                float d[3];
                uint32_t code = encoders[p](mz[i], bits), top = oct_top(bits);
                tl_oct_decode(code, bits, d);
                TL_CHECK(d[0] == 0.0f && d[1] == 0.0f && d[2] == -1.0f);
                /* each sign combination has its own corner: the sign bit picks it */
                TL_CHECK_EQ_U(comp_u(code, bits), signbit(mz[i][0]) ? 0u : top);
                TL_CHECK_EQ_U(comp_v(code, bits), signbit(mz[i][1]) ? 0u : top);
            }
    }
    printf("  (+-0, +-0, -1) -> the four corners, each decoding to exactly (0, 0, -1) at 8..16 bits\n");
}

/* The same fold with GLSL's sign() (0 for 0): (0,0,-1) lands on the centre, i.e. +Z. */
static uint32_t naive_sign_encode12(const float n[3])
{
    float l1 = fabsf(n[0]) + fabsf(n[1]) + fabsf(n[2]);
    float u = n[0] / l1, v = n[1] / l1;
    if (n[2] < 0.0f) {
        float su = u > 0.0f ? 1.0f : u < 0.0f ? -1.0f : 0.0f, sv = v > 0.0f ? 1.0f : v < 0.0f ? -1.0f : 0.0f;
        float fu = (1.0f - fabsf(v)) * su, fv = (1.0f - fabsf(u)) * sv;
        u = fu;
        v = fv;
    }
    uint32_t qu = (uint32_t)((u + 1.0f) * 2047.0f + 0.5f), qv = (uint32_t)((v + 1.0f) * 2047.0f + 0.5f);
    return qu | (qv << 12);
}

TL_TEST(oct12_negative_z_needs_sign_not_zero)
{
    const float mz[3] = {0.0f, 0.0f, -1.0f};
    float d[3], naive[3];
    tl_oct_decode(tl_oct_encode(mz, 12), 12, d);
    tl_oct_decode(naive_sign_encode12(mz), 12, naive);
    printf("  (0,0,-1): sign-not-zero decodes to z = %.9g; plain sign() would give z = %.9g\n", d[2], naive[2]);
    TL_CHECK(d[2] < -0.999f);
    TL_CHECK(naive[2] > 0.999f); /* shows what the sign bit saves us from */
    float dp[3];
    tl_oct_decode(tl_oct_encode_precise(mz, 12), 12, dp);
    TL_CHECK(dp[2] < -0.999f);
}

/* ---------------------------------------------------------------------------------------------
 * The fold: equator |x| + |y| = 1 (in L1 terms), z = +0 and z = -0, and a ULP off it
 * ------------------------------------------------------------------------------------------- */

#define EQUATOR_STEPS 20000u

/* Equator direction k of EQUATOR_STEPS, plus the exact axes and diagonals. */
static void equator(uint32_t k, float v[3])
{
    double t = 2.0 * 3.14159265358979323846 * k / EQUATOR_STEPS;
    v[0] = (float)cos(t);
    v[1] = (float)sin(t);
    v[2] = 0.0f;
    if (k % (EQUATOR_STEPS / 4) == 0) { /* exact axes, with both signs of zero */
        uint32_t q = k / (EQUATOR_STEPS / 4);
        v[0] = q == 0 ? 1.0f : q == 2 ? -1.0f : (q == 1 ? 0.0f : -0.0f);
        v[1] = q == 1 ? 1.0f : q == 3 ? -1.0f : (q == 0 ? 0.0f : -0.0f);
    }
}

static void check_fold(float z_on_fold, uint32_t bits)
{
    size_t same = 0, near = 0, total = 0;
    double worst = 0.0;
    for (uint32_t k = 0; k < EQUATOR_STEPS; k++) {
        float v[3], ref[3];
        equator(k, v);
        memcpy(ref, v, sizeof ref);
        v[2] = z_on_fold;
        for (int p = 0; p < 2; p++) {
            uint32_t code = encoders[p](v, bits), code_ref = encoders[p](ref, bits);
            float d[3];
            tl_oct_decode(code, bits, d);
            double err = tl_angle_deg(v, d);
            if (err > worst) worst = err;
            TL_CHECK(decoded_ok(d));
            TL_CHECK_LE(err, bound_deg(bits));
            TL_CHECK_LE(fabs(d[2]), sin(bound_deg(bits) * 3.14159265358979323846 / 180.0));
            same += code == code_ref;
            near += codes_near(code, code_ref, bits);
            total++;
        }
    }
    printf("  oct%u z = %s0: max error %.6g deg (bound %.6g); codes equal to z = +0: %zu/%zu, within 1: %zu\n", bits,
           signbit(z_on_fold) ? "-" : "+", worst, bound_deg(bits), same, total, near);
    TL_CHECK_EQ_U(near, total);
}

TL_TEST(oct12_fold_edge_positive_zero)
{
    for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits += 2) check_fold(0.0f, bits);
}

TL_TEST(oct12_fold_edge_negative_zero)
{
    for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits += 2) check_fold(-0.0f, bits);
}

/* One ULP (and a few other tiny steps) off the fold on either side: z = +-FLT_TRUE_MIN,
 * +-FLT_MIN, +-2^-24, and x nudged by one ULP, must land on the fold's code or its neighbour. */
TL_TEST(oct12_fold_one_ulp_off)
{
    const float dz[] = {FLT_TRUE_MIN, -FLT_TRUE_MIN, FLT_MIN, -FLT_MIN, 0x1.0p-24f, -0x1.0p-24f};
    const uint32_t budgets[] = {8, 12, 16};
    for (size_t bi = 0; bi < 3; bi++) {
        uint32_t bits = budgets[bi];
        size_t total = 0, near = 0;
        double worst = 0.0;
        for (uint32_t k = 0; k < EQUATOR_STEPS; k += 3) {
            float fold[3];
            equator(k, fold);
            for (size_t j = 0; j < sizeof dz / sizeof dz[0] + 2; j++) {
                float v[3];
                memcpy(v, fold, sizeof v);
                if (j < sizeof dz / sizeof dz[0]) v[2] = dz[j];
                else v[0] = nextafterf(v[0], j & 1u ? INFINITY : -INFINITY), v[2] = -0.0f;
                for (int p = 0; p < 2; p++) {
                    uint32_t code = encoders[p](v, bits), code_fold = encoders[p](fold, bits);
                    float d[3];
                    tl_oct_decode(code, bits, d);
                    double err = tl_angle_deg(v, d);
                    if (err > worst) worst = err;
                    TL_CHECK(decoded_ok(d));
                    TL_CHECK_LE(err, bound_deg(bits));
                    int ok = codes_near(code, code_fold, bits);
                    if (!ok)
                        fprintf(stderr, "  oct%u %s: (%a, %a, %a) -> 0x%x, on the fold 0x%x\n", bits, encoder_names[p],
                                v[0], v[1], v[2], code, code_fold);
                    near += ok;
                    total++;
                }
            }
        }
        printf("  oct%-2u 1 ULP off the fold: %zu inputs, max error %.6g deg (bound %.6g), within 1 code: %zu\n", bits,
               total, worst, bound_deg(bits), near);
        TL_CHECK_EQ_U(near, total);
    }
}

/* ---------------------------------------------------------------------------------------------
 * The square's outer boundary and corners: the mirrored edges must not swap codes
 * ------------------------------------------------------------------------------------------- */

TL_TEST(oct_square_edges_and_corners_round_trip)
{
    size_t total = 0, bad = 0;
    for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++) {
        uint32_t top = oct_top(bits);
        for (uint32_t k = 0; k <= top; k++) {
            const uint32_t edge[4][2] = {{0, k}, {top, k}, {k, 0}, {k, top}};
            for (int e = 0; e < 4; e++) {
                uint32_t code = edge[e][0] | (edge[e][1] << bits);
                float d[3];
                tl_oct_decode(code, bits, d);
                uint32_t a = tl_oct_encode(d, bits), b = tl_oct_encode_precise(d, bits);
                if (a != code || b != code || !decoded_ok(d)) {
                    if (bad < 8)
                        fprintf(stderr, "  oct%u edge code 0x%x -> (%a, %a, %a) -> plain 0x%x precise 0x%x\n", bits,
                                code, d[0], d[1], d[2], a, b);
                    bad++;
                }
                total++;
            }
        }
        /* the four corners are all -Z, told apart by the signs of the zero x and y */
        const uint32_t corners[4] = {0u, top, top << bits, top | (top << bits)};
        for (int c = 0; c < 4; c++) {
            float d[3];
            tl_oct_decode(corners[c], bits, d);
            TL_CHECK(d[0] == 0.0f && d[1] == 0.0f && d[2] == -1.0f);
            TL_CHECK(!signbit(d[0]) == (comp_u(corners[c], bits) == top));
            TL_CHECK(!signbit(d[1]) == (comp_v(corners[c], bits) == top));
        }
    }
    printf("  outer-boundary codes at 8..16 bits: %zu checked, %zu failed to round-trip\n", total, bad);
    TL_CHECK_EQ_U(bad, 0);
}

/* ---------------------------------------------------------------------------------------------
 * Non-unit, zero, denormal, Inf and NaN inputs
 * ------------------------------------------------------------------------------------------- */

/* Random directions scaled far from unit length: the code must be the unit vector's or a
 * neighbour (scaling rounds the components); exact powers of two must give the same code. */
TL_TEST(oct_non_unit_lengths_same_code)
{
    /* Far from unit length the input is rescaled first (rounding), so only "within 1 code" holds;
     * powers of two from 2^-30 to 2^30 leave every float operation exact up to scale. */
    const float scales[] = {1e-30f, 1e-20f, 1e-10f, 0.5f,        3.0f,        1e10f,      1e20f,
                            1e30f,  1e38f,  0x1.0p-120f, 0x1.0p-61f, 0x1.0p-59f, 0x1.0p-50f, 0x1.0p-40f,
                            0x1.0p40f, 0x1.0p59f, 0x1.0p61f, 0x1.0p120f};
    const float pow2[] = {0x1.0p-30f, 0x1.0p-20f, 0x1.0p-1f, 0x1.0p1f, 0x1.0p20f, 0x1.0p30f};
    const uint32_t budgets[] = {8, 12, 16};
    const size_t count = 20000;
    tl_rng rng = {0x5CA1Eu};
    size_t total = 0, equal = 0, near = 0, pow2_total = 0, pow2_equal = 0;
    for (size_t i = 0; i < count; i++) {
        float n[3];
        tl_rng_direction(&rng, n);
        for (size_t bi = 0; bi < 3; bi++)
            for (int p = 0; p < 2; p++) {
                uint32_t bits = budgets[bi], ref = encoders[p](n, bits);
                for (size_t s = 0; s < sizeof scales / sizeof scales[0]; s++) {
                    float v[3] = {n[0] * scales[s], n[1] * scales[s], n[2] * scales[s]};
                    uint32_t code = encoders[p](v, bits);
                    if (!codes_near(code, ref, bits))
                        fprintf(stderr, "  oct%u %s: (%a, %a, %a) * %a -> 0x%x, unit 0x%x\n", bits,
                                encoder_names[p], n[0], n[1], n[2], (double)scales[s], code, ref);
                    equal += code == ref;
                    near += codes_near(code, ref, bits);
                    total++;
                }
                for (size_t s = 0; s < sizeof pow2 / sizeof pow2[0]; s++) {
                    float v[3] = {n[0] * pow2[s], n[1] * pow2[s], n[2] * pow2[s]};
                    uint32_t code = encoders[p](v, bits);
                    if (code != ref && pow2_total - pow2_equal < 5)
                        fprintf(stderr, "  oct%u %s: (%a, %a, %a) * %a -> 0x%x, unit 0x%x\n", bits,
                                encoder_names[p], n[0], n[1], n[2], (double)pow2[s], code, ref);
                    pow2_equal += code == ref;
                    pow2_total++;
                }
            }
    }
    printf("  scaled inputs: %zu, same code %zu, within 1 code %zu\n", total, equal, near);
    printf("  exact power-of-two scalings 2^-30..2^30: %zu, same code %zu\n", pow2_total, pow2_equal);
    TL_CHECK_EQ_U(near, total);
    TL_CHECK_EQ_U(pow2_equal, pow2_total);
}

TL_TEST(oct_zero_vector_encodes_as_positive_z)
{
    const float zeros[4][3] = {{0.0f, 0.0f, 0.0f}, {-0.0f, -0.0f, -0.0f}, {0.0f, -0.0f, 0.0f}, {-0.0f, 0.0f, -0.0f}};
    const float pz[3] = {0.0f, 0.0f, 1.0f};
    for (int i = 0; i < 4; i++) {
        check_direction("zero vector", zeros[i], pz);
        for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++) {
            TL_CHECK_EQ_U(tl_oct_encode(zeros[i], bits), tl_oct_encode(pz, bits));
            TL_CHECK_EQ_U(tl_oct_encode_precise(zeros[i], bits), tl_oct_encode_precise(pz, bits));
        }
        float s[3];
        tl_normal_sanitize(zeros[i], s);
        TL_CHECK(s[0] == 0.0f && s[1] == 0.0f && s[2] == 1.0f);
    }
    printf("  all four signed zero vectors encode as +Z at 8..16 bits\n");
}

/* Denormal components are scaled up exactly, so the direction survives. */
TL_TEST(oct_denormal_components_keep_direction)
{
    static const struct { float in[3], dir[3]; int exact; } cases[] = {
        {{1e-40f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 1},
        {{FLT_TRUE_MIN, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 1},
        {{0.0f, -1e-40f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1},
        {{0.0f, 0.0f, -FLT_TRUE_MIN}, {0.0f, 0.0f, -1.0f}, 1},
        {{-0.0f, 0.0f, 3e-39f}, {-0.0f, 0.0f, 1.0f}, 1},
        {{1e-40f, 1e-40f, 0.0f}, {1.0f, 1.0f, 0.0f}, 0},
        {{1e-40f, -2e-40f, 2e-40f}, {1.0f, -2.0f, 2.0f}, 0},
        {{FLT_MIN, 0.0f, -FLT_MIN}, {1.0f, 0.0f, -1.0f}, 0},
        {{1.0f, 1e-40f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0}, /* a usable vector with a denormal part */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const float *in = cases[i].in, *dir = cases[i].dir;
        float unit[3];
        tl_normal_sanitize(dir, unit);
        check_direction("denormal", in, unit);
        for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++)
            for (int p = 0; p < 2; p++) {
                uint32_t code = encoders[p](in, bits), ref = encoders[p](dir, bits);
                if (cases[i].exact) TL_CHECK_EQ_U(code, ref);
                else TL_CHECK(codes_near(code, ref, bits));
            }
    }
    printf("  (1e-40, 0, 0) encodes exactly as +X; %zu denormal inputs checked at 8..16 bits\n",
           sizeof cases / sizeof cases[0]);
}

/* Infinite components become +-1, the finite ones 0. */
TL_TEST(oct_inf_components_give_their_direction)
{
    static const struct { float in[3], dir[3]; } cases[] = {
        {{INFINITY, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}},
        {{-INFINITY, 5.0f, -3.0f}, {-1.0f, 0.0f, 0.0f}},
        {{0.0f, 0.0f, -INFINITY}, {0.0f, 0.0f, -1.0f}},
        {{INFINITY, -INFINITY, 0.25f}, {1.0f, -1.0f, 0.0f}},
        {{INFINITY, INFINITY, INFINITY}, {1.0f, 1.0f, 1.0f}},
        {{-INFINITY, -INFINITY, -INFINITY}, {-1.0f, -1.0f, -1.0f}},
        {{FLT_MAX, INFINITY, FLT_MAX}, {0.0f, 1.0f, 0.0f}},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        float unit[3];
        tl_normal_sanitize(cases[i].dir, unit);
        check_direction("inf", cases[i].in, unit);
        for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++)
            for (int p = 0; p < 2; p++)
                TL_CHECK(codes_near(encoders[p](cases[i].in, bits), encoders[p](cases[i].dir, bits), bits));
    }
    printf("  %zu inputs with infinite components checked at 8..16 bits\n", sizeof cases / sizeof cases[0]);
}

/* NaN anywhere gives +Z (header: tl_normal_sanitize). */
TL_TEST(oct_nan_components_give_positive_z)
{
    const float qnan = NAN, nnan = -NAN;
    const float in[][3] = {
        {qnan, 0.0f, 0.0f}, {0.0f, qnan, 0.0f}, {0.0f, 0.0f, qnan}, {qnan, qnan, qnan}, {nnan, -1.0f, 0.0f},
        {1.0f, 0.0f, nnan}, {INFINITY, qnan, 0.0f}, {0.0f, 0.0f, -1.0f},
    };
    const float pz[3] = {0.0f, 0.0f, 1.0f};
    for (size_t i = 0; i + 1 < sizeof in / sizeof in[0]; i++) {
        check_direction("nan", in[i], pz);
        for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++) {
            TL_CHECK_EQ_U(tl_oct_encode(in[i], bits), tl_oct_encode(pz, bits));
            TL_CHECK_EQ_U(tl_oct_encode_precise(in[i], bits), tl_oct_encode_precise(pz, bits));
        }
        float p[2];
        tl_oct_project(in[i], p);
        TL_CHECK(p[0] == 0.0f && p[1] == 0.0f);
    }
    /* unproject of NaN or out-of-range points: clamped, finite, unit */
    const float pts[][2] = {{qnan, 0.0f}, {qnan, qnan}, {2.0f, -3.0f}, {INFINITY, -INFINITY}, {1.0f, 1.0f}, {-0.0f, 0.0f}};
    for (size_t i = 0; i < sizeof pts / sizeof pts[0]; i++) {
        float d[3];
        tl_oct_unproject(pts[i], d);
        TL_CHECK(decoded_ok(d));
    }
    printf("  NaN inputs encode as +Z; unproject of NaN/out-of-square points stays finite and unit\n");
}

/* Budgets outside 8..16 are clamped, the same way by encode and decode. */
TL_TEST(oct_bits_out_of_range_clamped)
{
    const uint32_t low[] = {0, 1, 7}, high[] = {17, 32, 0xFFFFFFFFu};
    tl_rng rng = {0xB175u};
    for (int i = 0; i < 1000; i++) {
        float n[3], a[3], b[3];
        tl_rng_direction(&rng, n);
        for (int k = 0; k < 3; k++) {
            TL_CHECK_EQ_U(tl_oct_encode(n, low[k]), tl_oct_encode(n, 8));
            TL_CHECK_EQ_U(tl_oct_encode_precise(n, high[k]), tl_oct_encode_precise(n, 16));
            uint32_t code = (uint32_t)tl_rng_u64(&rng);
            tl_oct_decode(code, low[k], a);
            tl_oct_decode(code, 8, b);
            TL_CHECK(memcmp(a, b, sizeof a) == 0);
            tl_oct_decode(code, high[k], a);
            tl_oct_decode(code, 16, b);
            TL_CHECK(memcmp(a, b, sizeof a) == 0);
        }
    }
    printf("  bits 0, 1, 7 behave as 8 and 17, 32, 2^32-1 as 16 for encode, precise and decode\n");
}

/* Every extreme input at every budget: finite, unit output (the header's promise). */
TL_TEST(oct_extreme_inputs_never_nan_or_inf)
{
    const float in[][3] = {
        {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, 0.0f}, {-0.0f, -0.0f, -0.0f},
        {1e-40f, 0.0f, 0.0f}, {FLT_TRUE_MIN, -FLT_TRUE_MIN, FLT_TRUE_MIN}, {INFINITY, 0.0f, 0.0f},
        {-INFINITY, INFINITY, -INFINITY}, {NAN, 0.0f, 0.0f}, {0.0f, 0.0f, -NAN}, {FLT_MAX, FLT_MAX, FLT_MAX},
        {-FLT_MAX, 0.0f, FLT_MAX}, {1e30f, 1e30f, -1e30f}, {1e-30f, -1e-30f, 1e-30f},
        {0.70710677f, 0.70710677f, -0.0f}, {-0.70710677f, 0.70710677f, 0.0f}, {1.0f, 0.0f, -0.0f},
        {0x1.0p-60f, 0.0f, 0.0f}, {0x1.0p60f, 0.0f, -0x1.0p60f}, {0x1.0p-61f, 0x1.0p-62f, 0.0f},
    };
    size_t total = 0;
    for (size_t i = 0; i < sizeof in / sizeof in[0]; i++)
        for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++)
            for (int p = 0; p < 2; p++) {
                uint32_t code = encoders[p](in[i], bits);
                float d[3], s[3], pr[2];
                tl_oct_decode(code, bits, d);
                TL_CHECK((uint64_t)code < (1ull << (2 * bits)));
                TL_CHECK(decoded_ok(d));
                tl_normal_sanitize(in[i], s);
                TL_CHECK(decoded_ok(s));
                tl_oct_project(in[i], pr);
                TL_CHECK(pr[0] >= -1.0f && pr[0] <= 1.0f && pr[1] >= -1.0f && pr[1] <= 1.0f);
                total++;
            }
    printf("  %zu (input, budget, encoder) combinations: all codes in range, decodes finite and unit\n", total);
}
