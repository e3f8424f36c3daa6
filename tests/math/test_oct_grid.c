/* The octahedral odd grid (codec.h): 2^bits - 1 levels per component, code k standing for
 * (2k - top) / top with top = 2^bits - 2, so 0, -1 and +1 are codes. Axis normals (floors, walls)
 * and the zero vector must round-trip with no error at all, the unused code 2^bits - 1 must
 * decode like top, and the random-direction error may grow over the even grid (top = 2^bits - 1)
 * only by the ratio of the grid spacings, (2^bits - 1) / (2^bits - 2), plus the sampling noise
 * of a maximum over 10^6 random directions. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "thinlight/codec.h"
#include "thinlight/metrics.h"
#include "tl_test.h"

static uint32_t oct_top(uint32_t bits) { return (1u << bits) - 2u; }
static uint32_t oct_centre(uint32_t bits) { return oct_top(bits) / 2u; }

typedef uint32_t (*encode_fn)(const float n[3], uint32_t bits);
static const encode_fn encoders[2] = {tl_oct_encode, tl_oct_encode_precise};

/* An axis direction, the signed-zero spellings of its input, and its expected code. */
typedef struct axis_case {
    const char *name;
    float in[4][3];   /* the same direction with every sign of its zero components */
    int code_u, code_v; /* -1: code 0, 0: centre, +1: top */
} axis_case;

static const axis_case axes[] = {
    {"+X", {{1, 0, 0}, {1, -0.0f, 0}, {1, 0, -0.0f}, {1, -0.0f, -0.0f}}, +1, 0},
    {"-X", {{-1, 0, 0}, {-1, -0.0f, 0}, {-1, 0, -0.0f}, {-1, -0.0f, -0.0f}}, -1, 0},
    {"+Y", {{0, 1, 0}, {-0.0f, 1, 0}, {0, 1, -0.0f}, {-0.0f, 1, -0.0f}}, 0, +1},
    {"-Y", {{0, -1, 0}, {-0.0f, -1, 0}, {0, -1, -0.0f}, {-0.0f, -1, -0.0f}}, 0, -1},
    {"+Z", {{0, 0, 1}, {-0.0f, 0, 1}, {0, -0.0f, 1}, {-0.0f, -0.0f, 1}}, 0, 0},
};

static uint32_t grid_code(int which, uint32_t bits)
{
    return which < 0 ? 0u : which == 0 ? oct_centre(bits) : oct_top(bits);
}

static int same_vector(const float a[3], const float b[3]) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

/* Every axis at every budget, both encoders, scalar and batch: the expected code and an exact
 * decode. -Z is checked by test_oct_extreme (the four corners). Returns the failures. */
static size_t check_axes(uint32_t bits)
{
    size_t bad = 0;
    for (size_t a = 0; a < sizeof axes / sizeof axes[0]; a++)
        for (int s = 0; s < 4; s++)
            for (int p = 0; p < 2; p++) {
                const float *in = axes[a].in[s];
                uint32_t want = grid_code(axes[a].code_u, bits) | grid_code(axes[a].code_v, bits) << bits;
                uint32_t code = encoders[p](in, bits), batch[1];
                if (p) tl_oct_encode_precise_n(in, batch, 1, bits);
                else tl_oct_encode_n(in, batch, 1, bits);
                float d[3], db[3];
                tl_oct_decode(code, bits, d);
                tl_oct_decode_n(&code, db, 1, bits);
                int ok = code == want && batch[0] == want && same_vector(d, axes[a].in[0]) &&
                         same_vector(db, axes[a].in[0]) && tl_angle_deg(in, d) == 0.0;
                if (!ok && bad++ < 8)
                    fprintf(stderr, "  oct%u %s: %s (%g, %g, %g) -> 0x%x (want 0x%x) -> (%a, %a, %a)\n", bits,
                            p ? "precise" : "plain", axes[a].name, in[0], in[1], in[2], code, want, d[0], d[1], d[2]);
            }
    return bad;
}

