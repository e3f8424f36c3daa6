/* Tests of the pure-C metrics: reference data where it is published, otherwise cases whose
 * answer is computed independently here. */
#include <float.h>
#include <stdint.h>

#include "thinlight/metrics.h"
#include "tl_test.h"

/* Table 1 of G. Sharma, W. Wu and E. N. Dalal, "The CIEDE2000 color-difference formula:
 * implementation notes, supplementary test data, and mathematical observations", Color Research
 * and Application 30(1), 21-30, 2005: L1 a1 b1, L2 a2 b2, published dE00 (4 decimals). */
static const double tl__sharma[34][7] = {
    {50.0000, 2.6772, -79.7751, 50.0000, 0.0000, -82.7485, 2.0425},
    {50.0000, 3.1571, -77.2803, 50.0000, 0.0000, -82.7485, 2.8615},
    {50.0000, 2.8361, -74.0200, 50.0000, 0.0000, -82.7485, 3.4412},
    {50.0000, -1.3802, -84.2814, 50.0000, 0.0000, -82.7485, 1.0000},
    {50.0000, -1.1848, -84.8006, 50.0000, 0.0000, -82.7485, 1.0000},
    {50.0000, -0.9009, -85.5211, 50.0000, 0.0000, -82.7485, 1.0000},
    {50.0000, 0.0000, 0.0000, 50.0000, -1.0000, 2.0000, 2.3669},
    {50.0000, -1.0000, 2.0000, 50.0000, 0.0000, 0.0000, 2.3669},
    {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0009, 7.1792},
    {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0010, 7.1792},
    {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0011, 7.2195},
    {50.0000, 2.4900, -0.0010, 50.0000, -2.4900, 0.0012, 7.2195},
    {50.0000, -0.0010, 2.4900, 50.0000, 0.0009, -2.4900, 4.8045},
    {50.0000, -0.0010, 2.4900, 50.0000, 0.0010, -2.4900, 4.8045},
    {50.0000, -0.0010, 2.4900, 50.0000, 0.0011, -2.4900, 4.7461},
    {50.0000, 2.5000, 0.0000, 50.0000, 0.0000, -2.5000, 4.3065},
    {50.0000, 2.5000, 0.0000, 73.0000, 25.0000, -18.0000, 27.1492},
    {50.0000, 2.5000, 0.0000, 61.0000, -5.0000, 29.0000, 22.8977},
    {50.0000, 2.5000, 0.0000, 56.0000, -27.0000, -3.0000, 31.9030},
    {50.0000, 2.5000, 0.0000, 58.0000, 24.0000, 15.0000, 19.4535},
    {50.0000, 2.5000, 0.0000, 50.0000, 3.1736, 0.5854, 1.0000},
    {50.0000, 2.5000, 0.0000, 50.0000, 3.2972, 0.0000, 1.0000},
    {50.0000, 2.5000, 0.0000, 50.0000, 1.8634, 0.5757, 1.0000},
    {50.0000, 2.5000, 0.0000, 50.0000, 3.2592, 0.3350, 1.0000},
    {60.2574, -34.0099, 36.2677, 60.4626, -34.1751, 39.4387, 1.2644},
    {63.0109, -31.0961, -5.8663, 62.8187, -29.7946, -4.0864, 1.2630},
    {61.2901, 3.7196, -5.3901, 61.4292, 2.2480, -4.9620, 1.8731},
    {35.0831, -44.1164, 3.7933, 35.0232, -40.0716, 1.5901, 1.8645},
    {22.7233, 20.0904, -46.6940, 23.0331, 14.9730, -42.5619, 2.0373},
    {36.4612, 47.8580, 18.3852, 36.2715, 50.5065, 21.2231, 1.4146},
    {90.8027, -2.0831, 1.4410, 91.1528, -1.6435, 0.0447, 1.4441},
    {90.9257, -0.5406, -0.9208, 88.6381, -0.8985, -0.7239, 1.5381},
    {6.7747, -0.2908, -2.4247, 5.8714, -0.0985, -2.2286, 0.6377},
    {2.0776, 0.0795, -1.1350, 0.9033, -0.0636, -0.5514, 0.9082},
};

