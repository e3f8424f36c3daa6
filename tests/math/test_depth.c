/* Depth and view-space position: for near/far ratios 1:10 .. 1:10^7 and an infinite far plane,
 * in D24, D32F and reversed-Z D32F, distances sampled log-uniformly go through the GPU's window
 * depth, the format's quantisation and tl_view_position_from_depth, and are compared with the
 * exact position computed in double from the true distance. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "thinlight/codec.h"
#include "thinlight/metrics.h"
#include "tl_test.h"

#define SAMPLES 100000u
#define NEAR_Z 0.1f
#define FOV_Y 1.0471976f /* 60 degrees */
#define ASPECT (16.0f / 9.0f)
#define N_RATIOS 8       /* 10^1 .. 10^7, then infinite */
#define INF_SPAN 1e7     /* distances sampled up to near * 10^7 with an infinite far plane */

/* Reversed-Z D32F: the window depth n/d-like value keeps float's relative precision 2^-24 at
 * every distance. Its GPU evaluation (product, sum, divide) and the reconstruction (subtract,
 * divide for z; add, divide for d_eye; multiply for position = z * d_eye) round about 8 times,
 * each at most 2^-24 relative, partly cancelling: 4 * 2^-22 = 16 * 2^-24 bounds them all. */
#define REVERSED_BOUND (4.0 * 0x1.0p-22)

static const tl_depth_format formats[3] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F, TL_DEPTH_FORMAT_D32F_REVERSED};

static double ratio_of(int r) { return r < 7 ? pow(10.0, r + 1) : INFINITY; }

static void make_projection(tl_depth_format format, int r, float fov, float aspect, tl_projection *p)
{
    float far_z = r < 7 ? (float)(NEAR_Z * ratio_of(r)) : INFINITY;
    tl_result res = tl_projection_perspective(format, fov, aspect, NEAR_Z, far_z, p);
    TL_CHECK(res == TL_OK);
}

/* Exact position for distance d (true z = -d) through NDC (x, y), in double. */
static void reference_position(const tl_projection *p, double d, double x, double y, double ref[3])
{
    double z = -d;
    ref[0] = -z * (x + p->m[8]) / p->m[0];
    ref[1] = -z * (y + p->m[9]) / p->m[5];
    ref[2] = z;
}

static double relative_error(const float pos[3], const double ref[3])
{
    double dx = pos[0] - ref[0], dy = pos[1] - ref[1], dz = pos[2] - ref[2];
    return sqrt(dx * dx + dy * dy + dz * dz) / sqrt(ref[0] * ref[0] + ref[1] * ref[1] + ref[2] * ref[2]);
}

static int finite3(const float p[3]) { return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]); }

/* One distance through the whole pipeline; returns the relative position error. */
static double position_error(const tl_projection *p, float d, float x, float y, int *finite)
{
    float window = tl_depth_window_from_distance(p, d);
    float q = tl_depth_quantize(p->format, window);
    float pos[3];
    tl_view_position_from_depth(p, x, y, q, pos);
    double ref[3];
    reference_position(p, d, x, y, ref);
    *finite = finite3(pos);
    return relative_error(pos, ref);
}

typedef struct depth_table {
    tl_stats s[3][N_RATIOS];
} depth_table;

/* Random log-uniform distances in [near, far] (far = near * 10^7 for the infinite plane) and
 * random NDC x, y in [-1, 1]; `fov` and `aspect` select the projection. */
static void measure_table(depth_table *t, float fov, float aspect, int grazing, unsigned long long seed)
{
    size_t nonfinite = 0;
    for (int f = 0; f < 3; f++)
        for (int r = 0; r < N_RATIOS; r++) {
            tl_projection p;
            make_projection(formats[f], r, fov, aspect, &p);
            tl_stats_reset(&t->s[f][r]);
            tl_rng rng = {seed + (unsigned long long)(f * 16 + r)};
            double span = r < 7 ? ratio_of(r) : INF_SPAN;
            for (uint32_t i = 0; i < SAMPLES; i++) {
                float d = (float)(NEAR_Z * pow(span, tl_rng_unit(&rng)));
                if (d < NEAR_Z) d = NEAR_Z;
                if (r < 7 && d > NEAR_Z * span) d = (float)(NEAR_Z * span);
                float x, y;
                if (grazing) { /* the frustum's edges and corners */
                    uint64_t k = tl_rng_u64(&rng);
                    x = (k & 1u) ? 1.0f : -1.0f;
                    y = (k & 2u) ? 1.0f : (k & 4u) ? -1.0f : (float)(2.0 * tl_rng_unit(&rng) - 1.0);
                } else {
                    x = (float)(2.0 * tl_rng_unit(&rng) - 1.0);
                    y = (float)(2.0 * tl_rng_unit(&rng) - 1.0);
                }
                int fin;
                tl_stats_add(&t->s[f][r], position_error(&p, d, x, y, &fin));
                nonfinite += !fin;
            }
        }
    TL_CHECK_EQ_U(nonfinite, 0);
}

