/* Stability cases, lighting limits: gloss 0 and 1, grazing N.L and N.V, a light at the shaded
 * point, radius 0 and huge (stability.h). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stability.h"

/* Gloss 0 (power 2) and gloss 1 (power 4096) in a rendered frame: RT0 stores both ends exactly,
 * the light buffer matches the model at the G-buffer's samples, the gloss-1 peak is the expected
 * factor above the gloss-0 peak, and no target holds a non-finite value. */
TL_TEST(stability_gloss_0_and_1)
{
    double peak[2] = {0, 0};
    for (int gi = 0; gi < 2; gi++) {
        mini_scene m;
        mini_init(&m, 1.0471976f, 0.1f, 100.0f);
        m.mat[0] = plain_material(0.5f, 1.0f, (float)gi);
        add_wall(&m, 5.0f, 0);
        m.light[0] = point_light(0.0f, 0.0f, 0.0f, 10.0f, 1.0f, 1.0f, 1.0f);  /* at the eye: peak at the centre */
        m.light[1] = point_light(1.5f, 1.0f, -3.0f, 6.0f, 0.0f, 0.25f, 1.0f); /* off-axis peak, no red */
        m.s.light_count = 2;
        char label[64];
        snprintf(label, sizeof label, "gloss %d", gi);
        run u;
        if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, label)) continue;
        check_all_targets_finite(&u, label);
        size_t wrong_gloss = 0;
        for (size_t i = 0; i < (size_t)64 * 64; i++) wrong_gloss += u.f.rt0[4 * i + 3] != (float)gi;
        TL_CHECK_EQ_U(wrong_gloss, 0);
        light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 2, label);
        TL_CHECK_EQ_U(c.bad, 0);
        TL_CHECK(c.lit > 1000);
        if (u.f.specular) /* the four pixels around the view axis */
            for (uint32_t y = 31; y <= 32; y++)
                for (uint32_t x = 31; x <= 32; x++) peak[gi] = fmax(peak[gi], u.f.specular[((size_t)y * 64 + x) * 4]);
        run_free(&u);
    }
    /* the lobe's normalisation: (4096 + 8) / (2 + 8) = 410 at N.H = 1; the pixels next to the axis
     * are off the peak by ~0.7 degrees (cos^4096 = 0.72); red comes from the light at the eye alone */
    printf("  specular peaks: gloss 0 %.6g, gloss 1 %.6g (ratio %.1f)\n", peak[0], peak[1], peak[1] / peak[0]);
    TL_CHECK(peak[1] > 200.0 * peak[0] && peak[1] < 410.5 * peak[0]);
}

/* N.L -> 0: point lights in the wall's plane, a hair in front of it and a hair behind it, and a
 * directional light along the wall. The diffuse term must vanish to within what the encoded
 * normal allows: N.L <= sin(max oct12-precise error 0.0393 deg + depth-step angle). */