TL_TEST(oct12_axis_normals_exact)
{
    TL_CHECK_EQ_U(check_axes(12), 0);
    /* and through both RT0 layouts, whose normals are oct12 and oct10 precise */
    size_t bad = 0;
    for (size_t a = 0; a < sizeof axes / sizeof axes[0]; a++)
        for (int s = 0; s < 4; s++) {
            uint8_t t[4];
            float n8[3], n10[3], g;
            uint32_t flags;
            tl_rt0_encode_rgba8(axes[a].in[s], 0.5f, t);
            tl_rt0_decode_rgba8(t, n8, &g);
            tl_rt0_decode_rgb10a2(tl_rt0_encode_rgb10a2(axes[a].in[s], 0.5f, 0), n10, &g, &flags);
            bad += !same_vector(n8, axes[a].in[0]) || !same_vector(n10, axes[a].in[0]);
        }
    printf("  +-X, +-Y, +Z with every signed zero: oct12 plain and precise, scalar and batch, RT0 RGBA8 and\n"
           "  RGB10A2: %zu not decoded exactly\n", bad);
    TL_CHECK_EQ_U(bad, 0);
}

TL_TEST(oct_axis_normals_exact_every_budget)
{
    size_t bad = 0;
    for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++) bad += check_axes(bits);
    printf("  axes at 8..16 bits, both encoders, scalar and batch: %zu failures\n", bad);
    TL_CHECK_EQ_U(bad, 0);
}

/* The zero vector (every sign) and NaN become +Z (tl_normal_sanitize), which now decodes exactly. */
TL_TEST(oct_zero_vector_decodes_exactly_positive_z)
{
    const float in[][3] = {{0, 0, 0}, {-0.0f, -0.0f, -0.0f}, {0, -0.0f, 0}, {-0.0f, 0, -0.0f}, {NAN, 0, 0}, {0, 0, -NAN}};
    const float pz[3] = {0.0f, 0.0f, 1.0f};
    size_t bad = 0;
    for (size_t i = 0; i < sizeof in / sizeof in[0]; i++)
        for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++)
            for (int p = 0; p < 2; p++) {
                float d[3];
                uint32_t code = encoders[p](in[i], bits);
                tl_oct_decode(code, bits, d);
                bad += code != (oct_centre(bits) | oct_centre(bits) << bits) || !same_vector(d, pz) || signbit(d[0]) ||
                       signbit(d[1]);
            }
    printf("  zero and NaN vectors at 8..16 bits: %zu not decoded as exactly (+0, +0, 1)\n", bad);
    TL_CHECK_EQ_U(bad, 0);
}

/* The component code 2^bits - 1 is outside the grid: it decodes like top, scalar and batch. */
TL_TEST(oct_unused_code_decodes_as_top)
{
    size_t bad = 0, total = 0;
    for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++) {
        uint32_t top = oct_top(bits), unused = top + 1u;
        for (uint32_t k = 0; k <= unused; k++) {
            const uint32_t pairs[3][2] = {{unused, k}, {k, unused}, {unused, unused}};
            for (int i = 0; i < 3; i++) {
                uint32_t code = pairs[i][0] | pairs[i][1] << bits;
                uint32_t clamped = (pairs[i][0] > top ? top : pairs[i][0]) | (pairs[i][1] > top ? top : pairs[i][1]) << bits;
                float d[3], c[3], b[3];
                tl_oct_decode(code, bits, d);
                tl_oct_decode(clamped, bits, c);
                tl_oct_decode_n(&code, b, 1, bits);
                bad += memcmp(d, c, sizeof d) != 0 || memcmp(b, c, sizeof b) != 0;
                total++;
            }
        }
    }
    printf("  %zu codes with the unused component 2^bits - 1 at 8..16 bits: %zu decode unlike top\n", total, bad);
    TL_CHECK_EQ_U(bad, 0);
}