static void print_table(const depth_table *t, const char *what)
{
    printf("  relative position error |p - p_ref| / |p_ref|, %s, %u samples each\n", what, SAMPLES);
    printf("  %-14s %-6s %-12s %-12s %-12s\n", "format", "far/n", "mean", "p99", "max");
    for (int f = 0; f < 3; f++)
        for (int r = 0; r < N_RATIOS; r++) {
            char ratio[16];
            if (r < 7) snprintf(ratio, sizeof ratio, "1e%d", r + 1);
            else snprintf(ratio, sizeof ratio, "inf");
            const tl_stats *s = &t->s[f][r];
            printf("  %-14s %-6s %-12.4g %-12.4g %-12.4g\n", tl_depth_format_name(formats[f]), ratio, tl_stats_mean(s),
                   tl_stats_percentile(s, 0.99), s->max);
        }
    printf("  reversed-Z bound 4 * 2^-22 = %.4g\n", REVERSED_BOUND);
}

TL_TEST(depth_reversed_d32f_relative_error_all_ratios)
{
    depth_table *t = malloc(sizeof *t);
    TL_CHECK(t != NULL);
    if (!t) return;
    measure_table(t, FOV_Y, ASPECT, 0, 0xD3E7u);
    print_table(t, "fov 60 deg, aspect 16:9");
    for (int r = 0; r < N_RATIOS; r++) {
        const tl_stats *s = &t->s[2][r];
        TL_CHECK_LE(tl_stats_percentile(s, 0.99), REVERSED_BOUND);
        TL_CHECK_LE(s->max, REVERSED_BOUND);
    }
    /* from 1:10^4 on, D24 is far worse than reversed Z (and keeps getting worse) */
    for (int r = 3; r < N_RATIOS; r++) {
        const tl_stats *d24 = &t->s[0][r], *rev = &t->s[2][r];
        TL_CHECK(d24->max > 100.0 * rev->max);
        TL_CHECK(tl_stats_percentile(d24, 0.99) > 100.0 * tl_stats_percentile(rev, 0.99));
    }
    for (int r = 1; r < 7; r++) TL_CHECK(t->s[0][r].max > t->s[0][r - 1].max);
    free(t);
}

/* Grazing rays: a 172-degree vertical field of view with aspect 4, sampled on the frustum's
 * edges (x_ndc = +-1) and corners, where d_eye is longest (|x| up to 4 tan(86 deg) ~ 57). */
TL_TEST(depth_grazing_rays_wide_fov)
{
    depth_table *t = malloc(sizeof *t);
    TL_CHECK(t != NULL);
    if (!t) return;
    measure_table(t, 3.0f, 4.0f, 1, 0x62A2u);
    print_table(t, "grazing rays, fov 172 deg, aspect 4, x_ndc = +-1");
    for (int r = 0; r < N_RATIOS; r++) TL_CHECK_LE(t->s[2][r].max, REVERSED_BOUND);
    free(t);
    /* off-centre frustum terms m[8], m[9] enter d_eye as documented */
    tl_projection p;
    make_projection(TL_DEPTH_FORMAT_D32F_REVERSED, 7, FOV_Y, ASPECT, &p);
    p.m[8] = 0.25f;
    p.m[9] = -0.125f;
    tl_rng rng = {0x0FFCu};
    double worst = 0.0;
    for (int i = 0; i < 10000; i++) {
        float d = (float)(NEAR_Z * pow(1e6, tl_rng_unit(&rng)));
        float x = (float)(2.0 * tl_rng_unit(&rng) - 1.0), y = (float)(2.0 * tl_rng_unit(&rng) - 1.0);
        int fin;
        double e = position_error(&p, d, x, y, &fin);
        TL_CHECK(fin);
        if (e > worst) worst = e;
    }
    printf("  off-centre (m8 = 0.25, m9 = -0.125), reversed, infinite far: max relative error %.4g\n", worst);
    TL_CHECK_LE(worst, REVERSED_BOUND);
}