TL_TEST(ciede2000_sharma_reference_pairs)
{
    for (size_t i = 0; i < 34; i++) {
        const double *r = tl__sharma[i];
        /* Both orders: the formula is symmetric, and pairs 7/8 and the 180-degree ties of
         * pairs 10 and 14 check that the hue edge cases do not depend on the order. */
        double d12 = tl_ciede2000(r, r + 3), d21 = tl_ciede2000(r + 3, r);
        if (!(fabs(d12 - r[6]) <= 1e-4) || !(fabs(d21 - r[6]) <= 1e-4))
            fprintf(stderr, "pair %zu: %.6f / %.6f, published %.4f\n", i + 1, d12, d21, r[6]);
        TL_CHECK_LE(fabs(d12 - r[6]), 1e-4);
        TL_CHECK_LE(fabs(d21 - r[6]), 1e-4);
    }
    double lab[3] = {50.0, 10.0, -20.0};
    TL_CHECK(tl_ciede2000(lab, lab) == 0.0);
    TL_CHECK(isnan(tl_ciede2000(NULL, lab)));
    TL_CHECK(isnan(tl_ciede2000(lab, NULL)));
    double nan_lab[3] = {50.0, NAN, 0.0};
    TL_CHECK(isnan(tl_ciede2000(lab, nan_lab)));
}

TL_TEST(srgb_to_lab_white_black_primaries)
{
    double lab[3];
    tl_srgb_to_lab((const double[3]){1.0, 1.0, 1.0}, lab);
    TL_CHECK_LE(fabs(lab[0] - 100.0), 1e-3);
    TL_CHECK_LE(fabs(lab[1]), 1e-3);
    TL_CHECK_LE(fabs(lab[2]), 1e-3);

    tl_srgb_to_lab((const double[3]){0.0, 0.0, 0.0}, lab);
    TL_CHECK(lab[0] == 0.0 && lab[1] == 0.0 && lab[2] == 0.0);

    /* Widely tabulated sRGB primaries (D65). */
    static const double prim[3][6] = {
        {1, 0, 0, 53.24, 80.09, 67.20},
        {0, 1, 0, 87.73, -86.18, 83.18},
        {0, 0, 1, 32.30, 79.19, -107.86},
    };
    for (size_t i = 0; i < 3; i++) {
        tl_srgb_to_lab(prim[i], lab);
        for (size_t c = 0; c < 3; c++) TL_CHECK_LE(fabs(lab[c] - prim[i][3 + c]), 0.05);
    }

    /* Mid grey on both sides of the curve's knee: neutral, and L* rising with the input. */
    double prev = -1.0;
    for (double v = 0.0; v <= 1.0; v += 1.0 / 64.0) {
        tl_srgb_to_lab((const double[3]){v, v, v}, lab);
        TL_CHECK_LE(fabs(lab[1]) + fabs(lab[2]), 1e-3);
        TL_CHECK(lab[0] > prev);
        prev = lab[0];
    }
    /* sRGB 0.5 is linear 0.2140 (the exact curve; a 2.2 power gives 0.2176): L* = 53.389. */
    tl_srgb_to_lab((const double[3]){0.5, 0.5, 0.5}, lab);
    TL_CHECK_LE(fabs(lab[0] - 53.389), 2e-3);

    lab[0] = lab[1] = lab[2] = 1.0;
    tl_srgb_to_lab(NULL, lab);
    TL_CHECK(isnan(lab[0]) && isnan(lab[1]) && isnan(lab[2]));
    tl_srgb_to_lab((const double[3]){1.0, 1.0, 1.0}, NULL); /* must not crash */
}

