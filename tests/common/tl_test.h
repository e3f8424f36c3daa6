/* Minimal test harness: one executable holds named cases, each defined once with TL_TEST(name);
 * `exe --list` prints them and ctest runs each by name (tests/CMakeLists.txt, tl_add_test). A
 * case fails when any TL_CHECK in it fails. */
#ifndef TL_TEST_H
#define TL_TEST_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct tl_test_case {
    const char *name;
    void (*fn)(void);
    const char *file; /* where it is defined: cases run and list in source order */
    int line;
    int full; /* 1: in the `full` tier (TL_TEST_FULL), 0: the default tier */
} tl_test_case;

void tl_test_register(const tl_test_case *c);

/* Defines the test case `name` (its ctest name too) and registers it before main runs:
 *     TL_TEST(oct12_fold_edge_negative_zero) { TL_CHECK(...); }
 * A case registered conditionally sits inside an #if. TL_TEST_FULL puts the case in the `full`
 * tier (ctest label `full`: exhaustive products, full-size renders, long truths; tests/README.md),
 * which the README's test command leaves out. */
#define TL_TEST(name) TL__TEST_IN_TIER(name, 0)
#define TL_TEST_FULL(name) TL__TEST_IN_TIER(name, 1)
#define TL__TEST_IN_TIER(name, tier)                                                             \
    static void name(void);                                                                      \
    __attribute__((constructor)) static void tl__register_##name(void)                           \
    {                                                                                            \
        static const tl_test_case tl__case = {#name, name, __FILE__, __LINE__, tier};           \
        tl_test_register(&tl__case);                                                             \
    }                                                                                            \
    static void name(void)

extern int tl_test_failures;

#define TL_CHECK(cond)                                                                           \
    do {                                                                                         \
        if (!(cond)) {                                                                           \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond);             \
            tl_test_failures++;                                                                  \
        }                                                                                        \
    } while (0)

/* Like TL_CHECK but prints the values compared; for bounds. */
#define TL_CHECK_LE(a, b)                                                                        \
    do {                                                                                         \
        double tl__a = (double)(a), tl__b = (double)(b);                                         \
        if (!(tl__a <= tl__b)) {                                                                 \
            fprintf(stderr, "%s:%d: check failed: %s <= %s (%.9g > %.9g)\n", __FILE__, __LINE__, \
                    #a, #b, tl__a, tl__b);                                                       \
            tl_test_failures++;                                                                  \
        }                                                                                        \
    } while (0)

#define TL_CHECK_EQ_U(a, b)                                                                      \
    do {                                                                                         \
        unsigned long long tl__a = (unsigned long long)(a), tl__b = (unsigned long long)(b);     \
        if (tl__a != tl__b) {                                                                    \
            fprintf(stderr, "%s:%d: check failed: %s == %s (0x%llx != 0x%llx)\n", __FILE__,      \
                    __LINE__, #a, #b, tl__a, tl__b);                                             \
            tl_test_failures++;                                                                  \
        }                                                                                        \
    } while (0)

#define TL_CHECK_FINITE3(v) TL_CHECK(isfinite((v)[0]) && isfinite((v)[1]) && isfinite((v)[2]))

/* Steps of the stored formats, from their bit counts: tolerances are written with these.
 * A `bits`-bit UNORM stores k / (2^bits - 1): its largest code, and one step is 1 / that
 * (8 bits: 1/255; D24: 1/16777215). */
#define TL_UNORM_MAX(bits) ((1ull << (bits)) - 1ull)
/* FP16 keeps 10 explicit mantissa bits, so adjacent values of one binade are 2^-10 of its
 * lower end apart: one step is at most 2^-10 of the value, half a step (round to nearest) 2^-11. */
#define TL_HALF_MANTISSA_BITS 10
#define TL_HALF_REL_STEP (1.0 / (double)(1u << TL_HALF_MANTISSA_BITS))

/* Deterministic random numbers (splitmix64), so every run sees the same inputs. */
typedef struct tl_rng { unsigned long long s; } tl_rng;
static inline unsigned long long tl_rng_u64(tl_rng *r)
{
    unsigned long long z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
/* Uniform in [0,1). */
static inline double tl_rng_unit(tl_rng *r) { return (double)(tl_rng_u64(r) >> 11) * 0x1.0p-53; }
/* Uniform direction on the sphere (float). */
static inline void tl_rng_direction(tl_rng *r, float v[3])
{
    double z = 2.0 * tl_rng_unit(r) - 1.0, phi = 6.283185307179586 * tl_rng_unit(r);
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    v[0] = (float)(s * cos(phi));
    v[1] = (float)(s * sin(phi));
    v[2] = (float)z;
}

#endif