/* Exactly at the near plane and at the far plane, through the centre, edges and corners. */
TL_TEST(depth_positions_at_near_and_far_plane)
{
    const float xy[][2] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {-1.0f, 1.0f}, {1.0f, -1.0f}, {0.3f, 0.7f}};
    printf("  %-14s %-6s %-14s %-14s %-12s %-12s\n", "format", "far/n", "window(near)", "window(far)", "err near",
           "err far");
    for (int f = 0; f < 3; f++)
        for (int r = 0; r < N_RATIOS; r++) {
            tl_projection p;
            make_projection(formats[f], r, FOV_Y, ASPECT, &p);
            float near_w = tl_depth_window_from_distance(&p, NEAR_Z);
            float far_d = r < 7 ? (float)(NEAR_Z * ratio_of(r)) : FLT_MAX;
            float far_w = tl_depth_window_from_distance(&p, far_d);
            double en = 0.0, ef = 0.0;
            for (size_t k = 0; k < sizeof xy / sizeof xy[0]; k++) {
                int fin1, fin2;
                double a = position_error(&p, NEAR_Z, xy[k][0], xy[k][1], &fin1);
                TL_CHECK(fin1);
                if (a > en) en = a;
                if (r < 7) {
                    double b = position_error(&p, far_d, xy[k][0], xy[k][1], &fin2);
                    TL_CHECK(fin2);
                    if (b > ef) ef = b;
                }
            }
            char ratio[16];
            if (r < 7) snprintf(ratio, sizeof ratio, "1e%d", r + 1);
            else snprintf(ratio, sizeof ratio, "inf");
            char far_err[32];
            if (r < 7) snprintf(far_err, sizeof far_err, "%.4g", ef);
            else snprintf(far_err, sizeof far_err, "-");
            printf("  %-14s %-6s %-14.9g %-14.9g %-12.4g %-12s\n", tl_depth_format_name(formats[f]), ratio, near_w,
                   far_w, en, far_err);
            /* the near plane is where every format is precise */
            TL_CHECK_LE(en, REVERSED_BOUND);
            if (formats[f] == TL_DEPTH_FORMAT_D32F_REVERSED) {
                TL_CHECK_LE(ef, REVERSED_BOUND);
                TL_CHECK(near_w >= nextafterf(1.0f, 0.0f) && near_w <= 1.0f);
                TL_CHECK(far_w >= 0.0f && far_w <= (r < 7 ? 1e-6f : FLT_MIN));
            } else {
                TL_CHECK(near_w >= 0.0f && near_w <= 1e-6f);
                TL_CHECK(far_w >= 1.0f - 1e-6f && far_w <= 1.0f);
            }
        }
}

/* Window depth 0, 1, NaN and other junk: finite linear z (negative) and finite positions, for
 * every format and far plane, at the centre and the frustum's corners. */