TL_TEST(angle_deg_tiny_and_opposite)
{
    /* 1e-6 degrees: the exact angle between these float vectors is atan(y), y rounded. */
    float y = (float)tan(1e-6 * 3.14159265358979323846 / 180.0);
    float a[3] = {1.0f, 0.0f, 0.0f}, b[3] = {1.0f, y, 0.0f};
    double want = atan((double)y) * 180.0 / 3.14159265358979323846;
    TL_CHECK_LE(fabs(want - 1e-6), 1e-8);
    TL_CHECK_LE(fabs(tl_angle_deg(a, b) - want), 0.01 * want);
    TL_CHECK_LE(fabs(tl_angle_deg(b, a) - want), 0.01 * want);
    /* Same tiny angle on a non-axis, non-unit pair: the acos form would give 0 here. */
    float c[3] = {3.0f, 4.0f, 0.0f}, d[3] = {3.0f, 4.0f, 5e-7f * 5.0f};
    double want_cd = atan((double)d[2] / 5.0) * 180.0 / 3.14159265358979323846;
    TL_CHECK_LE(fabs(tl_angle_deg(c, d) - want_cd), 0.01 * want_cd);

    TL_CHECK(tl_angle_deg(a, a) == 0.0);
    float up[3] = {0.0f, 0.0f, 5.0f}, down[3] = {0.0f, 0.0f, -0.25f}, x2[3] = {2.0f, 0.0f, 0.0f};
    TL_CHECK_LE(fabs(tl_angle_deg(x2, up) - 90.0), 1e-12);
    TL_CHECK_LE(fabs(tl_angle_deg(up, down) - 180.0), 1e-12);
    float diag[3] = {7.0f, 7.0f, 0.0f};
    TL_CHECK_LE(fabs(tl_angle_deg(x2, diag) - 45.0), 1e-12);

    float zero[3] = {0.0f, 0.0f, 0.0f}, nan3[3] = {NAN, 0.0f, 1.0f}, inf3[3] = {INFINITY, 0.0f, 0.0f};
    TL_CHECK(tl_angle_deg(zero, up) == 180.0);
    TL_CHECK(tl_angle_deg(up, zero) == 180.0);
    TL_CHECK(tl_angle_deg(nan3, up) == 180.0);
    TL_CHECK(tl_angle_deg(up, nan3) == 180.0);
    TL_CHECK(tl_angle_deg(inf3, up) == 180.0);
    TL_CHECK(tl_angle_deg(NULL, up) == 180.0);
    TL_CHECK(tl_angle_deg(up, NULL) == 180.0);

    /* Denormal and huge components still give the right angle (no underflow or overflow). */
    float tiny_x[3] = {1e-44f, 0.0f, 0.0f}, huge_y[3] = {0.0f, 3e38f, 0.0f};
    TL_CHECK_LE(fabs(tl_angle_deg(tiny_x, huge_y) - 90.0), 1e-12);

    /* Random directions against the acos form where that is well conditioned. */
    tl_rng rng = {42};
    for (int i = 0; i < 1000; i++) {
        float u[3], v[3];
        tl_rng_direction(&rng, u);
        tl_rng_direction(&rng, v);
        double nu = sqrt((double)u[0] * u[0] + (double)u[1] * u[1] + (double)u[2] * u[2]);
        double nv = sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]);
        double cs = ((double)u[0] * v[0] + (double)u[1] * v[1] + (double)u[2] * v[2]) / (nu * nv);
        if (fabs(cs) > 0.9) continue;
        TL_CHECK_LE(fabs(tl_angle_deg(u, v) - acos(cs) * 180.0 / 3.14159265358979323846), 1e-9);
    }
}

