/* Stability cases, depth: positions at the near and far plane and along grazing view rays,
 * against analytic ray-plane intersections (stability.h). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stability.h"

/* ---- depth: positions at the near and far plane, grazing view rays -------------------------- */

typedef struct plane_quad {
    double n[3], c;        /* n . p = c */
    double lo[3], hi[3];   /* extent */
} plane_quad;

/* Exact view-space z of the nearest quad hit by the ray through NDC (x, y); 0 when none. */
static double exact_z(const tl_projection *pr, double x, double y, const plane_quad *q, size_t count, double near_z)
{
    double r[3] = {(x + pr->m[8]) / pr->m[0], (y + pr->m[9]) / pr->m[5], -1.0}; /* the ray's point at z = -1 */
    double best = 0.0;
    for (size_t k = 0; k < count; k++) {
        double nd = q[k].n[0] * r[0] + q[k].n[1] * r[1] + q[k].n[2] * r[2];
        if (nd == 0.0) continue;
        double t = q[k].c / nd;
        if (!(t >= near_z)) continue; /* behind the camera or clipped by the near plane */
        int inside = 1;
        for (int a = 0; a < 3; a++) {
            double v = r[a] * t, lo = q[k].lo[a], hi = q[k].hi[a];
            inside &= v >= lo - 1e-9 * fabs(lo) && v <= hi + 1e-9 * fabs(hi);
        }
        if (inside && (best == 0.0 || t < best)) best = t;
    }
    return -best;
}

/* Window depth of view-space z, exactly (double). */
static double exact_window(const tl_projection *pr, double z)
{
    double ndc = (pr->m[10] * z + pr->m[14]) / (-z);
    return pr->format == TL_DEPTH_FORMAT_D32F_REVERSED ? ndc : 0.5 * ndc + 0.5;
}

/* View-space z of a window depth, exactly (double). */
static double exact_linearize(const tl_projection *pr, double w)
{
    double zn = pr->format == TL_DEPTH_FORMAT_D32F_REVERSED ? w : 2.0 * w - 1.0;
    return pr->m[14] / (pr->m[11] * zn - pr->m[10]);
}

/* One step of the stored depth at window depth w: a D24 code, or a float ULP for D32F. */
static double depth_step(tl_depth_format f, double w)
{
    if (f != TL_DEPTH_FORMAT_D32F_REVERSED && f != TL_DEPTH_FORMAT_D32F) return 1.0 / TL_UNORM_MAX(24);
    float wf = (float)w;
    return (double)nextafterf(wf, INFINITY) - (double)wf;
}

typedef struct depth_stats {
    size_t pixels, at_far, bad_window, bad_position;
    double max_window_ratio, max_rel, max_allowed_rel;
} depth_stats;

/* Compares the DEPTH target (window depth, linear distance) and the position the light pass
 * reconstructs from it (the view-ray method) with the exact intersection, pixel by pixel.
 *
 * The window depth may differ from the exact one by
 * - the format's rounding: half a D24 code, or half a float ULP for D32F;
 * - the vertex transform in float: clip z = m10 z + m14 and the divide by w round at 2^-24 of
 *   |m10| + |m14 / z| (this dominates reversed Z near a finite far plane, where the two terms
 *   cancel: window ~ 1e-7 from terms ~ 1e-3);
 * - the rasteriser's float plane equation, 2^-24 of the window's change across the image per
 *   operation; `slope_ops` of them are allowed (walls facing the camera have no change).
 * The allowed position error is what that window interval gives through the exact inverse
 * projection, plus 4 x 2^-22 for the float reconstruction (docs/precision.md). A pixel that the
 * exact depth puts within that interval of the far plane may hold the clear value (D24 at
 * 1:10^7 cannot tell the last 4 x 10^-4 of the range from the far plane). */
