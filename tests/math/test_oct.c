/* Octahedral and other 2-component normal encodings: random-input error bounds against a
 * double-precision angle, exhaustive decode->encode idempotence, and scalar/batch bit identity.
 * Every case prints its measured figures so the ctest log documents them. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "thinlight/codec.h"
#include "thinlight/metrics.h"
#include "tl_test.h"

#define RANDOM_COUNT 1000000u

/* The top code of a component on the odd grid (codec.h): codes 0..top, k standing for
 * (2k - top) / top. */
static uint32_t oct_top(uint32_t bits) { return (1u << bits) - 2u; }
#define PI_D 3.14159265358979323846
#define RAD_TO_DEG (180.0 / PI_D)

static void *xmalloc(size_t size)
{
    void *p = malloc(size);
    if (!p) {
        fprintf(stderr, "out of memory (%zu bytes)\n", size);
        exit(2);
    }
    return p;
}

static tl_stats *stats_new(void)
{
    tl_stats *s = xmalloc(sizeof *s);
    tl_stats_reset(s);
    return s;
}

static void print_stats(const char *label, const tl_stats *s, const char *unit)
{
    printf("  %-44s n=%-9llu mean=%-12.6g p99=%-12.6g max=%-12.6g %s\n", label, (unsigned long long)s->count,
           tl_stats_mean(s), tl_stats_percentile(s, 0.99), s->max, unit);
}

/* `count` uniform directions from a fixed seed, as xyz triples. */
static float *random_directions(size_t count, unsigned long long seed)
{
    float *n = xmalloc(3 * count * sizeof *n);
    tl_rng rng = {seed};
    for (size_t i = 0; i < count; i++) tl_rng_direction(&rng, n + 3 * i);
    return n;
}

/* Angular error statistics (degrees) of one encoding over `count` directions. */
static void measure_normal(tl_normal_encoding enc, uint32_t bits, const float *n, size_t count, tl_stats *s)
{
    uint32_t *codes = xmalloc(count * sizeof *codes);
    float *dec = xmalloc(3 * count * sizeof *dec);
    tl_normal_encode_n(enc, n, codes, count, bits);
    tl_normal_decode_n(enc, codes, dec, count, bits);
    tl_stats_reset(s);
    for (size_t i = 0; i < count; i++) tl_stats_add(s, tl_angle_deg(n + 3 * i, dec + 3 * i));
    free(codes);
    free(dec);
}

/* ---------------------------------------------------------------------------------------------
 * 1. Random-direction error bounds
 * ------------------------------------------------------------------------------------------- */

TL_TEST(oct12_random_plain_error_bounds)
{
    float *n = random_directions(RANDOM_COUNT, 0x0C7012u);
    tl_stats *s = stats_new();
    measure_normal(TL_NORMAL_OCT, 12, n, RANDOM_COUNT, s);
    print_stats("oct12 plain, angle error", s, "deg");
    TL_CHECK(s->count == RANDOM_COUNT && s->rejected == 0);
    TL_CHECK_LE(tl_stats_mean(s), 0.021);
    TL_CHECK_LE(s->max, 0.060);
    free(s);
    free(n);
}

TL_TEST(oct12_random_precise_error_bounds)
{
    float *n = random_directions(RANDOM_COUNT, 0x0C7012u);
    tl_stats *plain = stats_new(), *precise = stats_new();
    measure_normal(TL_NORMAL_OCT, 12, n, RANDOM_COUNT, plain);
    measure_normal(TL_NORMAL_OCT_PRECISE, 12, n, RANDOM_COUNT, precise);
    print_stats("oct12 plain, angle error", plain, "deg");
    print_stats("oct12 precise, angle error", precise, "deg");
    TL_CHECK_LE(precise->max, 0.040);
    TL_CHECK_LE(tl_stats_mean(precise), tl_stats_mean(plain));
    TL_CHECK_LE(precise->max, plain->max);
    free(plain);
    free(precise);
    free(n);
}

TL_TEST(oct8_random_plain_max_error)
{
    float *n = random_directions(RANDOM_COUNT, 0x0C7008u);
    tl_stats *s = stats_new();
    measure_normal(TL_NORMAL_OCT, 8, n, RANDOM_COUNT, s);
    print_stats("oct8 plain, angle error", s, "deg");
    TL_CHECK_LE(s->max, 0.96);
    free(s);
    free(n);
}