TL_TEST(image_compare_psnr_known)
{
    enum { N = 256 };
    float a[N], b[N];
    /* Offset 1/4 is exact in float, so mse = 1/16 and psnr = 10 log10(16). */
    for (size_t i = 0; i < N; i++) {
        a[i] = (float)i / N;
        b[i] = a[i] + 0.25f;
    }
    tl_image_error e;
    TL_CHECK(tl_image_compare(a, b, N, 1.0, &e) == TL_OK);
    TL_CHECK(e.mse == 0.0625);
    TL_CHECK(e.mean_abs == 0.25);
    TL_CHECK(e.max_abs == 0.25);
    TL_CHECK_LE(fabs(e.psnr_db - 10.0 * log10(16.0)), 1e-12);
    TL_CHECK_EQ_U(e.count, N);
    TL_CHECK_EQ_U(e.nonfinite, 0);
    /* Peak 2 adds 20 log10(2) dB. */
    TL_CHECK(tl_image_compare(a, b, N, 2.0, &e) == TL_OK);
    TL_CHECK_LE(fabs(e.psnr_db - 10.0 * log10(64.0)), 1e-12);

    /* Identical images. */
    TL_CHECK(tl_image_compare(a, a, N, 1.0, &e) == TL_OK);
    TL_CHECK(e.mse == 0.0 && e.mean_abs == 0.0 && e.max_abs == 0.0);
    TL_CHECK(e.psnr_db == 999.0);

    /* One error of 1/2 among N: mse = 1/(4N), mean = 1/(2N), max = 1/2. */
    memcpy(b, a, sizeof a);
    b[17] += 0.5f;
    TL_CHECK(tl_image_compare(a, b, N, 1.0, &e) == TL_OK);
    TL_CHECK(e.mse == 0.25 / N && e.mean_abs == 0.5 / N && e.max_abs == 0.5);
    TL_CHECK_LE(fabs(e.psnr_db - 10.0 * log10(4.0 * N)), 1e-12);

    /* NaN and Inf on either side are counted and excluded from every other field. */
    b[3] = NAN;
    a[5] = INFINITY;
    b[6] = -INFINITY;
    a[7] = NAN;
    b[7] = NAN;
    TL_CHECK(tl_image_compare(a, b, N, 1.0, &e) == TL_OK);
    TL_CHECK_EQ_U(e.nonfinite, 4);
    TL_CHECK_EQ_U(e.count, N);
    TL_CHECK(e.mse == 0.25 / (N - 4) && e.max_abs == 0.5);
    TL_CHECK(isfinite(e.psnr_db) && isfinite(e.mean_abs));

    /* Nothing finite to compare: not a perfect score. */
    float n1[2] = {NAN, INFINITY};
    TL_CHECK(tl_image_compare(n1, n1, 2, 1.0, &e) == TL_OK);
    TL_CHECK_EQ_U(e.nonfinite, 2);
    TL_CHECK(e.psnr_db == 0.0 && e.mse == 0.0);

    /* Huge finite differences do not overflow. */
    float big1[1] = {FLT_MAX}, big2[1] = {-FLT_MAX};
    TL_CHECK(tl_image_compare(big1, big2, 1, 1.0, &e) == TL_OK);
    TL_CHECK(isfinite(e.mse) && e.max_abs == 2.0 * FLT_MAX);

    TL_CHECK(tl_image_compare(NULL, b, N, 1.0, &e) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_image_compare(a, NULL, N, 1.0, &e) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_image_compare(a, b, N, 1.0, NULL) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_image_compare(a, b, 0, 1.0, &e) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_image_compare(a, b, N, 0.0, &e) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_image_compare(a, b, N, NAN, &e) == TL_ERROR_INVALID_ARGUMENT);
}