static depth_stats check_depth(const run *u, const plane_quad *q, size_t count, double near_z, double slope_ops,
                               const char *label)
{
    depth_stats st = {0};
    tl_depth_format f = u->desc.options.depth_format ? u->desc.options.depth_format : TL_DEPTH_FORMAT_D24;
    int rev = f == TL_DEPTH_FORMAT_D32F_REVERSED;
    const tl_projection *pr = &u->pr;
    size_t shown = 0;
    for (uint32_t y = 0; y < u->f.h; y++)
        for (uint32_t x = 0; x < u->f.w; x++) {
            float ndc[2], nx[2], ny[2];
            pixel_ndc(x, y, u->f.w, u->f.h, ndc);
            pixel_ndc(x + 1, y, u->f.w, u->f.h, nx);
            pixel_ndc(x, y + 1, u->f.w, u->f.h, ny);
            double z = exact_z(pr, ndc[0], ndc[1], q, count, near_z);
            if (z == 0.0) continue;
            size_t i = ((size_t)y * u->f.w + x) * 4;
            double w = exact_window(pr, z);
            double zx = exact_z(pr, nx[0], nx[1], q, count, near_z), zy = exact_z(pr, ny[0], ny[1], q, count, near_z);
            double gx = zx != 0.0 ? fabs(exact_window(pr, zx) - w) : 0.0;
            double gy = zy != 0.0 ? fabs(exact_window(pr, zy) - w) : 0.0;
            double tol = 0.5 * depth_step(f, w) +
                         4.0 * 0x1.0p-24 * (fabs(pr->m[10]) + fabs(pr->m[14] / z)) * (rev ? 1.0 : 0.5) +
                         slope_ops * 0x1.0p-24 * (gx * u->f.w + gy * u->f.h);
            double wl = fmax(w - tol, rev ? 0x1.0p-149 : 0.0), wh = fmin(w + tol, rev ? 1.0 : 1.0 - 0x1.0p-40);
            if (u->f.depth[i] == u->clear && (rev ? w - tol <= 0.0 : w + tol >= 1.0)) {
                st.at_far++;
                continue;
            }
            st.pixels++;
            double dw = fabs((double)u->f.depth[i] - w);
            st.max_window_ratio = fmax(st.max_window_ratio, dw / tol);
            if (!(dw <= tol)) {
                if (shown++ < 4)
                    fprintf(stderr, "  %s: pixel (%u, %u) window depth %.9g, exact %.9g, allowed +-%.3g\n", label, x, y,
                            (double)u->f.depth[i], w, tol);
                st.bad_window++;
            }
            gsample g;
            if (!gbuffer_sample(&u->f, pr, u->clear, x, y, &g)) {
                st.bad_position++;
                continue;
            }
            double r[3] = {-z * (ndc[0] + pr->m[8]) / pr->m[0], -z * (ndc[1] + pr->m[9]) / pr->m[5], z};
            double rl = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
            double e = sqrt((g.p[0] - r[0]) * (g.p[0] - r[0]) + (g.p[1] - r[1]) * (g.p[1] - r[1]) +
                            (g.p[2] - r[2]) * (g.p[2] - r[2])) / rl;
            double za = exact_linearize(pr, wl), zb = exact_linearize(pr, wh);
            double allowed = fmax(fabs(za - z), fabs(zb - z)) / fabs(z) + 4.0 * 0x1.0p-22;
            st.max_rel = fmax(st.max_rel, e);
            st.max_allowed_rel = fmax(st.max_allowed_rel, allowed);
            if (!(e <= allowed)) {
                if (shown++ < 8)
                    fprintf(stderr, "  %s: pixel (%u, %u) position error %.3g > allowed %.3g\n", label, x, y, e,
                            allowed);
                st.bad_position++;
            }
        }
    printf("  %s: %zu pixels (+%zu lost to the far plane), window depth error at most %.3g of its allowance, "
           "position relative error max %.3g (allowed up to %.3g); %zu / %zu beyond\n", label, st.pixels, st.at_far,
           st.max_window_ratio, st.max_rel, st.max_allowed_rel, st.bad_window, st.bad_position);
    return st;
}

/* Walls exactly at the near plane and just inside the far plane (1 - 2^-12 of it), and at 10^6
 * near distances with an infinite far plane, in D24 and reversed-Z D32F. */