TL_TEST(oct16_random_plain_max_error)
{
    float *n = random_directions(RANDOM_COUNT, 0x0C7016u);
    tl_stats *s = stats_new();
    measure_normal(TL_NORMAL_OCT, 16, n, RANDOM_COUNT, s);
    print_stats("oct16 plain, angle error", s, "deg");
    TL_CHECK_LE(s->max, 0.0038);
    free(s);
    free(n);
}

/* The grid spacing halves with every extra bit, so the worst-case error should as well. */
TL_TEST(oct_plain_max_error_halves_per_bit)
{
    float *n = random_directions(RANDOM_COUNT, 0x0C70FFu);
    tl_stats *s = stats_new();
    double max[TL_OCT_MAX_BITS + 1], mean[TL_OCT_MAX_BITS + 1];
    for (uint32_t b = TL_OCT_MIN_BITS; b <= TL_OCT_MAX_BITS; b++) {
        measure_normal(TL_NORMAL_OCT, b, n, RANDOM_COUNT, s);
        max[b] = s->max;
        mean[b] = tl_stats_mean(s);
    }
    printf("  bits  mean_deg      max_deg       max(b-1)/max(b)\n");
    for (uint32_t b = TL_OCT_MIN_BITS; b <= TL_OCT_MAX_BITS; b++) {
        if (b == TL_OCT_MIN_BITS) {
            printf("  %4u  %-12.6g  %-12.6g  -\n", b, mean[b], max[b]);
            continue;
        }
        double ratio = max[b - 1] / max[b];
        printf("  %4u  %-12.6g  %-12.6g  %.4f\n", b, mean[b], max[b], ratio);
        TL_CHECK(ratio >= 1.7 && ratio <= 2.3);
    }
    free(s);
    free(n);
}

/* The precise variant must pick the best of its 4 floor/ceil candidates, judged in double, at
 * unit length and at lengths far from it (exact powers of two, so the direction is unchanged). */
TL_TEST(oct_precise_picks_best_candidate_double_reference)
{
    const size_t count = 100000;
    const uint32_t budgets[] = {8, 10, 12, 16};
    const float scales[] = {1.0f, 0x1.0p-59f, 0x1.0p-50f, 0x1.0p-40f, 0x1.0p-31f, 0x1.0p31f, 0x1.0p59f};
    float *n = random_directions(count, 0xBE57u);
    for (size_t si = 0; si < sizeof scales / sizeof scales[0]; si++)
        for (size_t bi = 0; bi < sizeof budgets / sizeof budgets[0]; bi++) {
            uint32_t bits = budgets[bi], top = oct_top(bits);
            size_t not_best = 0;
            double worst_excess = 0.0;
            for (size_t i = 0; i < count; i++) {
                const float *v = n + 3 * i;
                float vs[3] = {v[0] * scales[si], v[1] * scales[si], v[2] * scales[si]};
                uint32_t code = tl_oct_encode_precise(vs, bits);
                float d[3];
                tl_oct_decode(code, bits, d);
                double chosen = tl_angle_deg(v, d);
                /* floor candidates as the double projection sees them */
                double ax = fabs((double)v[0]), ay = fabs((double)v[1]), az = fabs((double)v[2]);
                double l1 = ax + ay + az, pu = v[0] / l1, pv = v[1] / l1;
                if (v[2] < 0.0f) {
                    double fu = (1.0 - fabs(pv)) * (signbit(v[0]) ? -1.0 : 1.0);
                    double fv = (1.0 - fabs(pu)) * (signbit(v[1]) ? -1.0 : 1.0);
                    pu = fu;
                    pv = fv;
                }
                double qu = floor((pu + 1.0) * 0.5 * top), qv = floor((pv + 1.0) * 0.5 * top);
                uint32_t u0 = qu >= top ? top - 1u : (uint32_t)qu, v0 = qv >= top ? top - 1u : (uint32_t)qv;
                double best = 1e300;
                for (uint32_t k = 0; k < 4; k++) {
                    float c[3];
                    tl_oct_decode((u0 + (k & 1u)) | ((v0 + (k >> 1)) << bits), bits, c);
                    double a = tl_angle_deg(v, c);
                    if (a < best) best = a;
                }
                if (chosen > best) {
                    not_best++;
                    if (chosen - best > worst_excess) worst_excess = chosen - best;
                }
            }
            printf("  oct%-2u precise, length %-8a: %6zu of %zu not the double-best candidate, worst excess %.3g deg\n",
                   bits, (double)scales[si], not_best, count, worst_excess);
            /* The float cross product resolves angles only to a few 2^-24 rad (its products
             * cancel), so near-ties may go either way: allow 8 * 2^-24 rad. */
            TL_CHECK_LE(worst_excess, 8.0 * 0x1.0p-24 * RAD_TO_DEG);
        }
    free(n);
}