TL_TEST(stability_grazing_light_n_dot_l)
{
    const float offsets[3] = {0.0f, 1e-3f, -1e-3f}; /* in the plane, in front, behind */
    for (int o = 0; o < 3; o++) {
        mini_scene m;
        mini_init(&m, 1.0471976f, 0.1f, 100.0f);
        m.mat[0] = plain_material(0.5f, 1.0f, 0.75f);
        add_wall(&m, 5.0f, 0);
        m.light[0] = point_light(2.0f, 0.5f, -5.0f + offsets[o], 6.0f, 3.0f, 3.0f, 3.0f);
        m.light[1] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {1.0f, 0.0f, offsets[o]},
                                .color = {2, 2, 2}};
        m.s.light_count = 2;
        char label[80];
        snprintf(label, sizeof label, "grazing N.L, light offset %g", (double)offsets[o]);
        run u;
        if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, label)) continue;
        check_all_targets_finite(&u, label);
        light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 2, label);
        TL_CHECK_EQ_U(c.bad, 0);
        /* independent of the reference: diffuse / (colour * falloff) is N.L, which may exceed
         * the light's true elevation over the plane (offset / distance) only by the normal's
         * encoding error (oct12 precise, max 0.0393 deg) and the tilt of one D24 depth step
         * (1.5e-5 m at 5 m with near 0.1, far 100) seen from the light */
        double worst = -1.0;
        const double normal_err = 0.0393 * 3.14159265358979 / 180.0, depth_step = 1.5e-5;
        for (uint32_t y = 0; y < 64; y++)
            for (uint32_t x = 0; x < 64; x++) {
                gsample g;
                if (!gbuffer_sample(&u.f, &u.pr, u.clear, x, y, &g)) continue;
                double t[2], e[2], dir_terms[2];
                gsample h = g; /* the same sample with the normal turned towards the light */
                const float *lp = m.light[0].position;
                double d[3] = {lp[0] - g.p[0], lp[1] - g.p[1], lp[2] - g.p[2]};
                double dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                for (int k = 0; k < 3; k++) h.n[k] = d[k] / dl;
                light_terms(&m.light[0], &h, t, e);
                light_terms(&m.light[1], &g, dir_terms, e);
                if (t[0] < 1e-3) continue;
                double gpu = u.f.diffuse[((size_t)y * 64 + x) * 4] - 2.0 * dir_terms[0];
                double allowed = sin(normal_err + depth_step / dl) + fmax(offsets[o], 0.0f) / dl;
                double excess = gpu / (3.0 * t[0]) - allowed;
                worst = fmax(worst, excess);
            }
        printf("  %s: max N.L beyond the allowance %.3g\n", label, worst);
        TL_CHECK_LE(worst, TL_HALF_REL_STEP); /* and one FP16 step of the stored diffuse */
        run_free(&u);
    }
}

/* N.V -> 0: a floor seen from 1 m above it out to 110 m, where the view ray of the row next to
 * the horizon meets the floor at 0.5 degrees; lit by a point light far down the floor and a directional
 * light at 0.06 degrees above the horizon (N.L -> 0 as well). */
TL_TEST(stability_grazing_view_n_dot_v)
{
    mini_scene m;
    mini_init(&m, 1.0471976f, 0.1f, 1000.0f);
    m.mat[0] = plain_material(0.5f, 1.0f, 0.9f);
    add_quad(&m, (float[3]){-300, -1, 10}, (float[3]){600, 0, 0}, (float[3]){0, 0, -400}, 0); /* +Y */
    m.light[0] = point_light(0.0f, 0.0f, -60.0f, 80.0f, 400.0f, 400.0f, 400.0f);
    m.light[1] = (tl_light){.type = TL_LIGHT_DIRECTIONAL, .direction = {0.0f, -1e-3f, -1.0f}, .color = {3, 3, 3}};
    m.s.light_count = 2;
    char label[64];
    snprintf(label, sizeof label, "grazing N.V");
    run u;
    if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, label)) return;
    check_all_targets_finite(&u, label);
    light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 2, label);
    TL_CHECK_EQ_U(c.bad, 0);
    TL_CHECK(c.lit > 500);
    /* the rows next to the horizon are floor at N.V < 0.02, and they are lit */
    double min_ndotv = 1.0;
    for (uint32_t y = 0; y < 32; y++) {
        gsample g;
        if (!gbuffer_sample(&u.f, &u.pr, u.clear, 32, y, &g)) continue;
        double pl = sqrt(g.p[0] * g.p[0] + g.p[1] * g.p[1] + g.p[2] * g.p[2]);
        double ndotv = -(g.n[0] * g.p[0] + g.n[1] * g.p[1] + g.n[2] * g.p[2]) / pl;
        min_ndotv = fmin(min_ndotv, ndotv);
    }
    printf("  %s: smallest N.V on the floor %.4f\n", label, min_ndotv);
    TL_CHECK(min_ndotv < 0.01);
    run_free(&u);
}