TL_TEST(depth_special_windows_give_finite_positions)
{
    const float windows[] = {0.0f, 1.0f, NAN, -NAN, -0.0f, -1.0f, 2.0f, INFINITY, -INFINITY, FLT_TRUE_MIN,
                             nextafterf(1.0f, 0.0f), 0.5f};
    const float xy[][2] = {{0.0f, 0.0f}, {1.0f, 1.0f}, {-1.0f, -1.0f}, {1.0f, -1.0f}};
    const float fovs[2] = {FOV_Y, 3.0f}, aspects[2] = {ASPECT, 4.0f};
    size_t total = 0, bad = 0;
    for (int f = 0; f < 3; f++)
        for (int r = 0; r < N_RATIOS; r++)
            for (int v = 0; v < 2; v++) {
                tl_projection p;
                make_projection(formats[f], r, fovs[v], aspects[v], &p);
                for (size_t w = 0; w < sizeof windows / sizeof windows[0]; w++) {
                    float z = tl_depth_linearize(&p, windows[w]);
                    float q = tl_depth_quantize(formats[f], windows[w]);
                    /* in front of the camera; only an infinite window (not a depth at all) may
                     * give the camera's own z = 0 */
                    int in_front = isinf(windows[w]) ? z <= 0.0f : z < 0.0f;
                    /* D24 clamps into [0, 1]; D32F formats store finite windows unchanged */
                    int q_ok = formats[f] == TL_DEPTH_FORMAT_D24 ? q >= 0.0f && q <= 1.0f
                                                                  : isinf(windows[w]) || isfinite(q);
                    int ok = isfinite(z) && in_front && q_ok;
                    for (size_t k = 0; k < sizeof xy / sizeof xy[0]; k++) {
                        float pos[3];
                        tl_view_position_from_depth(&p, xy[k][0], xy[k][1], windows[w], pos);
                        int fin = finite3(pos);
                        if (!fin || !ok) {
                            if (bad < 8)
                                fprintf(stderr, "  %s far/n %s fov %g: window %g ndc (%g, %g) -> z %g, pos (%g, %g, %g)\n",
                                        tl_depth_format_name(formats[f]), r < 7 ? "finite" : "inf", fovs[v],
                                        windows[w], xy[k][0], xy[k][1], z, pos[0], pos[1], pos[2]);
                            bad++;
                        }
                        total++;
                    }
                }
            }
    printf("  %zu (format, far plane, fov, window, ndc) combinations: %zu non-finite or non-negative-z\n", total, bad);
    TL_CHECK_EQ_U(bad, 0);
    /* NaN quantises to the far end of each convention */
    TL_CHECK(tl_depth_quantize(TL_DEPTH_FORMAT_D24, NAN) == 1.0f);
    TL_CHECK(tl_depth_quantize(TL_DEPTH_FORMAT_D32F, NAN) == 1.0f);
    TL_CHECK(tl_depth_quantize(TL_DEPTH_FORMAT_D32F_REVERSED, NAN) == 0.0f);
    /* NaN NDC coordinates: finite as well */
    tl_projection p;
    make_projection(TL_DEPTH_FORMAT_D32F_REVERSED, 7, FOV_Y, ASPECT, &p);
    float pn[3];
    tl_view_position_from_depth(&p, NAN, -NAN, 0.5f, pn);
    TL_CHECK(finite3(pn));
    /* a NULL projection is not dereferenced */
    float pos[3];
    tl_view_position_from_depth(NULL, 0.0f, 0.0f, 0.5f, pos);
    TL_CHECK(finite3(pos));
    TL_CHECK(isfinite(tl_depth_linearize(NULL, 0.5f)));
}