/* Plain rounding: the code is the nearest grid point of the projection computed in double,
 * except where the float projection lands within float rounding of a rounding boundary. */
TL_TEST(oct_plain_code_matches_double_projection)
{
    const size_t count = RANDOM_COUNT;
    float *n = random_directions(count, 0x9A1Bu);
    const uint32_t budgets[] = {8, 12, 16};
    for (size_t bi = 0; bi < sizeof budgets / sizeof budgets[0]; bi++) {
        uint32_t bits = budgets[bi], top = oct_top(bits), mask = (1u << bits) - 1u;
        /* float error of q = (p + 1) * top / 2: a few ULPs of p (2^-24 each) times top/2 */
        const double band = 4.0 * 0x1.0p-24 * top;
        size_t differ = 0;
        for (size_t i = 0; i < count; i++) {
            const float *v = n + 3 * i;
            double l1 = fabs((double)v[0]) + fabs((double)v[1]) + fabs((double)v[2]);
            double pu = v[0] / l1, pv = v[1] / l1;
            if (v[2] < 0.0f) {
                double fu = (1.0 - fabs(pv)) * (signbit(v[0]) ? -1.0 : 1.0);
                double fv = (1.0 - fabs(pu)) * (signbit(v[1]) ? -1.0 : 1.0);
                pu = fu;
                pv = fv;
            }
            double qu = (pu + 1.0) * 0.5 * top, qv = (pv + 1.0) * 0.5 * top;
            uint32_t ru = (uint32_t)floor(qu + 0.5), rv = (uint32_t)floor(qv + 0.5);
            uint32_t code = tl_oct_encode(v, bits), cu = code & mask, cv = code >> bits;
            if (cu != ru || cv != rv) {
                differ++;
                /* only allowed right at a rounding boundary: |q - (k + 1/2)| within float error */
                double du = fabs(qu - floor(qu) - 0.5), dv = fabs(qv - floor(qv) - 0.5);
                TL_CHECK(du < band || dv < band);
                TL_CHECK((cu > ru ? cu - ru : ru - cu) <= 1u && (cv > rv ? cv - rv : rv - cv) <= 1u);
            }
        }
        printf("  oct%-2u plain: %zu of %zu codes differ from double rounding (all within %.3g of a tie)\n", bits,
               differ, count, band);
        /* at most the inputs whose q falls within the band of a rounding boundary, per component */
        TL_CHECK_LE((double)differ, 2.0 * 2.0 * band * (double)count);
    }
    free(n);
}

/* Projection without quantisation: unproject(project(n)) is n up to float rounding. */
TL_TEST(oct_project_unproject_round_trip_unquantised)
{
    float *n = random_directions(RANDOM_COUNT, 0x9801u);
    tl_stats *s = stats_new();
    for (size_t i = 0; i < RANDOM_COUNT; i++) {
        float p[2], d[3];
        tl_oct_project(n + 3 * i, p);
        TL_CHECK(p[0] >= -1.0f && p[0] <= 1.0f && p[1] >= -1.0f && p[1] <= 1.0f);
        tl_oct_unproject(p, d);
        tl_stats_add(s, tl_angle_deg(n + 3 * i, d));
    }
    print_stats("project/unproject (float only)", s, "deg");
    TL_CHECK_LE(s->max, 1e-4);
    free(s);
    free(n);
}

/* ---------------------------------------------------------------------------------------------
 * 2. Exhaustive decode -> encode idempotence
 * ------------------------------------------------------------------------------------------- */

/* Every code of the odd grid, (2^bits - 1)^2 of them: component codes 0..top (the unused
 * component code 2^bits - 1 is covered by test_oct_grid.c). */
