/* GLSL/C parity of depth: linearisation and view position for D24, D32F and reversed D32F
 * (parity.h). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "parity.h"

/* ---- depth ---------------------------------------------------------------------------------- */

/* Window depths for one projection: uniform in [0,1], depths of log-uniform distances between
 * near / 2 and far * 2 (or 10^7 near for infinite far) as the GPU writes them, their D24
 * quantisation, and the ends (0, 1, a ULP inside, -0, just outside, NaN, Inf). */
static void depth_inputs(fvec *a, const tl_projection *p, float near_z, float far_z, uint64_t seed)
{
    tl_rng rng = {seed};
    double lo = log((double)near_z * 0.5), hi = log(far_z > 0.0f ? (double)far_z * 2.0 : (double)near_z * 1e7);
    for (uint32_t i = 0; i < 8192; i++) fpush(a, (float)tl_rng_unit(&rng));
    for (uint32_t i = 0; i < 8192; i++) {
        float d = tl_depth_window_from_distance(p, (float)exp(lo + (hi - lo) * tl_rng_unit(&rng)));
        fpush(a, d);
        fpush(a, tl_depth_quantize(TL_DEPTH_FORMAT_D24, d));
    }
    const float s[] = {0.0f, 1.0f, 0.5f, nextafterf(0.0f, 1.0f), nextafterf(1.0f, 0.0f), -0.0f, FLT_MIN,
                       nextafterf(1.0f, 2.0f), -0x1.0p-24f, 1.5f, -1.0f, NAN, INFINITY, -INFINITY,
                       tl_depth_window_from_distance(p, near_z), tl_depth_window_from_distance(p, far_z)};
    for (size_t i = 0; i < sizeof s / sizeof s[0]; i++) fpush(a, s[i]);
}

static void parity_depth(tl_depth_format format)
{
    parity_env env;
    if (!env_open(&env)) return;
    /* near/far ratios 1:10, 1:10^4, 1:10^7, an infinite far plane, and an off-centre copy
     * (m[8], m[9] nonzero, as a jittered or asymmetric frustum has). */
    const struct { float fov, aspect, near_z, far_z; bool off_centre; } cfg[] = {
        {1.0f, 16.0f / 9.0f, 0.5f, 5.0f, false},     {0.9f, 1.0f, 0.1f, 1000.0f, false},
        {1.2f, 1.5f, 0.01f, 1e5f, false},             {1.0f, 4.0f / 3.0f, 0.1f, 0.0f, false},
        {0.7f, 2.0f, 0.05f, 500.0f, true},            {1.4f, 0.5f, 0.2f, INFINITY, true},
    };
    const char *name = tl_depth_format_name(format);
    size_t total_lin = 0, total_pos = 0, bad = 0;
    for (size_t c = 0; c < sizeof cfg / sizeof cfg[0]; c++) {
        tl_projection p;
        TL_CHECK(tl_projection_perspective(format, cfg[c].fov, cfg[c].aspect, cfg[c].near_z, cfg[c].far_z, &p) ==
                 TL_OK);
        if (cfg[c].off_centre) {
            p.m[8] = 0.0625f;
            p.m[9] = -0.1875f;
        }
        parity_params pp = {.depth = {p.m[10], p.m[14], p.m[11], format == TL_DEPTH_FORMAT_D32F_REVERSED ? 1.0f : 0.0f},
                            .ray = {p.m[0], p.m[5], p.m[8], p.m[9]}};
        fvec d = {0};
        depth_inputs(&d, &p, cfg[c].near_z, cfg[c].far_z, 0xDE97u + c);
        uint32_t *expect = xmalloc_u32(d.n), *got = xmalloc_u32(d.n);
        for (size_t i = 0; i < d.n; i++) expect[i] = f2u(tl_depth_linearize(&p, d.v[i]));
        char what[64];
        snprintf(what, sizeof what, "depth_linearize %s #%zu", name, c);
        if (run_op(&env, OP_DEPTH_LINEARIZE, &pp, (uint32_t)d.n, d.v, d.n, NULL, 0, got, d.n))
            bad += compare_words(what, expect, got, d.n, 1, describe_f, d.v);
        total_lin += d.n;
        /* Positions: each depth with a random NDC point, plus the corners and centre. */
        fvec xyd = {0};
        tl_rng rng = {0x9050u + c};
        const float corner[] = {-1.0f, 0.0f, 1.0f};
        for (size_t i = 0; i < d.n; i++) {
            float x, y;
            if (i % 16 < 9) {
                x = corner[i % 3];
                y = corner[(i / 3) % 3];
            } else {
                x = (float)(2.0 * tl_rng_unit(&rng) - 1.0);
                y = (float)(2.0 * tl_rng_unit(&rng) - 1.0);
            }
            fpush3(&xyd, x, y, d.v[i]);
        }
        size_t n = d.n;
        uint32_t *pexp = xmalloc_u32(3 * n), *pgot = xmalloc_u32(3 * n);
        for (size_t i = 0; i < n; i++) {
            float pos[3];
            tl_view_position_from_depth(&p, xyd.v[3 * i], xyd.v[3 * i + 1], xyd.v[3 * i + 2], pos);
            for (int k = 0; k < 3; k++) pexp[3 * i + k] = f2u(pos[k]);
        }
        snprintf(what, sizeof what, "view_position %s #%zu", name, c);
        if (run_op(&env, OP_VIEW_POSITION, &pp, (uint32_t)n, xyd.v, xyd.n, NULL, 0, pgot, 3 * n))
            bad += compare_words(what, pexp, pgot, n, 3, describe_xyz, xyd.v);
        total_pos += n;
        free(pexp);
        free(pgot);
        free(xyd.v);
        free(expect);
        free(got);
        free(d.v);
    }
    printf("depth %s: %zu depths, %zu positions compared\n", name, total_lin, total_pos);
    TL_CHECK_EQ_U(bad, 0);
    env_close(&env);
}

TL_TEST(parity_depth_d24) { parity_depth(TL_DEPTH_FORMAT_D24); }
TL_TEST(parity_depth_d32f) { parity_depth(TL_DEPTH_FORMAT_D32F); }
TL_TEST(parity_depth_reversed) { parity_depth(TL_DEPTH_FORMAT_D32F_REVERSED); }