TL_TEST(depth_projection_rejects_bad_arguments)
{
    tl_projection p;
    const float pi = 3.14159265358979f;
    struct { float fov, aspect, n, f; } bad[] = {
        {FOV_Y, ASPECT, 0.0f, 100.0f},     {FOV_Y, ASPECT, -1.0f, 100.0f},   {FOV_Y, ASPECT, -0.0f, 100.0f},
        {FOV_Y, ASPECT, 1.0f, 1.0f},       {FOV_Y, ASPECT, 1.0f, 0.5f},      {FOV_Y, ASPECT, NAN, 100.0f},
        {FOV_Y, ASPECT, 1.0f, NAN},        {NAN, ASPECT, 1.0f, 100.0f},      {FOV_Y, NAN, 1.0f, 100.0f},
        {pi, ASPECT, 1.0f, 100.0f},        {4.0f, ASPECT, 1.0f, 100.0f},     {0.0f, ASPECT, 1.0f, 100.0f},
        {-1.0f, ASPECT, 1.0f, 100.0f},     {INFINITY, ASPECT, 1.0f, 100.0f}, {FOV_Y, 0.0f, 1.0f, 100.0f},
        {FOV_Y, -1.0f, 1.0f, 100.0f},      {FOV_Y, INFINITY, 1.0f, 100.0f},  {FOV_Y, ASPECT, INFINITY, 100.0f},
    };
    for (int f = 0; f < 3; f++)
        for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
            tl_result r = tl_projection_perspective(formats[f], bad[i].fov, bad[i].aspect, bad[i].n, bad[i].f, &p);
            if (r != TL_ERROR_INVALID_ARGUMENT)
                fprintf(stderr, "  accepted fov %g aspect %g near %g far %g\n", bad[i].fov, bad[i].aspect, bad[i].n,
                        bad[i].f);
            TL_CHECK(r == TL_ERROR_INVALID_ARGUMENT);
        }
    TL_CHECK(tl_projection_perspective(TL_DEPTH_FORMAT_D24, FOV_Y, ASPECT, 1.0f, 100.0f, NULL) ==
             TL_ERROR_INVALID_ARGUMENT);
    TL_CHECK(tl_projection_perspective(TL_DEPTH_FORMAT_COUNT_, FOV_Y, ASPECT, 1.0f, 100.0f, &p) ==
             TL_ERROR_INVALID_ARGUMENT);
    /* accepted: infinite far as 0, negative or Inf; the default format is D24 */
    const float inf_far[] = {0.0f, -5.0f, INFINITY};
    for (size_t i = 0; i < 3; i++) {
        TL_CHECK(tl_projection_perspective(TL_DEPTH_FORMAT_D24, FOV_Y, ASPECT, 1.0f, inf_far[i], &p) == TL_OK);
        TL_CHECK(p.m[10] == -1.0f && p.m[14] == -2.0f);
        TL_CHECK(tl_projection_perspective(TL_DEPTH_FORMAT_D32F_REVERSED, FOV_Y, ASPECT, 1.0f, inf_far[i], &p) == TL_OK);
        TL_CHECK(p.m[10] == 0.0f && p.m[14] == 1.0f);
    }
    TL_CHECK(tl_projection_perspective(TL_DEPTH_FORMAT_DEFAULT, FOV_Y, ASPECT, 1.0f, 10.0f, &p) == TL_OK);
    TL_CHECK(p.format == TL_DEPTH_FORMAT_D24);
    TL_CHECK(tl_projection_perspective(TL_DEPTH_FORMAT_D24, 3.14f, ASPECT, 1e-30f, 1e30f, &p) == TL_OK);
    printf("  %zu bad (fov, aspect, near, far) sets rejected for each format; infinite far as 0, < 0 or Inf\n",
           sizeof bad / sizeof bad[0]);
}

/* The matrix against its formulas in double: each entry rounded once. */
TL_TEST(depth_projection_matrix_matches_double)
{
    const float fovs[] = {0.01f, FOV_Y, 2.0f, 3.1f}, aspects[] = {0.25f, 1.0f, ASPECT, 4.0f};
    double worst = 0.0;
    for (int f = 0; f < 3; f++)
        for (int r = 0; r < N_RATIOS; r++)
            for (int v = 0; v < 4; v++) {
                tl_projection p;
                TL_CHECK(tl_projection_perspective(formats[f], fovs[v], aspects[v], NEAR_Z,
                                                   r < 7 ? (float)(NEAR_Z * ratio_of(r)) : INFINITY, &p) == TL_OK);
                double n = NEAR_Z, fa = r < 7 ? (double)(float)(NEAR_Z * ratio_of(r)) : INFINITY;
                double cot = 1.0 / tan(0.5 * (double)fovs[v]), a, b;
                if (formats[f] == TL_DEPTH_FORMAT_D32F_REVERSED) {
                    a = r < 7 ? n / (fa - n) : 0.0;
                    b = r < 7 ? fa * n / (fa - n) : n;
                } else {
                    a = r < 7 ? (fa + n) / (n - fa) : -1.0;
                    b = r < 7 ? 2.0 * fa * n / (n - fa) : -2.0 * n;
                }
                const double ref[4] = {cot / aspects[v], cot, a, b};
                const float got[4] = {p.m[0], p.m[5], p.m[10], p.m[14]};
                for (int k = 0; k < 4; k++) {
                    double e = ref[k] == 0.0 ? fabs(got[k]) : fabs(got[k] - ref[k]) / fabs(ref[k]);
                    if (e > worst) worst = e;
                }
                TL_CHECK(p.m[11] == -1.0f && p.m[15] == 0.0f && p.m[8] == 0.0f && p.m[9] == 0.0f);
            }
    printf("  projection entries vs double formulas: max relative error %.3g (one rounding: <= 2^-24 = %.3g)\n", worst,
           0x1.0p-24);
    TL_CHECK_LE(worst, 0x1.0p-24 * (1.0 + 1e-9));
}

/* Every D24 code: decode then encode gives it back, decoded depths increase strictly, and the
 * batch forms match. */