static void check_idempotent_exhaustive(uint32_t bits)
{
    const size_t chunk = 1u << 16;
    const uint64_t side = (uint64_t)oct_top(bits) + 1u, total = side * side;
    uint32_t *codes = xmalloc(chunk * sizeof *codes), *plain = xmalloc(chunk * sizeof *plain),
             *precise = xmalloc(chunk * sizeof *precise);
    float *n = xmalloc(3 * chunk * sizeof *n);
    uint64_t bad_plain = 0, bad_precise = 0, bad_unit = 0;
    double worst_len = 0.0;
    for (uint64_t start = 0; start < total; start += chunk) {
        size_t m = (size_t)(total - start < chunk ? total - start : chunk);
        for (size_t i = 0; i < m; i++) {
            uint64_t k = start + i;
            codes[i] = (uint32_t)(k % side) | (uint32_t)(k / side) << bits;
        }
        tl_oct_decode_n(codes, n, m, bits);
        tl_oct_encode_n(n, plain, m, bits);
        tl_oct_encode_precise_n(n, precise, m, bits);
        for (size_t i = 0; i < m; i++) {
            if (plain[i] != codes[i]) {
                if (bad_plain++ < 5)
                    fprintf(stderr, "  oct%u plain: code 0x%x -> (%a, %a, %a) -> 0x%x\n", bits, codes[i],
                            n[3 * i], n[3 * i + 1], n[3 * i + 2], plain[i]);
            }
            if (precise[i] != codes[i]) {
                if (bad_precise++ < 5)
                    fprintf(stderr, "  oct%u precise: code 0x%x -> (%a, %a, %a) -> 0x%x\n", bits, codes[i],
                            n[3 * i], n[3 * i + 1], n[3 * i + 2], precise[i]);
            }
            const float *v = n + 3 * i;
            double len = sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]);
            if (!(fabs(len - 1.0) <= 1e-6)) bad_unit++;
            if (fabs(len - 1.0) > worst_len) worst_len = fabs(len - 1.0);
        }
    }
    printf("  oct%u: %llu codes, plain mismatches %llu, precise mismatches %llu, max |len-1| %.3g\n", bits,
           (unsigned long long)total, (unsigned long long)bad_plain, (unsigned long long)bad_precise, worst_len);
    TL_CHECK_EQ_U(bad_plain, 0);
    TL_CHECK_EQ_U(bad_precise, 0);
    TL_CHECK_EQ_U(bad_unit, 0);
    free(codes);
    free(plain);
    free(precise);
    free(n);
}

TL_TEST(oct8_exhaustive_decode_encode_idempotent) { check_idempotent_exhaustive(8); }
TL_TEST(oct10_exhaustive_decode_encode_idempotent) { check_idempotent_exhaustive(10); }
TL_TEST(oct12_exhaustive_decode_encode_idempotent) { check_idempotent_exhaustive(12); }
TL_TEST(oct9_oct11_exhaustive_decode_encode_idempotent)
{
    check_idempotent_exhaustive(9);
    check_idempotent_exhaustive(11);
}

/* ---------------------------------------------------------------------------------------------
 * 3. Scalar vs batch bit identity
 * ------------------------------------------------------------------------------------------- */

/* Random directions with random lengths and, at pseudo-random lanes, inputs that need the
 * sanitising path: NaN, Inf, zero, denormal, too small and too large. */
static float *mixed_inputs(size_t count, unsigned long long seed)
{
    static const float bad[][3] = {
        {NAN, 0.0f, 1.0f}, {0.0f, -NAN, 0.0f}, {INFINITY, 0.0f, 0.0f}, {-INFINITY, INFINITY, 1.0f},
        {0.0f, 0.0f, 0.0f}, {-0.0f, -0.0f, -0.0f}, {1e-40f, 0.0f, 0.0f}, {0.0f, -1e-45f, 1e-40f},
        {1e-30f, -2e-30f, 3e-30f}, {1e30f, 1e30f, -1e30f}, {FLT_MAX, -FLT_MAX, FLT_MAX},
        {0.0f, 0.0f, -1.0f}, {-0.0f, 0.0f, -1.0f}, {0.6f, -0.4f, -0.0f}, {0.6f, 0.4f, 0.0f},
    };
    const size_t nbad = sizeof bad / sizeof bad[0];
    float *n = xmalloc(3 * count * sizeof *n);
    tl_rng rng = {seed};
    for (size_t i = 0; i < count; i++) {
        float *v = n + 3 * i;
        uint64_t r = tl_rng_u64(&rng);
        if ((r & 63u) == 0) {
            memcpy(v, bad[(r >> 8) % nbad], sizeof bad[0]);
        } else {
            tl_rng_direction(&rng, v);
            if ((r & 3u) == 1) { /* non-unit lengths */
                float s = (float)exp2(80.0 * tl_rng_unit(&rng) - 40.0);
                v[0] *= s;
                v[1] *= s;
                v[2] *= s;
            }
        }
    }
    return n;
}

