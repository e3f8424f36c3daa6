/* GLSL/C parity of the normal encodings: oct encode, encode_precise and decode at every bit
 * budget, the extreme inputs, and RT0 (RGBA8, RGB10A2) (parity.h). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "parity.h"

/* ---- normals: oct encode / encode_precise / decode ------------------------------------------ */

static void parity_oct_encode_set(const char *name, const float *v, size_t count, uint32_t bits, bool precise)
{
    parity_env env;
    if (!env_open(&env)) return;
    uint32_t *expect = xmalloc_u32(count), *got = xmalloc_u32(count);
    if (precise)
        for (size_t i = 0; i < count; i++) expect[i] = tl_oct_encode_precise(v + 3 * i, bits);
    else
        for (size_t i = 0; i < count; i++) expect[i] = tl_oct_encode(v + 3 * i, bits);
    parity_params pp = {.bits = bits};
    if (run_op(&env, precise ? OP_OCT_ENCODE_PRECISE : OP_OCT_ENCODE, &pp, (uint32_t)count, v, 3 * count,
               NULL, 0, got, count)) {
        char what[64];
        snprintf(what, sizeof what, "%s oct%u %s", name, bits, precise ? "encode_precise" : "encode");
        TL_CHECK_EQ_U(compare_words(what, expect, got, count, 1, describe_xyz, v), 0);
    }
    free(expect);
    free(got);
    env_close(&env);
}

static void parity_oct_random_encode(uint32_t bits, bool precise)
{
    fvec a = {0};
    random_directions(&a, 0x0C7000u + bits, RANDOM_COUNT);
    parity_oct_encode_set("random", a.v, a.n / 3, bits, precise);
    free(a.v);
}

TL_TEST(parity_oct8_encode) { parity_oct_random_encode(8, false); }
TL_TEST(parity_oct10_encode) { parity_oct_random_encode(10, false); }
TL_TEST(parity_oct12_encode) { parity_oct_random_encode(12, false); }
TL_TEST(parity_oct16_encode) { parity_oct_random_encode(16, false); }
TL_TEST(parity_oct8_encode_precise) { parity_oct_random_encode(8, true); }
TL_TEST(parity_oct10_encode_precise) { parity_oct_random_encode(10, true); }
TL_TEST(parity_oct12_encode_precise) { parity_oct_random_encode(12, true); }
TL_TEST(parity_oct16_encode_precise) { parity_oct_random_encode(16, true); }

static void parity_oct_decode_codes(uint32_t bits, const uint32_t *codes, size_t count)
{
    parity_env env;
    if (!env_open(&env)) return;
    uint32_t *expect = xmalloc_u32(3 * count), *got = xmalloc_u32(3 * count);
    for (size_t i = 0; i < count; i++) {
        float n[3];
        tl_oct_decode(codes[i], bits, n);
        for (int k = 0; k < 3; k++) expect[3 * i + k] = f2u(n[k]);
    }
    parity_params pp = {.bits = bits};
    if (run_op(&env, OP_OCT_DECODE, &pp, (uint32_t)count, NULL, 0, codes, count, got, 3 * count)) {
        char what[64];
        snprintf(what, sizeof what, "oct%u decode", bits);
        TL_CHECK_EQ_U(compare_words(what, expect, got, count, 3, describe_u, codes), 0);
    }
    free(expect);
    free(got);
    env_close(&env);
}

/* Every code of the budget when it has at most 2^20, else random codes plus the square's edges
 * and corners; codes carry random garbage above bit 2*bits (decode ignores it). */
static void parity_oct_decode(uint32_t bits)
{
    uvec c = {0};
    uint32_t max = (1u << bits) - 1u;
    tl_rng rng = {0xDEC0DEu + bits};
    if (bits <= 10) {
        for (uint32_t k = 0; k <= (max << bits | max); k++) upush(&c, k);
    } else {
        for (uint32_t i = 0; i < RANDOM_COUNT; i++) upush(&c, (uint32_t)tl_rng_u64(&rng));
        const uint32_t edge[] = {0, 1, max / 2, max / 2 + 1, max - 1, max};
        for (size_t i = 0; i < 6; i++)
            for (size_t j = 0; j < 6; j++) upush(&c, edge[i] | edge[j] << bits);
        for (uint32_t k = 0; k <= max; k += 7) {
            upush(&c, k);
            upush(&c, k | max << bits);
            upush(&c, k << bits);
            upush(&c, max | k << bits);
        }
    }
    if (bits < 16)
        for (size_t i = 0; i < c.n; i += 5) c.v[i] |= (uint32_t)tl_rng_u64(&rng) << (2 * bits);
    parity_oct_decode_codes(bits, c.v, c.n);
    free(c.v);
}

TL_TEST(parity_oct8_decode_all_codes) { parity_oct_decode(8); }
TL_TEST(parity_oct10_decode_all_codes) { parity_oct_decode(10); }
TL_TEST(parity_oct12_decode) { parity_oct_decode(12); }
TL_TEST(parity_oct16_decode) { parity_oct_decode(16); }