/* A point light on the lit surface: the distance to the pixel at the image centre (odd size,
 * so a pixel centre lies on the view axis) is below one depth step, far under the falloff's
 * clamp distance 0.01 radius. The light buffer must hold at most colour / (0.01 radius)^2
 * (and at most colour * 4096, the per-light clamp) and match the model everywhere. */
TL_TEST(stability_light_at_shaded_point)
{
    const float radii[2] = {10.0f, 0.5f}; /* peak 1 / 0.1^2 = 100, and 1 / 0.005^2 = 40000 -> clamp 4096 */
    const tl_depth_format formats[2] = {TL_DEPTH_FORMAT_D24, TL_DEPTH_FORMAT_D32F_REVERSED};
    for (int f = 0; f < 2; f++)
        for (int ri = 0; ri < 2; ri++) {
            mini_scene m;
            mini_init(&m, 1.0471976f, 0.1f, 100.0f);
            m.mat[0] = plain_material(0.5f, 1.0f, 0.5f);
            add_wall(&m, 5.0f, 0);
            m.light[0] = point_light(0.0f, 0.0f, -5.0f, radii[ri], 2.0f, 2.0f, 2.0f);
            m.s.light_count = 1;
            char label[96];
            snprintf(label, sizeof label, "light on the surface, radius %g, %s", (double)radii[ri],
                     tl_depth_format_name(formats[f]));
            run u;
            if (!run_scene(&u, (tl_renderer_desc){.width = 63, .height = 63,
                                                  .options.depth_format = formats[f]}, &m.s, label))
                continue;
            check_all_targets_finite(&u, label);
            light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 1, label);
            TL_CHECK_EQ_U(c.bad, 0);
            double m01 = 0.01 * radii[ri], cap = 2.0 * fmin(4096.0, 1.0 / (m01 * m01));
            double peak = 0.0;
            for (size_t i = 0; i < (size_t)63 * 63 * 4; i++)
                if (i % 4 != 3) {
                    TL_CHECK(u.f.diffuse[i] >= 0.0f);
                    peak = fmax(peak, u.f.diffuse[i]);
                }
            gsample g;
            TL_CHECK(gbuffer_sample(&u.f, &u.pr, u.clear, 31, 31, &g));
            double dist = sqrt(g.p[0] * g.p[0] + g.p[1] * g.p[1] + (g.p[2] + 5.0) * (g.p[2] + 5.0));
            printf("  %s: centre pixel %.3g m from the light, diffuse there %.6g, peak %.6g (cap %.6g)\n", label, dist,
                   (double)u.f.diffuse[(31 * 63 + 31) * 4], peak, cap);
            TL_CHECK(dist < m01);
            TL_CHECK_LE(peak, cap * (1.0 + 0.5 * TL_HALF_REL_STEP)); /* the cap, stored to nearest FP16 */
            run_free(&u);
        }
}

/* Radius 0 and radii so small that the falloff underflows: no light, no NaN (attenuation would
 * be 0 / 0 at radius 0). Radius 0 is refused, naming the light (it was drawn as nothing without a
 * word before, issue 25); the tiny radii are drawn and the frame must equal the frame without
 * those lights, bit for bit. */