TL_TEST(oct_encode_n_matches_scalar_bit_exact)
{
    const size_t count = RANDOM_COUNT + 3; /* not a multiple of 4 */
    float *n = mixed_inputs(count, 0xBA7C4u);
    uint32_t *codes = xmalloc((count + 1) * sizeof *codes);
    size_t mismatches = 0, checked = 0;
    for (uint32_t bits = 6; bits <= 18; bits++) { /* 6, 7, 17, 18 exercise the clamping */
        size_t m = bits == 12 ? count : count / 8 + 1;
        codes[m] = 0xDEADBEEFu;
        tl_oct_encode_n(n, codes, m, bits);
        TL_CHECK_EQ_U(codes[m], 0xDEADBEEFu); /* nothing written past the end */
        for (size_t i = 0; i < m; i++, checked++)
            if (codes[i] != tl_oct_encode(n + 3 * i, bits)) mismatches++;
    }
    printf("  tl_oct_encode_n vs tl_oct_encode: %zu inputs, %zu mismatches\n", checked, mismatches);
    TL_CHECK_EQ_U(mismatches, 0);
    free(codes);
    free(n);
}

TL_TEST(oct_encode_precise_n_matches_scalar_bit_exact)
{
    const size_t count = RANDOM_COUNT + 1;
    float *n = mixed_inputs(count, 0xBA7C5u);
    uint32_t *codes = xmalloc((count + 1) * sizeof *codes);
    size_t mismatches = 0, checked = 0;
    for (uint32_t bits = 6; bits <= 18; bits++) {
        size_t m = bits == 12 ? count : count / 8 + 2;
        codes[m] = 0xDEADBEEFu;
        tl_oct_encode_precise_n(n, codes, m, bits);
        TL_CHECK_EQ_U(codes[m], 0xDEADBEEFu);
        for (size_t i = 0; i < m; i++, checked++)
            if (codes[i] != tl_oct_encode_precise(n + 3 * i, bits)) mismatches++;
    }
    printf("  tl_oct_encode_precise_n vs tl_oct_encode_precise: %zu inputs, %zu mismatches\n", checked,
           mismatches);
    TL_CHECK_EQ_U(mismatches, 0);
    free(codes);
    free(n);
}

TL_TEST(oct_decode_n_matches_scalar_bit_exact)
{
    const size_t count = RANDOM_COUNT + 2;
    uint32_t *codes = xmalloc(count * sizeof *codes);
    float *n = xmalloc((3 * count + 1) * sizeof *n);
    tl_rng rng = {0xDEC0DEu};
    for (size_t i = 0; i < count; i++) codes[i] = (uint32_t)tl_rng_u64(&rng); /* high bits are junk */
    size_t mismatches = 0, checked = 0;
    for (uint32_t bits = 6; bits <= 18; bits++) {
        size_t m = bits == 12 ? count : count / 8 + 3;
        n[3 * m] = -42.0f;
        tl_oct_decode_n(codes, n, m, bits);
        TL_CHECK(n[3 * m] == -42.0f);
        for (size_t i = 0; i < m; i++, checked++) {
            float s[3];
            tl_oct_decode(codes[i], bits, s);
            if (memcmp(s, n + 3 * i, sizeof s) != 0) mismatches++;
        }
    }
    printf("  tl_oct_decode_n vs tl_oct_decode: %zu codes, %zu mismatches\n", checked, mismatches);
    TL_CHECK_EQ_U(mismatches, 0);
    free(codes);
    free(n);
}

/* Every count 0..19 at every offset 0..3, so that bad inputs fall into every lane of the SIMD
 * blocks and into the scalar tail. */