TL_TEST(image_compare_u8_known)
{
    enum { N = 300 };
    uint8_t a[N], b[N];
    for (size_t i = 0; i < N; i++) {
        a[i] = (uint8_t)(i % 256);
        b[i] = a[i];
    }
    tl_image_error e;
    TL_CHECK(tl_image_compare_u8(a, b, N, &e) == TL_OK);
    TL_CHECK(e.mse == 0.0 && e.psnr_db == 999.0 && e.max_abs == 0.0);
    TL_CHECK_EQ_U(e.count, N);

    /* Off by one step everywhere, in both directions (no unsigned wrap-around):
     * mse = 1, psnr = 20 log10(255). */
    for (size_t i = 0; i < N; i++) b[i] = (uint8_t)(a[i] == 255 ? 254 : a[i] + 1);
    TL_CHECK(tl_image_compare_u8(a, b, N, &e) == TL_OK);
    TL_CHECK(e.mse == 1.0 && e.mean_abs == 1.0 && e.max_abs == 1.0);
    TL_CHECK_LE(fabs(e.psnr_db - 20.0 * log10(255.0)), 1e-12);
    TL_CHECK(tl_image_compare_u8(b, a, N, &e) == TL_OK);
    TL_CHECK(e.mse == 1.0);

    /* Black against white: the worst case, 0 dB. */
    uint8_t black[4] = {0, 0, 0, 0}, white[4] = {255, 255, 255, 255};
    TL_CHECK(tl_image_compare_u8(black, white, 4, &e) == TL_OK);
    TL_CHECK(e.mse == 65025.0 && e.max_abs == 255.0 && e.mean_abs == 255.0);
    TL_CHECK_LE(fabs(e.psnr_db), 1e-12);
    TL_CHECK_EQ_U(e.nonfinite, 0);

    /* One pixel off by 10 among 4: mse 25, mean 2.5. */
    uint8_t c[4] = {10, 20, 30, 40}, d[4] = {10, 30, 30, 40};
    TL_CHECK(tl_image_compare_u8(c, d, 4, &e) == TL_OK);
    TL_CHECK(e.mse == 25.0 && e.mean_abs == 2.5 && e.max_abs == 10.0);
    TL_CHECK_LE(fabs(e.psnr_db - 10.0 * log10(65025.0 / 25.0)), 1e-12);

    TL_CHECK(tl_image_compare_u8(NULL, b, N, &e) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_image_compare_u8(a, NULL, N, &e) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_image_compare_u8(a, b, N, NULL) == TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_image_compare_u8(a, b, 0, &e) == TL_ERROR_INVALID_ARGUMENT);

    /* tl_relative_error lives beside the image measures. */
    TL_CHECK(tl_relative_error(0.0, 0.0) == 0.0);
    TL_CHECK(tl_relative_error(1.5, 1.5) == 0.0);
    TL_CHECK(tl_relative_error(1.1, 1.0) > 0.0999999 && tl_relative_error(1.1, 1.0) < 0.1000001);
    TL_CHECK(tl_relative_error(-3.0, -2.0) == 0.5);
    TL_CHECK(tl_relative_error(1.0, 0.0) == DBL_MAX);
    TL_CHECK(tl_relative_error(1e300, 1e-300) == DBL_MAX);
    TL_CHECK(isnan(tl_relative_error(NAN, 1.0)));
}