TL_TEST(stability_light_radius_zero)
{
    const float tiny[] = {0.0f, FLT_TRUE_MIN, 1e-30f};
    mini_scene m;
    mini_init(&m, 1.0471976f, 0.1f, 100.0f);
    add_wall(&m, 5.0f, 0);
    m.light[0] = point_light(1.0f, 0.0f, -4.0f, 3.0f, 1.0f, 1.0f, 1.0f); /* control */
    run ref, u;
    m.s.light_count = 1;
    if (!run_scene(&ref, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, "control")) return;
    for (size_t t = 0; t < sizeof tiny / sizeof tiny[0]; t++) {
        /* a point light on the surface (distance 0 at its pixel) and a spot light in front */
        m.light[1] = point_light(0.0f, 0.0f, -5.0f, tiny[t], 5.0f, 5.0f, 5.0f);
        m.light[2] = (tl_light){.type = TL_LIGHT_SPOT, .position = {0, 0, -4}, .direction = {0, 0, -1},
                                .color = {5, 5, 5}, .radius = tiny[t], .cos_inner = 0.9f, .cos_outer = 0.8f};
        m.s.light_count = 3;
        char label[80];
        snprintf(label, sizeof label, "radius %g", (double)tiny[t]);
        if (tiny[t] == 0.0f) {
            TL_CHECK(tl_renderer_set_scene(ref.r, &m.s) == TL_ERROR_INVALID_ARGUMENT);
            printf("  %s: refused, \"%s\"\n", label, tl_renderer_last_error(ref.r));
            TL_CHECK(strstr(tl_renderer_last_error(ref.r), "lights[1].radius = 0: a point light needs a finite radius > 0"));
            continue;
        }
        if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, label)) continue;
        check_all_targets_finite(&u, label);
        size_t differ = 0;
        for (size_t i = 0; i < (size_t)64 * 64 * 4; i++) {
            differ += u.f.diffuse[i] != ref.f.diffuse[i] || u.f.hdr[i] != ref.f.hdr[i];
            if (u.f.specular) differ += u.f.specular[i] != ref.f.specular[i];
        }
        printf("  %s: %u point + %u spot instances drawn, %zu values differ from the control frame\n", label,
               u.stats.lights_drawn[TL_LIGHT_POINT], u.stats.lights_drawn[TL_LIGHT_SPOT], differ);
        TL_CHECK_EQ_U(differ, 0);
        run_free(&u);
    }
    run_free(&ref);
}

/* Huge radii: 1e6 (camera and scene deep inside the volume; the falloff's clamp distance is
 * 1e4, so the attenuation is 1e-8 everywhere and a colour of 2e8 brings it back to ~2), and
 * 1e30 and FLT_MAX, where (0.01 radius)^2 overflows float and the model gives exactly 0. The
 * volume path must match the model and the full-screen path. */
TL_TEST(stability_light_radius_huge)
{
    const float radii[3] = {1e6f, 1e30f, FLT_MAX};
    for (int ri = 0; ri < 3; ri++) {
        mini_scene m;
        mini_init(&m, 1.0471976f, 0.1f, 100.0f);
        m.mat[0] = plain_material(0.5f, 1.0f, 0.5f);
        add_wall(&m, 5.0f, 0);
        m.light[0] = point_light(2.0f, 1.0f, -3.0f, radii[ri], 2e8f, 1e8f, 3e8f);
        m.s.light_count = 1;
        char label[80];
        snprintf(label, sizeof label, "radius %g", (double)radii[ri]);
        run u, full;
        if (!run_scene(&u, (tl_renderer_desc){.width = 64, .height = 64}, &m.s, label)) continue;
        check_all_targets_finite(&u, label);
        light_check c = check_light_buffer(&u.f, &u.pr, u.clear, m.light, 1, label);
        TL_CHECK_EQ_U(c.bad, 0);
        if (ri == 0) TL_CHECK(c.lit > 3000 && c.max_value > 1.0);
        if (ri > 0) { /* (0.01 radius)^2 overflows float: the shader's attenuation is exactly 0 */
            size_t nonzero = 0;
            for (size_t i = 0; i < (size_t)64 * 64 * 4; i++) nonzero += u.f.diffuse[i] != 0.0f;
            TL_CHECK_EQ_U(nonzero, 0);
        }
        if (run_scene(&full, (tl_renderer_desc){.width = 64, .height = 64, .options.fullscreen_lights = 1},
                      &m.s, "full-screen")) {
            size_t differ = 0;
            for (size_t i = 0; i < (size_t)64 * 64 * 4; i++) differ += u.f.diffuse[i] != full.f.diffuse[i];
            printf("  %s: %zu light-buffer values differ from the full-screen path\n", label, differ);
            TL_CHECK_EQ_U(differ, 0);
            run_free(&full);
        }
        run_free(&u);
    }
}