TL_TEST(oct_batch_short_counts_and_lanes_match_scalar)
{
    float *n = mixed_inputs(64, 0x1A4Eu);
    /* force one bad input per lane position too */
    const float nan_v[3] = {NAN, NAN, NAN}, zero_v[3] = {0.0f, 0.0f, 0.0f}, inf_v[3] = {0.0f, -INFINITY, 0.0f};
    memcpy(n + 3 * 1, nan_v, sizeof nan_v);
    memcpy(n + 3 * 6, zero_v, sizeof zero_v);
    memcpy(n + 3 * 11, inf_v, sizeof inf_v);
    memcpy(n + 3 * 16, nan_v, sizeof nan_v);
    size_t mismatches = 0;
    for (uint32_t bits = 8; bits <= 16; bits += 4)
        for (size_t off = 0; off < 4; off++)
            for (size_t cnt = 0; cnt < 20; cnt++) {
                uint32_t a[24], b[24];
                float d[3 * 24];
                for (size_t i = 0; i < 24; i++) a[i] = b[i] = 0xA5A5A5A5u;
                for (size_t i = 0; i < 3 * 24; i++) d[i] = 7.0f;
                tl_oct_encode_n(n + 3 * off, a, cnt, bits);
                tl_oct_encode_precise_n(n + 3 * off, b, cnt, bits);
                for (size_t i = 0; i < cnt; i++) {
                    if (a[i] != tl_oct_encode(n + 3 * (off + i), bits)) mismatches++;
                    if (b[i] != tl_oct_encode_precise(n + 3 * (off + i), bits)) mismatches++;
                }
                for (size_t i = cnt; i < 24; i++)
                    if (a[i] != 0xA5A5A5A5u || b[i] != 0xA5A5A5A5u) mismatches++;
                tl_oct_decode_n(b, d, cnt, bits);
                for (size_t i = 0; i < cnt; i++) {
                    float s[3];
                    tl_oct_decode(b[i], bits, s);
                    if (memcmp(s, d + 3 * i, sizeof s) != 0) mismatches++;
                }
                for (size_t i = 3 * cnt; i < 3 * 24; i++)
                    if (d[i] != 7.0f) mismatches++;
            }
    printf("  short counts 0..19 x offsets 0..3 x bits {8,12,16}: %zu mismatches\n", mismatches);
    TL_CHECK_EQ_U(mismatches, 0);
    /* NULL buffers are ignored, not dereferenced */
    tl_oct_encode_n(NULL, NULL, 5, 12);
    tl_oct_encode_precise_n(NULL, NULL, 5, 12);
    tl_oct_decode_n(NULL, NULL, 5, 12);
    free(n);
}

TL_TEST(normal_encode_n_all_encodings_match_scalar)
{
    const size_t count = 100003;
    float *n = mixed_inputs(count, 0xA17u);
    uint32_t *codes = xmalloc(count * sizeof *codes);
    float *dec = xmalloc(3 * count * sizeof *dec);
    size_t mismatches = 0;
    for (int e = 0; e < TL_NORMAL_ENCODING_COUNT_; e++) {
        tl_normal_encoding enc = (tl_normal_encoding)e;
        tl_normal_encode_n(enc, n, codes, count, 12);
        tl_normal_decode_n(enc, codes, dec, count, 12);
        for (size_t i = 0; i < count; i++) {
            float s[3];
            if (codes[i] != tl_normal_encode(enc, n + 3 * i, 12)) mismatches++;
            tl_normal_decode(enc, codes[i], 12, s);
            if (memcmp(s, dec + 3 * i, sizeof s) != 0) mismatches++;
        }
    }
    printf("  tl_normal_encode_n/decode_n vs scalar, %d encodings x %zu: %zu mismatches\n",
           (int)TL_NORMAL_ENCODING_COUNT_, count, mismatches);
    TL_CHECK_EQ_U(mismatches, 0);
    free(codes);
    free(dec);
    free(n);
}

/* ---------------------------------------------------------------------------------------------
 * 5. Other encodings: finite outputs on extreme inputs, error bounds derived from their grids
 * ------------------------------------------------------------------------------------------- */