/* Error of one encoding over `count` random directions; also its worst error on the axes. */
static void measure(tl_normal_encoding enc, uint32_t bits, const float *n, size_t count, tl_stats *s, double *axis_max)
{
    uint32_t *codes = malloc(count * sizeof *codes);
    float *dec = malloc(3 * count * sizeof *dec);
    if (!codes || !dec) abort();
    tl_normal_encode_n(enc, n, codes, count, bits);
    tl_normal_decode_n(enc, codes, dec, count, bits);
    tl_stats_reset(s);
    for (size_t i = 0; i < count; i++) tl_stats_add(s, tl_angle_deg(n + 3 * i, dec + 3 * i));
    static const float six[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    *axis_max = 0.0;
    for (int a = 0; a < 6; a++) {
        float d[3];
        tl_normal_decode(enc, tl_normal_encode(enc, six[a], bits), bits, d);
        *axis_max = fmax(*axis_max, tl_angle_deg(six[a], d));
    }
    free(codes);
    free(dec);
}

/* Odd against even grid at every budget, both encoders. The odd grid's spacing is 2 / (2^b - 2)
 * against 2 / (2^b - 1), so its worst and mean errors may grow by at most that ratio, plus the
 * sampling noise: 0.1 % for the mean, 2 % for the maximum (the two grids' worst points lie in
 * different places, and 10^6 samples come within ~1 % of either; measured up to 0.98 %). The
 * axes go from a non-zero error to exactly 0. */
TL_TEST(oct_odd_grid_vs_even_grid_error)
{
    const size_t count = 1000000;
    float *n = malloc(3 * count * sizeof *n);
    tl_stats *odd = malloc(sizeof *odd), *even = malloc(sizeof *even);
    if (!n || !odd || !even) abort();
    tl_rng rng = {0x0DD6u};
    for (size_t i = 0; i < count; i++) tl_rng_direction(&rng, n + 3 * i);
    printf("  bits variant  even mean / max / axes (deg)           odd mean / max / axes (deg)            ratio\n");
    for (uint32_t bits = 8; bits <= 16; bits += 2)
        for (int p = 0; p < 2; p++) {
            double ax_odd, ax_even;
            measure(p ? TL_NORMAL_OCT_PRECISE : TL_NORMAL_OCT, bits, n, count, odd, &ax_odd);
            measure(p ? TL_NORMAL_OCT_PRECISE_EVEN : TL_NORMAL_OCT_EVEN, bits, n, count, even, &ax_even);
            double spacing = (double)((1u << bits) - 1u) / (double)oct_top(bits);
            printf("  %4u %-8s %-11.5g %-11.5g %-11.5g   %-11.5g %-11.5g %-11.5g   %.6f\n", bits, p ? "precise" : "plain",
                   tl_stats_mean(even), even->max, ax_even, tl_stats_mean(odd), odd->max, ax_odd, spacing);
            TL_CHECK_LE(tl_stats_mean(odd), tl_stats_mean(even) * spacing * 1.001);
            TL_CHECK_LE(odd->max, even->max * spacing * 1.02);
            TL_CHECK(ax_odd == 0.0);
            TL_CHECK(ax_even > 0.0);
        }
    free(n);
    free(odd);
    free(even);
}

/* The even-grid comparison variants keep their own exhaustive idempotence. */
TL_TEST(oct_even_grid_exhaustive_decode_encode_idempotent)
{
    for (uint32_t bits = 8; bits <= 10; bits += 2) {
        uint32_t side = 1u << bits, total = side * side;
        uint32_t *codes = malloc(total * sizeof *codes), *back = malloc(total * sizeof *back);
        float *d = malloc(3 * (size_t)total * sizeof *d);
        if (!codes || !back || !d) abort();
        for (uint32_t k = 0; k < total; k++) codes[k] = k;
        size_t bad = 0;
        for (int p = 0; p < 2; p++) {
            tl_normal_encoding e = p ? TL_NORMAL_OCT_PRECISE_EVEN : TL_NORMAL_OCT_EVEN;
            tl_normal_decode_n(e, codes, d, total, bits);
            tl_normal_encode_n(e, d, back, total, bits);
            for (uint32_t k = 0; k < total; k++) bad += back[k] != k;
        }
        printf("  oct%u even grid, plain and precise: %u codes each, %zu mismatches\n", bits, total, bad);
        TL_CHECK_EQ_U(bad, 0);
        free(codes);
        free(back);
        free(d);
    }
}