/* Extreme inputs at every budget, both encoders, and tl_normal_sanitize itself. */
TL_TEST(parity_oct_extreme_cases)
{
    fvec a = {0};
    extreme_normals(&a);
    size_t count = a.n / 3;
    static const uint32_t budgets[] = {8, 10, 12, 16};
    for (size_t b = 0; b < 4; b++) {
        parity_oct_encode_set("extreme", a.v, count, budgets[b], false);
        parity_oct_encode_set("extreme", a.v, count, budgets[b], true);
    }
    parity_env env;
    if (env_open(&env)) {
        uint32_t *expect = xmalloc_u32(3 * count), *got = xmalloc_u32(3 * count);
        for (size_t i = 0; i < count; i++) {
            float n[3];
            tl_normal_sanitize(a.v + 3 * i, n);
            for (int k = 0; k < 3; k++) expect[3 * i + k] = f2u(n[k]);
        }
        if (run_op(&env, OP_NORMAL_SANITIZE, NULL, (uint32_t)count, a.v, a.n, NULL, 0, got, 3 * count))
            TL_CHECK_EQ_U(compare_words("extreme normal_sanitize", expect, got, count, 3, describe_xyz, a.v),
                          0);
        free(expect);
        free(got);
        env_close(&env);
    }
    free(a.v);
}

/* ---- RT0 ------------------------------------------------------------------------------------ */

/* The odd grid in GLSL: the axes (every signed zero) encoded by the shader, both encoders, every
 * budget, decode in the shader to exactly the axis; -Z to exactly (0, 0, -1). */
TL_TEST(parity_oct_axes_exact)
{
    static const float axes[7][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, 0, 0}};
    static const float expect[7][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, 0, 1}};
    fvec a = {0};
    for (int k = 0; k < 7; k++)
        for (int s = 0; s < 8; s++) /* every sign of every zero component */
            fpush3(&a, axes[k][0] == 0.0f && (s & 1) ? -0.0f : axes[k][0], axes[k][1] == 0.0f && (s & 2) ? -0.0f : axes[k][1],
                   axes[k][2] == 0.0f && (s & 4) ? -0.0f : axes[k][2]);
    size_t count = a.n / 3, bad = 0;
    parity_env env;
    if (!env_open(&env)) return;
    uint32_t *codes = xmalloc_u32(count), *dec = xmalloc_u32(3 * count);
    for (uint32_t bits = TL_OCT_MIN_BITS; bits <= TL_OCT_MAX_BITS; bits++)
        for (int p = 0; p < 2; p++) {
            parity_params pp = {.bits = bits};
            if (!run_op(&env, p ? OP_OCT_ENCODE_PRECISE : OP_OCT_ENCODE, &pp, (uint32_t)count, a.v, a.n, NULL, 0,
                        codes, count) ||
                !run_op(&env, OP_OCT_DECODE, &pp, (uint32_t)count, NULL, 0, codes, count, dec, 3 * count))
                continue;
            for (size_t i = 0; i < count; i++) {
                const float *e = expect[i / 8];
                int ok = u2f(dec[3 * i]) == e[0] && u2f(dec[3 * i + 1]) == e[1] && u2f(dec[3 * i + 2]) == e[2];
                if (!ok && bad++ < 6)
                    fprintf(stderr, "oct%u %s: (%g, %g, %g) -> 0x%x -> (%a, %a, %a)\n", bits, p ? "precise" : "plain",
                            (double)a.v[3 * i], (double)a.v[3 * i + 1], (double)a.v[3 * i + 2], codes[i],
                            (double)u2f(dec[3 * i]), (double)u2f(dec[3 * i + 1]), (double)u2f(dec[3 * i + 2]));
            }
        }
    printf("%-40s %8zu axis inputs x 9 budgets x 2 encoders, %zu not exact\n", "GLSL oct axes", count, bad);
    TL_CHECK_EQ_U(bad, 0);
    free(codes);
    free(dec);
    free(a.v);
    env_close(&env);
}

/* Random directions with gloss in [-0.25, 1.25], then every extreme normal with a few special
 * glosses (0, 1, out of range, NaN, Inf). */
static void rt0_inputs(fvec *a, uint64_t seed)
{
    tl_rng rng = {seed};
    for (uint32_t i = 0; i < RANDOM_COUNT; i++) {
        float v[3];
        tl_rng_direction(&rng, v);
        fpush3(a, v[0], v[1], v[2]);
        fpush(a, (float)(1.5 * tl_rng_unit(&rng) - 0.25));
    }
    fvec e = {0};
    extreme_normals(&e);
    const float glosses[] = {0.0f, 1.0f, 0.5f, -0.0f, -1.0f, 2.0f, NAN, INFINITY, -INFINITY, 0x1.0p-149f};
    for (size_t i = 0; i < e.n / 3; i++) {
        fpush3(a, e.v[3 * i], e.v[3 * i + 1], e.v[3 * i + 2]);
        fpush(a, glosses[i % (sizeof glosses / sizeof glosses[0])]);
    }
    free(e.v);
}