TL_TEST(normal_alt_encodings_extreme_inputs_finite)
{
    static const float in[][3] = {
        {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, -1.0f}, {-0.0f, -0.0f, -1.0f}, {0.0f, 0.0f, 0.0f},
        {-0.0f, -0.0f, -0.0f}, {1e-40f, 0.0f, 0.0f}, {0.0f, 0.0f, -1e-45f}, {INFINITY, 0.0f, 0.0f},
        {-INFINITY, INFINITY, -INFINITY}, {NAN, 0.0f, 0.0f}, {0.0f, 0.0f, NAN}, {FLT_MAX, FLT_MAX, -FLT_MAX},
        {1e30f, -1e30f, 0.0f}, {1e-30f, 0.0f, -1e-30f}, {1.0f, 0.0f, -0.0f}, {0.0f, -1.0f, 0.0f},
        {0.70710677f, 0.70710677f, -0.0f}, {1e-7f, 0.0f, -1.0f}, {0.0f, 1e-7f, 1.0f},
    };
    size_t bad = 0, total = 0;
    for (int e = 0; e < TL_NORMAL_ENCODING_COUNT_; e++)
        for (uint32_t bits = 0; bits <= 20; bits++)
            for (size_t i = 0; i < sizeof in / sizeof in[0]; i++) {
                uint32_t b = bits < TL_OCT_MIN_BITS ? TL_OCT_MIN_BITS : bits > TL_OCT_MAX_BITS ? TL_OCT_MAX_BITS : bits;
                uint32_t code = tl_normal_encode((tl_normal_encoding)e, in[i], bits);
                float d[3];
                tl_normal_decode((tl_normal_encoding)e, code, bits, d);
                double len = sqrt((double)d[0] * d[0] + (double)d[1] * d[1] + (double)d[2] * d[2]);
                int ok = (uint64_t)code < (1ull << (2 * b)) && isfinite(d[0]) && isfinite(d[1]) &&
                         isfinite(d[2]) && fabs(len - 1.0) <= 1e-6;
                if (!ok) {
                    if (bad < 10)
                        fprintf(stderr, "  %s bits %u input %zu: code 0x%x -> (%g, %g, %g)\n",
                                tl_normal_encoding_name((tl_normal_encoding)e), bits, i, code, d[0], d[1], d[2]);
                    bad++;
                }
                total++;
            }
    printf("  %zu (encoding, bits, extreme input) triples, %zu non-finite or non-unit\n", total, bad);
    TL_CHECK_EQ_U(bad, 0);
    /* stereographic: a lower-hemisphere input is clamped to the equator */
    const float below[3] = {0.6f, 0.0f, -0.8f};
    float d[3];
    tl_normal_decode(TL_NORMAL_STEREOGRAPHIC, tl_normal_encode(TL_NORMAL_STEREOGRAPHIC, below, 12), 12, d);
    printf("  stereographic12 of (0.6, 0, -0.8) decodes to (%g, %g, %g)\n", d[0], d[1], d[2]);
    TL_CHECK(fabsf(d[2]) <= 2e-3f && d[0] > 0.999f);
}

/* Random directions restricted to a band of z, uniformly on that part of the sphere. */
static float *random_directions_z(size_t count, unsigned long long seed, double zmin, double zmax)
{
    float *n = xmalloc(3 * count * sizeof *n);
    tl_rng rng = {seed};
    for (size_t i = 0; i < count; i++) {
        double z = zmin + (zmax - zmin) * tl_rng_unit(&rng), phi = 2.0 * PI_D * tl_rng_unit(&rng);
        double s = sqrt(fmax(0.0, 1.0 - z * z));
        n[3 * i] = (float)(s * cos(phi));
        n[3 * i + 1] = (float)(s * sin(phi));
        n[3 * i + 2] = (float)z;
    }
    return n;
}

/* Bounds are half a grid cell's diagonal mapped through each projection's largest local
 * stretch over the tested region, with 10 % for float evaluation. */
TL_TEST(normal_alt12_error_bounds_vs_grid_spacing)
{
    const uint32_t bits = 12;
    /* spherical: unorm grid of 2^bits levels; Lambert and stereographic: the odd snorm grid */
    const double max = (double)((1u << bits) - 1u), top = (double)oct_top(bits), slack = 1.10;
    tl_stats *s = stats_new();

    /* Spherical, |z| <= 0.9: azimuth half-step pi/max along a parallel of radius <= 1, z
     * half-step 1/max, which is 1/(max sin(theta)) in angle with sin(theta) >= sqrt(1 - 0.81). */
    float *band = random_directions_z(RANDOM_COUNT, 0x5F1u, -0.9, 0.9);
    measure_normal(TL_NORMAL_SPHERICAL, bits, band, RANDOM_COUNT, s);
    double sph_bound = slack * sqrt(pow(PI_D / max, 2) + pow(1.0 / (max * sqrt(1.0 - 0.81)), 2)) * RAD_TO_DEG;
    print_stats("spherical12, |z| <= 0.9", s, "deg");
    printf("  %-44s bound %.6g deg\n", "", sph_bound);
    TL_CHECK_LE(s->max, sph_bound);
    free(band);

    /* Lambert, z >= -0.9: disc radius r = 2 sin(theta/2), the code grid spans r in [-2, 2] with
     * half-step 2/top, so a half-cell diagonal is 2 sqrt(2)/top. The map stretches angles by
     * 1/cos(theta/2) radially (and shrinks them tangentially), with cos(theta/2) =
     * sqrt((1 + z)/2) >= sqrt(0.05); the diagonal may point radially. */
    float *cap = random_directions_z(RANDOM_COUNT, 0x1A3u, -0.9, 1.0);
    measure_normal(TL_NORMAL_LAMBERT, bits, cap, RANDOM_COUNT, s);
    double c = sqrt(0.05);
    double lam_bound = slack * 2.0 * sqrt(2.0) / (top * c) * RAD_TO_DEG;
    print_stats("lambert12, z >= -0.9", s, "deg");
    printf("  %-44s bound %.6g deg\n", "", lam_bound);
    TL_CHECK_LE(s->max, lam_bound);
    free(cap);

    /* Stereographic, upper hemisphere: conformal with |d theta| = 2 cos^2(theta/2) |d rho| <= 2 |d rho|,
     * half-diagonal sqrt(2)/top in rho. */
    float *upper = random_directions_z(RANDOM_COUNT, 0x57Eu, 0.0, 1.0);
    measure_normal(TL_NORMAL_STEREOGRAPHIC, bits, upper, RANDOM_COUNT, s);
    double st_bound = slack * 2.0 * sqrt(2.0) / top * RAD_TO_DEG;
    print_stats("stereographic12, z >= 0", s, "deg");
    printf("  %-44s bound %.6g deg\n", "", st_bound);
    TL_CHECK_LE(s->max, st_bound);
    free(upper);
    free(s);
}