TL_TEST(stability_positions_at_near_and_far_plane)
{
    static const struct { float near_z, far_z, dist; const char *what; } cases[] = {
        {0.1f, 100.0f, 0.1f, "at the near plane (0.1)"},
        {0.1f, 100.0f, 100.0f * (1.0f - 0x1.0p-12f), "at the far plane (100 (1 - 2^-12))"},
        {0.1f, 1e6f, 1e6f * (1.0f - 0x1.0p-12f), "at the far plane of 1:10^7"},
        {0.1f, 0.0f, 1e5f, "at 10^6 near distances, infinite far plane"},
    };
    const tl_depth_format formats[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    for (size_t ci = 0; ci < sizeof cases / sizeof cases[0]; ci++)
        for (int f = 0; f < 2; f++) {
            mini_scene m;
            mini_init(&m, 1.0471976f, cases[ci].near_z, cases[ci].far_z);
            m.mat[0] = plain_material(0.5f, 0.5f, 0.5f);
            add_wall(&m, cases[ci].dist, 0);
            float d = cases[ci].dist;
            float k = d * d; /* about 1 at the wall */
            m.light[0] = point_light(0.1f * d, 0.1f * d, -0.5f * d, 2.0f * d, k, k, k);
            m.s.light_count = 1;
            char label[128];
            snprintf(label, sizeof label, "wall %s, %s", cases[ci].what, tl_depth_format_name(formats[f]));
            run u;
            if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64, .options.depth_format = formats[f]}, &m.s,
                           label))
                continue;
            check_all_targets_finite(&u, label);
            float s = 2.0f * d + 1.0f;
            plane_quad q = {{0, 0, 1}, -(double)d, {-s, -s, -d - 1.0}, {s, s, -d + 1.0}};
            depth_stats st = check_depth(&u, &q, 1, cases[ci].near_z, 1.0, label);
            TL_CHECK(st.pixels + st.at_far == 64 * 64);
            TL_CHECK_EQ_U(st.bad_window, 0);
            TL_CHECK_EQ_U(st.bad_position, 0);
            light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 1, label);
            TL_CHECK_EQ_U(c.bad, 0);
            TL_CHECK(c.lit > 1000 || st.at_far == 64 * 64); /* D24 at 1:10^7: the wall merges with the far plane */
            run_free(&u);
        }
}

/* Grazing view rays: a 170-degree field of view over a floor 1 m below the eye, out to a wall at
 * 50 m (D24 and reversed D32F, far 1000). Rays meet the floor at down to 1.3 degrees near the
 * horizon and leave the axis by up to 85 degrees at the image edges; positions reconstructed
 * from the stored depth must match the exact intersections within the depth steps that the
 * sloped plane equation costs (4 at these slopes, measured 2), and lighting must match the model. */
TL_TEST(stability_grazing_view_rays_positions)
{
    const tl_depth_format formats[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    for (int f = 0; f < 2; f++) {
        mini_scene m;
        mini_init(&m, 2.96706f, 0.1f, 1000.0f);
        m.mat[0] = plain_material(0.5f, 0.5f, 0.7f);
        add_quad(&m, (float[3]){-2000, -1, 1}, (float[3]){4000, 0, 0}, (float[3]){0, 0, -51}, 0); /* floor */
        add_quad(&m, (float[3]){-2000, -1, -50}, (float[3]){4000, 0, 0}, (float[3]){0, 2000, 0}, 0); /* wall */
        m.light[0] = point_light(0.0f, 2.0f, -20.0f, 60.0f, 200.0f, 200.0f, 200.0f);
        m.s.light_count = 1;
        char label[96];
        snprintf(label, sizeof label, "grazing rays, %s", tl_depth_format_name(formats[f]));
        run u;
        if (!run_scene(&u, (tl_renderer_desc){.width = 96, .height = 64,
                                              .options.depth_format = formats[f]}, &m.s, label))
            continue;
        check_all_targets_finite(&u, label);
        plane_quad q[2] = {{{0, 1, 0}, -1.0, {-2000, -1.5, -50}, {2000, -0.5, 1}},
                           {{0, 0, 1}, -50.0, {-2000, -1, -51}, {2000, 1999, -49}}};
        depth_stats st = check_depth(&u, q, 2, 0.1, 16.0, label);
        TL_CHECK(st.pixels >= 96 * 56); /* the bottom rows' floor is cut by the near plane */
        TL_CHECK_EQ_U(st.bad_window, 0);
        TL_CHECK_EQ_U(st.bad_position, 0);
        light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 1, label);
        TL_CHECK_EQ_U(c.bad, 0);
        run_free(&u);
    }
}