static int tl__cmp_double(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* Large enough for 10^5 values; static so the test does not need a big stack. */
static double tl__values[100000];
static tl_stats tl__s, tl__s2, tl__s3;

TL_TEST(stats_mean_max_percentile)
{
    enum { N = 100000 };
    const double bin_rel = exp2(1.0 / TL_STATS_BINS_PER_OCTAVE) - 1.0;
    tl_rng rng = {12345};
    /* Spread over 12 octaves, so that many bins and octave boundaries are exercised. */
    for (size_t i = 0; i < N; i++) tl__values[i] = exp2(12.0 * tl_rng_unit(&rng) - 10.0);

    tl_stats *s = &tl__s;
    tl_stats_reset(s);
    tl_stats_add_n(s, tl__values, N);
    TL_CHECK_EQ_U(s->count, N);
    TL_CHECK_EQ_U(s->rejected, 0);

    long double sum = 0.0L;
    for (size_t i = 0; i < N; i++) sum += tl__values[i];
    double mean = (double)(sum / N);
    TL_CHECK_LE(fabs(tl_stats_mean(s) - mean), 1e-12 * mean);

    qsort(tl__values, N, sizeof tl__values[0], tl__cmp_double);
    TL_CHECK(s->min == tl__values[0] && s->max == tl__values[N - 1]);
    TL_CHECK(tl_stats_percentile(s, 0.0) == tl__values[0]);
    TL_CHECK(tl_stats_percentile(s, 1.0) == tl__values[N - 1]);
    static const double ps[] = {1e-5, 0.001, 0.01, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99, 0.999, 0.99999};
    for (size_t i = 0; i < sizeof ps / sizeof ps[0]; i++) {
        double k = ceil(ps[i] * N);
        double exact = tl__values[(size_t)(k < 1 ? 1 : k) - 1];
        double got = tl_stats_percentile(s, ps[i]);
        /* The bin width, with a margin only for the rounding of the edges themselves. */
        TL_CHECK_LE(fabs(got - exact), bin_rel * (1.0 + 1e-12) * exact);
    }
    /* A coarse check against a wrong bin: more than a bin width off would show here. */
    for (double p = 0.005; p < 1.0; p += 0.01) {
        double exact = tl__values[(size_t)ceil(p * N) - 1];
        TL_CHECK_LE(fabs(tl_stats_percentile(s, p) - exact), bin_rel * (1.0 + 1e-12) * exact);
    }

    /* Merge of two halves equals adding everything to one. */
    tl_stats *a = &tl__s2, *b = &tl__s3;
    tl_stats_reset(a);
    tl_stats_reset(b);
    tl_stats_add_n(a, tl__values, N / 3);
    tl_stats_add_n(b, tl__values + N / 3, N - N / 3);
    tl_stats_add(b, -1.0);
    tl_stats_merge(a, b);
    TL_CHECK_EQ_U(a->count, s->count);
    TL_CHECK_EQ_U(a->rejected, 1);
    TL_CHECK(a->min == s->min && a->max == s->max);
    TL_CHECK_LE(fabs(a->sum - s->sum), 1e-12 * s->sum);
    TL_CHECK(memcmp(a->bins, s->bins, sizeof s->bins) == 0);
    TL_CHECK(tl_stats_percentile(a, 0.99) == tl_stats_percentile(s, 0.99));
    /* Merging an empty one changes nothing; merging into an empty one copies. */
    tl_stats_reset(b);
    tl_stats_merge(a, b);
    TL_CHECK_EQ_U(a->count, N);
    TL_CHECK(a->min == s->min);
    tl_stats_merge(b, s);
    TL_CHECK(b->min == s->min && b->max == s->max && b->count == s->count);

    /* Rejected values are counted and change nothing else. */
    tl_stats_reset(a);
    tl_stats_add(a, 2.0);
    tl_stats_add(a, NAN);
    tl_stats_add(a, -1e-300);
    tl_stats_add(a, -INFINITY);
    tl_stats_add(a, 4.0);
    TL_CHECK_EQ_U(a->count, 2);
    TL_CHECK_EQ_U(a->rejected, 3);
    TL_CHECK(tl_stats_mean(a) == 3.0 && a->min == 2.0 && a->max == 4.0);

    /* Empty: zeros, whether reset or zero-initialised. */
    tl_stats_reset(a);
    TL_CHECK(tl_stats_mean(a) == 0.0 && tl_stats_percentile(a, 0.99) == 0.0);
    memset(b, 0, sizeof *b);
    TL_CHECK(tl_stats_mean(b) == 0.0 && tl_stats_percentile(b, 0.5) == 0.0);
    tl_stats_add(b, 5.0); /* a zero-initialised struct must not keep min = 0 */
    TL_CHECK(b->min == 5.0 && b->max == 5.0 && tl_stats_percentile(b, 0.5) == 5.0);
    TL_CHECK(tl_stats_mean(NULL) == 0.0 && tl_stats_percentile(NULL, 0.5) == 0.0);
    tl_stats_add(NULL, 1.0);
    tl_stats_add_n(a, NULL, 10);
    tl_stats_merge(NULL, a);
    tl_stats_merge(a, NULL);
    tl_stats_reset(NULL);
    TL_CHECK_EQ_U(a->count, 0);
}

TL_TEST(stats_extreme_values)
{
    tl_stats *s = &tl__s;
    tl_stats_reset(s);
    const size_t last = TL_STATS_BINS - 1;
    /* Bin 0 holds 0, -0, denormals and everything below 2^-64. */
    tl_stats_add(s, 0.0);
    tl_stats_add(s, -0.0);
    tl_stats_add(s, 4.9e-324);
    tl_stats_add(s, DBL_MIN);
    tl_stats_add(s, nextafter(ldexp(1.0, -64), 0.0));
    TL_CHECK_EQ_U(s->bins[0], 5);
    TL_CHECK_EQ_U(s->rejected, 0);
    /* 2^-64 opens bin 1; 2^64 opens the last bin, which also takes 1e300, DBL_MAX and Inf. */
    tl_stats_add(s, ldexp(1.0, -64));
    TL_CHECK_EQ_U(s->bins[1], 1);
    tl_stats_add(s, nextafter(ldexp(1.0, 64), 0.0));
    TL_CHECK_EQ_U(s->bins[last - 1], 1);
    tl_stats_add(s, ldexp(1.0, 64));
    tl_stats_add(s, 1e300);
    tl_stats_add(s, DBL_MAX);
    TL_CHECK_EQ_U(s->bins[last], 3);
    TL_CHECK(isfinite(tl_stats_percentile(s, 0.99)));
    tl_stats_add(s, INFINITY);
    TL_CHECK_EQ_U(s->bins[last], 4);
    TL_CHECK(s->max == INFINITY && s->min == 0.0);
    TL_CHECK_EQ_U(s->count, 11);

    /* Powers of two open their octave's first bin; the value just below is in the bin before. */
    for (int e = TL_STATS_OCTAVE_MIN; e < TL_STATS_OCTAVE_MAX; e++) {
        tl_stats_reset(s);
        tl_stats_add(s, ldexp(1.0, e));
        size_t want = 1 + (size_t)(e - TL_STATS_OCTAVE_MIN) * TL_STATS_BINS_PER_OCTAVE;
        TL_CHECK_EQ_U(s->bins[want], 1);
        tl_stats_add(s, nextafter(ldexp(1.0, e), 0.0));
        TL_CHECK_EQ_U(s->bins[want - 1], 1);
    }
    /* Every sub-bin edge 2^(j/64) (as exp2 rounds it) opens bin j; the double below it is in
     * bin j - 1, so no value sits outside the edges its percentile is estimated from. */
    const size_t octave0 = 1 + (size_t)(-TL_STATS_OCTAVE_MIN) * TL_STATS_BINS_PER_OCTAVE;
    for (int j = 1; j < TL_STATS_BINS_PER_OCTAVE; j++) {
        double edge = exp2((double)j / TL_STATS_BINS_PER_OCTAVE);
        for (int e = -3; e <= 3; e++) {
            tl_stats_reset(s);
            tl_stats_add(s, ldexp(edge, e));
            tl_stats_add(s, ldexp(nextafter(edge, 0.0), e));
            size_t bin = (size_t)((long)octave0 + (long)e * TL_STATS_BINS_PER_OCTAVE + j);
            TL_CHECK_EQ_U(s->bins[bin], 1);
            TL_CHECK_EQ_U(s->bins[bin - 1], 1);
        }
    }

    /* Percentiles stay within [min, max] however the values sit in the outer bins. */
    static const double sets[][4] = {
        {0.0, 0.0, 0.0, 0.0},
        {4.9e-324, 4.9e-324, 1e-310, 1e-300},
        {1e300, 1e300, 1e300, 1e300},
        {1e20, 1e25, 1e300, DBL_MAX},
        {0.0, 1e-30, 1.0, 1e30},
        {INFINITY, INFINITY, INFINITY, INFINITY},
        {1.0, 2.0, 3.0, INFINITY},
    };
    for (size_t i = 0; i < sizeof sets / sizeof sets[0]; i++) {
        tl_stats_reset(s);
        tl_stats_add_n(s, sets[i], 4);
        for (double p = 0.0; p <= 1.0; p += 0.125) {
            double q = tl_stats_percentile(s, p);
            TL_CHECK(q >= s->min && q <= s->max);
        }
        TL_CHECK(tl_stats_percentile(s, 0.0) == sets[i][0]);
        TL_CHECK(tl_stats_percentile(s, 1.0) == sets[i][3]);
    }
    /* An Inf among the errors must not summarise as finite. */
    TL_CHECK(tl_stats_percentile(s, 0.99) == INFINITY);
    TL_CHECK(tl_stats_mean(s) == INFINITY);
    TL_CHECK(isnan(tl_stats_percentile(s, NAN)));
    /* Out-of-range p clamps to the ends. */
    TL_CHECK(tl_stats_percentile(s, -1.0) == s->min && tl_stats_percentile(s, 2.0) == s->max);
}