TL_TEST(depth_d24_exhaustive_code_round_trip)
{
    const uint32_t chunk = 1u << 16;
    uint32_t *codes = malloc(chunk * sizeof *codes), *back = malloc(chunk * sizeof *back);
    float *w = malloc(chunk * sizeof *w);
    TL_CHECK(codes && back && w);
    if (!(codes && back && w)) return;
    uint32_t wrong = 0, not_increasing = 0, batch = 0;
    float prev = -1.0f;
    for (uint32_t start = 0; start < (1u << 24); start += chunk) {
        for (uint32_t i = 0; i < chunk; i++) codes[i] = start + i;
        tl_depth_decode_d24_n(codes, w, chunk);
        tl_depth_encode_d24_n(w, back, chunk);
        for (uint32_t i = 0; i < chunk; i++) {
            float s = tl_depth_decode_d24(codes[i]);
            if (memcmp(&s, &w[i], sizeof s) != 0 || back[i] != tl_depth_encode_d24(s)) batch++;
            if (back[i] != codes[i]) wrong++;
            if (!(w[i] > prev)) not_increasing++;
            prev = w[i];
            if (tl_depth_quantize(TL_DEPTH_FORMAT_D24, s) != s) wrong++;
        }
    }
    printf("  all 2^24 D24 codes: %u fail encode(decode(k)) == k, %u not strictly increasing, %u batch mismatches\n",
           wrong, not_increasing, batch);
    TL_CHECK_EQ_U(wrong, 0);
    TL_CHECK_EQ_U(not_increasing, 0);
    TL_CHECK_EQ_U(batch, 0);
    TL_CHECK(tl_depth_decode_d24(0) == 0.0f && tl_depth_decode_d24(0xFFFFFFu) == 1.0f);
    TL_CHECK(tl_depth_decode_d24(0xFFFFFFFFu) == 1.0f);
    TL_CHECK_EQ_U(tl_depth_encode_d24(-1.0f), 0);
    TL_CHECK_EQ_U(tl_depth_encode_d24(2.0f), 0xFFFFFFu);
    TL_CHECK_EQ_U(tl_depth_encode_d24(NAN), 0xFFFFFFu);
    /* quantisation error of any window depth: at most half a code */
    tl_rng rng = {0xD24u};
    double worst = 0.0;
    for (int i = 0; i < 1000000; i++) {
        float d = (float)tl_rng_unit(&rng);
        double e = fabs((double)tl_depth_quantize(TL_DEPTH_FORMAT_D24, d) - d) * TL_UNORM_MAX(24);
        if (e > worst) worst = e;
    }
    printf("  D24 quantisation of 10^6 random depths: max %.6f codes\n", worst);
    /* half a code plus the float rounding (2^-24 relative) of the result, in codes */
    TL_CHECK_LE(worst, 0.5 + TL_UNORM_MAX(24) * 0x1.0p-24);
    free(codes);
    free(back);
    free(w);
}

/* The batch position function equals the scalar one. */
TL_TEST(depth_view_position_batch_matches_scalar)
{
    tl_projection p;
    make_projection(TL_DEPTH_FORMAT_D32F_REVERSED, 3, FOV_Y, ASPECT, &p);
    enum { N = 4097 };
    static float ndc[2 * N], wd[N], pos[3 * N];
    tl_rng rng = {0xBA7Du};
    for (int i = 0; i < N; i++) {
        ndc[2 * i] = (float)(2.0 * tl_rng_unit(&rng) - 1.0);
        ndc[2 * i + 1] = (float)(2.0 * tl_rng_unit(&rng) - 1.0);
        wd[i] = i % 97 == 0 ? NAN : (float)tl_rng_unit(&rng);
    }
    tl_view_position_from_depth_n(&p, ndc, wd, pos, N);
    uint32_t mismatch = 0;
    for (int i = 0; i < N; i++) {
        float s[3];
        tl_view_position_from_depth(&p, ndc[2 * i], ndc[2 * i + 1], wd[i], s);
        if (memcmp(s, pos + 3 * i, sizeof s) != 0) mismatch++;
    }
    TL_CHECK_EQ_U(mismatch, 0);
    tl_view_position_from_depth_n(NULL, ndc, wd, pos, N); /* ignored */
    printf("  tl_view_position_from_depth_n vs scalar, %d positions: %u mismatches\n", N, mismatch);
}