static void describe_xyzg(size_t i, const void *ctx)
{
    const float *v = (const float *)ctx + 4 * i;
    fprintf(stderr, " for (%a, %a, %a) gloss %a", (double)v[0], (double)v[1], (double)v[2], (double)v[3]);
}

TL_TEST(parity_rt0_rgba8)
{
    parity_env env;
    if (!env_open(&env)) return;
    fvec a = {0};
    rt0_inputs(&a, 0x47A8u);
    size_t count = a.n / 4;
    uint32_t *expect = xmalloc_u32(4 * count), *got = xmalloc_u32(4 * count);
    for (size_t i = 0; i < count; i++) {
        uint8_t t[4];
        tl_rt0_encode_rgba8(a.v + 4 * i, a.v[4 * i + 3], t);
        for (int k = 0; k < 4; k++) expect[4 * i + k] = t[k];
    }
    if (run_op(&env, OP_RT0_RGBA8_ENCODE, NULL, (uint32_t)count, a.v, a.n, NULL, 0, got, 4 * count))
        TL_CHECK_EQ_U(compare_words("rt0_encode_rgba8 bytes", expect, got, count, 4, describe_xyzg, a.v),
                      0);
    /* Decode: every texel the encoder produced plus random texels (the 12-bit decode core is
     * also covered by parity_oct12_decode). */
    uvec t = {0};
    tl_rng rng = {0x47A9u};
    for (size_t i = 0; i < count; i++)
        upush(&t, expect[4 * i] | expect[4 * i + 1] << 8 | expect[4 * i + 2] << 16 | expect[4 * i + 3] << 24);
    for (uint32_t i = 0; i < RANDOM_COUNT; i++) upush(&t, (uint32_t)tl_rng_u64(&rng));
    upush(&t, 0u);
    upush(&t, 0xFFFFFFFFu);
    uint32_t *dexp = xmalloc_u32(4 * t.n), *dgot = xmalloc_u32(4 * t.n);
    for (size_t i = 0; i < t.n; i++) {
        uint8_t b[4] = {(uint8_t)t.v[i], (uint8_t)(t.v[i] >> 8), (uint8_t)(t.v[i] >> 16), (uint8_t)(t.v[i] >> 24)};
        float n[3], g;
        tl_rt0_decode_rgba8(b, n, &g);
        for (int k = 0; k < 3; k++) dexp[4 * i + k] = f2u(n[k]);
        dexp[4 * i + 3] = f2u(g);
    }
    if (run_op(&env, OP_RT0_RGBA8_DECODE, NULL, (uint32_t)t.n, NULL, 0, t.v, t.n, dgot, 4 * t.n))
        TL_CHECK_EQ_U(compare_words("rt0_decode_rgba8", dexp, dgot, t.n, 4, describe_u, t.v), 0);
    free(dexp);
    free(dgot);
    free(t.v);
    free(expect);
    free(got);
    free(a.v);
    env_close(&env);
}

TL_TEST(parity_rt0_rgb10a2)
{
    parity_env env;
    if (!env_open(&env)) return;
    fvec a = {0};
    rt0_inputs(&a, 0x10A2u);
    size_t count = a.n / 4;
    uvec flags = {0};
    tl_rng rng = {0x10A3u};
    for (size_t i = 0; i < count; i++) upush(&flags, (uint32_t)tl_rng_u64(&rng)); /* masked to 2 bits */
    uint32_t *expect = xmalloc_u32(count), *got = xmalloc_u32(count);
    for (size_t i = 0; i < count; i++) expect[i] = tl_rt0_encode_rgb10a2(a.v + 4 * i, a.v[4 * i + 3], flags.v[i]);
    if (run_op(&env, OP_RT0_RGB10A2_ENCODE, NULL, (uint32_t)count, a.v, a.n, flags.v, flags.n, got, count))
        TL_CHECK_EQ_U(compare_words("rt0_encode_rgb10a2 words", expect, got, count, 1, describe_xyzg, a.v),
                      0);
    /* Decode: the encoder's words and random words. */
    uvec t = {0};
    for (size_t i = 0; i < count; i++) upush(&t, expect[i]);
    for (uint32_t i = 0; i < RANDOM_COUNT; i++) upush(&t, (uint32_t)tl_rng_u64(&rng));
    uint32_t *dexp = xmalloc_u32(4 * t.n), *dgot = xmalloc_u32(4 * t.n);
    for (size_t i = 0; i < t.n; i++) {
        float n[3], g;
        uint32_t f;
        tl_rt0_decode_rgb10a2(t.v[i], n, &g, &f);
        for (int k = 0; k < 3; k++) dexp[4 * i + k] = f2u(n[k]);
        dexp[4 * i + 3] = f2u(g);
    }
    if (run_op(&env, OP_RT0_RGB10A2_DECODE, NULL, (uint32_t)t.n, NULL, 0, t.v, t.n, dgot, 4 * t.n))
        TL_CHECK_EQ_U(compare_words("rt0_decode_rgb10a2", dexp, dgot, t.n, 4, describe_u, t.v), 0);
    free(dexp);
    free(dgot);
    free(t.v);
    free(flags.v);
    free(expect);
    free(got);
    free(a.v);
    env_close(&env);
}