/* Octahedral precise at 12 bits beats every other encoding's worst case at equal bits, each
 * measured on its own domain (stereographic on the upper hemisphere). */
TL_TEST(oct12_precise_beats_alt_encodings_max_error)
{
    const uint32_t bits = 12;
    float *all = random_directions(RANDOM_COUNT, 0xC0FFEEu);
    float *upper = random_directions_z(RANDOM_COUNT, 0xC0FFEFu, 0.0, 1.0);
    tl_stats *s = stats_new();
    measure_normal(TL_NORMAL_OCT_PRECISE, bits, all, RANDOM_COUNT, s);
    double oct = s->max;
    print_stats("oct-precise12, sphere", s, "deg");
    measure_normal(TL_NORMAL_OCT, bits, all, RANDOM_COUNT, s);
    print_stats("oct12, sphere", s, "deg");
    measure_normal(TL_NORMAL_SPHERICAL, bits, all, RANDOM_COUNT, s);
    print_stats("spherical12, sphere", s, "deg");
    /* near the poles the z grid step 2/max opens to acos(1 - 1/max) ~ sqrt(2/max) */
    TL_CHECK_LE(s->max, 1.1 * sqrt(2.0 / ((1u << bits) - 1u)) * RAD_TO_DEG);
    TL_CHECK(oct < s->max);
    measure_normal(TL_NORMAL_LAMBERT, bits, all, RANDOM_COUNT, s);
    print_stats("lambert12, sphere", s, "deg");
    TL_CHECK(oct < s->max);
    measure_normal(TL_NORMAL_STEREOGRAPHIC, bits, upper, RANDOM_COUNT, s);
    /* Stereographic's worst case is next to the pole, where the map's stretch is largest, 2: at the
     * centre of a grid cell touching the pole, half a cell diagonal (sqrt(2)/top) from each of
     * its corners, the error is 2 atan(sqrt(2)/top) ~ 2 sqrt(2)/top rad (the pole itself is a
     * code of the odd grid and exact). Random samples rarely come that close, so this point joins
     * the sample. Octahedral precise's own worst case is only ~0.5 % below it (0.03940 vs
     * 0.03959 deg at 12 bits). */
    const double top = (double)oct_top(bits), cx = 1.0 / top, cy = 1.0 / top, cd = cx * cx + cy * cy;
    const float centre[3] = {(float)(2.0 * cx / (1.0 + cd)), (float)(2.0 * cy / (1.0 + cd)),
                             (float)((1.0 - cd) / (1.0 + cd))};
    float d[3];
    tl_normal_decode(TL_NORMAL_STEREOGRAPHIC, tl_normal_encode(TL_NORMAL_STEREOGRAPHIC, centre, bits), bits, d);
    double pole = tl_angle_deg(centre, d), pole_theory = 2.0 * atan(sqrt(2.0) / top) * RAD_TO_DEG;
    printf("  stereographic12 at the cell centre next to +Z: %.7g deg (2 atan(sqrt(2)/top) = %.7g deg)\n", pole,
           pole_theory);
    /* the other three corners of the cell lie where the stretch is smaller by O(1/top^2) */
    TL_CHECK_LE(fabs(pole - pole_theory), 1e-3 * pole_theory);
    tl_stats_add(s, pole);
    print_stats("stereographic12, upper hemisphere + near-pole", s, "deg");
    TL_CHECK(oct < s->max);
    free(s);
    free(all);
    free(upper);
}
