/* The double-precision lighting reference (tests/reference) against numerical integration: the
 * GGX distribution is normalised, the lobe's directional albedo stays <= 1, the sphere light's
 * closed-form irradiance equals its Monte Carlo integral, the representative point's error is
 * measured (and bounded by the accuracy docs/lighting.md claims), and every extreme case of
 * docs/stability.md gives finite, non-negative weights. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "lighting_integrals.h"
#include "lighting_ref.h"
#include "lighting_tables.h"
#include "tl_test.h"

#define DEG (TL_REF_PI / 180.0)

TL_TEST(ggx_d_integrates_to_one)
{
    const double alphas[] = {TL_REF_GGX_MIN_ALPHA, 0.01, 0.05, 0.1, 0.3, 0.6, 1.0};
    double worst = 0.0;
    for (size_t i = 0; i < sizeof alphas / sizeof alphas[0]; i++) {
        double e = fabs(tl_ref_ggx_d_integral(alphas[i], 20000) - 1.0);
        printf("  alpha %-9g integral of D n.h = 1 %+.3g\n", alphas[i], e);
        worst = fmax(worst, e);
    }
    /* quadrature in log(1 - (n.h)^2) with 20000 midpoints: error far below 1e-6 */
    TL_CHECK_LE(worst, 1e-6);
}

/* Energy: with F = 1 the lobe reflects at most what arrives, for every roughness and view. */
TL_TEST(ggx_directional_albedo_at_most_one)
{
    const double alphas[] = {TL_REF_GGX_MIN_ALPHA, 0.01, 0.04, 0.09, 0.16, 0.25, 0.36, 0.49, 0.64, 0.81, 1.0};
    const double nvs[] = {1e-4, 0.01, 0.05, 0.1, 0.2, 0.4, 0.6, 0.8, 1.0};
    double worst = 0.0, worst_alpha = 0.0, worst_nv = 0.0, worst_err = 0.0;
    printf("  alpha      albedo at n.v = 1e-4 0.01 0.05 0.1 0.2 0.4 0.6 0.8 1\n");
    for (size_t a = 0; a < sizeof alphas / sizeof alphas[0]; a++) {
        printf("  %-9.4g", alphas[a]);
        for (size_t i = 0; i < sizeof nvs / sizeof nvs[0]; i++) {
            tl_ref_estimate e = tl_ref_ggx_albedo(alphas[a], nvs[i], TL_REF_G1_SCHLICK, 512);
            printf(" %.4f", e.value);
            TL_CHECK(e.value >= 0.0 && e.error <= 0.01);
            if (e.value + e.error > worst) {
                worst = e.value + e.error;
                worst_err = e.error;
                worst_alpha = alphas[a];
                worst_nv = nvs[i];
            }
        }
        printf("\n");
    }
    printf("  largest albedo + quadrature error: %.7f (error %.2g) at alpha %g, n.v %g\n", worst, worst_err,
           worst_alpha, worst_nv);
    TL_CHECK_LE(worst, 1.0);
}

/* The closed-form irradiance of a sphere light against Monte Carlo over its solid angle, above,
 * across and below the horizon. Tolerance: 5 standard errors of the estimate (which is computed as
 * if the stratified samples were independent, so it overstates the true error), and the estimate
 * must be good to 0.5 % (of 0.01 near 0) for the comparison to mean anything. */
TL_TEST(sphere_irradiance_matches_monte_carlo)
{
    const double ratios[] = {0.05, 0.2, 0.5, 0.9};
    const double betas[] = {0.0, 30.0, 60.0, 80.0, 88.0, 90.0, 95.0, 110.0, 130.0, 160.0};
    const double n[3] = {0.0, 0.0, 1.0}, d = 1.0;
    size_t compared = 0, bad = 0;
    double worst_rel = 0.0;
    for (size_t q = 0; q < sizeof ratios / sizeof ratios[0]; q++)
        for (size_t b = 0; b < sizeof betas / sizeof betas[0]; b++) {
            double r = ratios[q] * d, beta = betas[b] * DEG;
            double c[3] = {sin(beta) * d, 0.0, cos(beta) * d};
            double exact = tl_ref_sphere_irradiance(cos(beta), d * d, r);
            tl_ref_estimate mc = tl_ref_sphere_diffuse_mc(n, c, r, 1024, 0xD1FFu + q * 16 + b);
            double diff = fabs(exact - mc.value);
            int ok = diff <= 5.0 * mc.error + 1e-12 && mc.error <= 5e-3 * fmax(mc.value, 1e-2);
            if (mc.value > 1e-3) worst_rel = fmax(worst_rel, diff / mc.value);
            if (!ok || b % 3 == 0)
                printf("  radius/d %.2f beta %5.1f: closed form %.8f, Monte Carlo %.8f +- %.2g%s\n", ratios[q],
                       betas[b], exact, mc.value, mc.error, ok ? "" : "  <-- differs");
            bad += !ok;
            compared++;
        }
    printf("  %zu configurations, %zu differ; largest relative difference %.2g\n", compared, bad, worst_rel);
    TL_CHECK_EQ_U(bad, 0);
}

/* Limits of the closed form: a vanishing radius is the point light, the two branches meet where
 * the horizon touches the sphere, and a point inside the sphere gets the clamped distance. */
TL_TEST(sphere_irradiance_limits_and_continuity)
{
    /* radius 0: exactly the point light's cos / d^2 */
    for (double cb = -1.0; cb <= 1.0; cb += 0.125)
        TL_CHECK(tl_ref_sphere_irradiance(cb, 4.0, 0.0) == fmax(cb, 0.0) / 4.0);
    /* tiny radius: within (radius/d)^2 of the point light above the horizon */
    TL_CHECK_LE(fabs(tl_ref_sphere_irradiance(0.5, 1.0, 1e-4) - 0.5), 1e-8);
    /* continuity across the branch boundary cos^2 = (r/d)^2, both sides */
    double worst = 0.0;
    const double ratios[] = {0.01, 0.1, 0.5, 0.9, 0.99};
    for (size_t q = 0; q < sizeof ratios / sizeof ratios[0]; q++)
        for (int sign = -1; sign <= 1; sign += 2) {
            double c0 = sign * ratios[q];
            double a = tl_ref_sphere_irradiance(c0 * (1.0 + 1e-9), 1.0, ratios[q]);
            double b = tl_ref_sphere_irradiance(c0 * (1.0 - 1e-9), 1.0, ratios[q]);
            worst = fmax(worst, fabs(a - b));
        }
    printf("  largest jump across the horizon boundary: %.3g (irradiance scale 1)\n", worst);
    TL_CHECK_LE(worst, 1e-7);
    /* monotonic in beta for a fixed sphere */
    for (size_t q = 0; q < sizeof ratios / sizeof ratios[0]; q++) {
        double prev = INFINITY;
        for (int k = 0; k <= 1800; k++) {
            double e = tl_ref_sphere_irradiance(cos(k * 0.1 * DEG), 1.0, ratios[q]);
            TL_CHECK(e <= prev + 1e-15 && e >= 0.0);
            prev = e;
        }
    }
    /* a point on or inside the sphere: the caller's clamped distance keeps it finite and bounded by
     * a facing half-space of the same radiance, pi / (pi r^2) */
    double d2c = 1.0 / TL_REF_SPHERE_MAX_SIN2, e = tl_ref_sphere_irradiance(1.0, d2c, 1.0);
    double e90 = tl_ref_sphere_irradiance(0.0, d2c, 1.0);
    printf("  on a unit sphere (clamped distance): %.6f facing it, %.6f edge-on; a facing half-space gives 1\n", e,
           e90);
    TL_CHECK(isfinite(e) && e > 0.0 && e <= 1.0);
    TL_CHECK(isfinite(e90) && e90 > 0.0 && e90 < e);
}

/* The representative point against Monte Carlo: the doc's table at 45 degrees (all of it is in
 * docs/lighting.md, from lighting_doc). Asserted: the references are good to 0.5 %; the point
 * limit (radius/d = 0.001) keeps the highlight's energy to 1 %; and the accuracy the doc claims
 * for the method over the whole table: peak within a factor 2, energy within a factor 1.5. */
TL_TEST_FULL(sphere_representative_point_vs_monte_carlo)
{
    const tl_rp_resolution res = {256, 512, 256};
    double worst_peak = 1.0, worst_energy = 1.0;
    printf("  roughness  radius/d  peak rp/true   energy rp/true   (view 45 deg)\n");
    for (int a = 0; a < TL_RP_ROUGHNESS_COUNT; a++)
        for (int q = -1; q < TL_RP_RATIO_COUNT; q++) {
            tl_rp_cell c = {.roughness = tl_rp_roughness[a], .ratio = q < 0 ? 0.001 : tl_rp_ratio[q], .view_deg = 45.0};
            tl_rp_cell_compute(&c, &res);
            double peak = c.peak_rp / c.peak_true.value, energy = c.energy_rp.value / c.energy_true.value;
            printf("  %-9.1f  %-8.3f  %-12.4f   %-12.4f     (MC +- %.2g %%, energy +- %.2g %%)\n", c.roughness,
                   c.ratio, peak, energy, 100.0 * c.peak_true.error / c.peak_true.value,
                   100.0 * (c.energy_rp.error + c.energy_true.error) / c.energy_true.value);
            TL_CHECK_LE(c.peak_true.error, 0.005 * c.peak_true.value);
            TL_CHECK_LE(c.energy_rp.error + c.energy_true.error, 0.005 * c.energy_true.value);
            if (q < 0) {
                TL_CHECK_LE(fabs(energy - 1.0), 0.01);
                continue;
            }
            if (fabs(log(peak)) > fabs(log(worst_peak))) worst_peak = peak;
            if (fabs(log(energy)) > fabs(log(worst_energy))) worst_energy = energy;
        }
    printf("  furthest from 1: peak %.3f, energy %.3f\n", worst_peak, worst_energy);
    TL_CHECK(worst_peak >= 0.5 && worst_peak <= 2.0);
    TL_CHECK(worst_energy >= 1.0 / 1.5 && worst_energy <= 1.5);
}

/* Schlick is linear in F0: F0 S1 + S2 equals the sum of each light's c w F(v.h). */
TL_TEST(ggx_two_specular_sums_are_exact)
{
    tl_rng rng = {0x5E5Eu};
    const double p[3] = {0.3, -0.2, -4.0};
    double nrm[3] = {0.1, 0.3, 1.0}, len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    double n[3] = {nrm[0] / len, nrm[1] / len, nrm[2] / len}, v[3];
    double pl = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (int i = 0; i < 3; i++) v[i] = -p[i] / pl;
    double worst = 0.0;
    for (int trial = 0; trial < 1000; trial++) {
        double f0 = tl_rng_unit(&rng), alpha = fmax(tl_rng_unit(&rng), TL_REF_GGX_MIN_ALPHA), s1 = 0.0, s2 = 0.0, direct = 0.0;
        for (int k = 0; k < 16; k++) {
            tl_ref_light l = {.type = TL_REF_LIGHT_POINT, .range = 10.0, .source_radius = 0.3 * tl_rng_unit(&rng)};
            for (int i = 0; i < 3; i++) l.position[i] = p[i] + 4.0 * tl_rng_unit(&rng) - 2.0;
            l.position[2] = p[2] + 0.5 + 2.0 * tl_rng_unit(&rng);
            double c = 10.0 * tl_rng_unit(&rng), t[3];
            tl_ref_ggx_terms(&l, p, n, v, alpha, t);
            s1 += c * t[1];
            s2 += c * t[2];
            double w = t[1] + t[2], s = w > 0.0 ? t[2] / w : 0.0;
            direct += c * w * (f0 + (1.0 - f0) * s);
        }
        worst = fmax(worst, fabs(f0 * s1 + s2 - direct) / fmax(direct, 1e-300));
    }
    printf("  1000 pixels x 16 lights: F0 S1 + S2 vs sum c w F(v.h), largest relative difference %.3g\n", worst);
    TL_CHECK_LE(worst, 1e-13);
}

/* A punctual light (radius 0) gives the GGX model exactly the Blinn-Phong model's diffuse weight:
 * the falloff, the cone and the distance floor are shared. */
TL_TEST(ggx_punctual_diffuse_equals_blinn_phong)
{
    tl_rng rng = {0xD1F0u};
    size_t differ = 0;
    for (int i = 0; i < 100000; i++) {
        tl_ref_light l = {.type = (tl_ref_light_type)(1 + (int)(tl_rng_u64(&rng) % 3)), .range = 0.5 + 5.0 * tl_rng_unit(&rng),
                          .cos_inner = 0.9, .cos_outer = 0.7};
        float dir[3], nf[3], vf[3];
        tl_rng_direction(&rng, dir);
        tl_rng_direction(&rng, nf);
        tl_rng_direction(&rng, vf);
        double n[3] = {nf[0], nf[1], nf[2]}, v[3] = {vf[0], vf[1], vf[2]}, p[3] = {0.0, 0.0, -3.0};
        double dn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; k++) {
            l.direction[k] = dir[k];
            l.position[k] = p[k] + 6.0 * tl_rng_unit(&rng) - 3.0;
            n[k] /= dn;
        }
        double bp[2], gg[3];
        tl_ref_blinn_phong_terms(&l, p, n, v, 64.0, bp);
        tl_ref_ggx_terms(&l, p, n, v, 0.3, gg);
        differ += fabs(bp[0] - gg[0]) > 1e-12 * fmax(bp[0], 1.0);
    }
    printf("  100000 random punctual lights: %zu diffuse weights differ between the models\n", differ);
    TL_CHECK_EQ_U(differ, 0);
}

/* A metal's specular colour is its base colour (no diffuse), a dielectric's F0 0.04; a glTF
 * roughness r becomes alpha = r^2 through gloss = 1 - r (down to the alpha floor); and a lit
 * pixel of each behaves accordingly. */
TL_TEST(ggx_metallic_roughness_surface)
{
    const double base[3] = {0.9, 0.6, 0.3}, n[3] = {0.0, 0.0, 1.0}, p[3] = {0.0, 0.0, -2.0}, ambient[3] = {0};
    tl_ref_surface metal, plastic;
    tl_ref_surface_metallic_roughness(base, 1.0, 0.5, &metal);
    tl_ref_surface_metallic_roughness(base, 0.0, 0.5, &plastic);
    for (int i = 0; i < 3; i++) {
        TL_CHECK(metal.specular[i] == base[i] && metal.albedo[i] == 0.0);
        TL_CHECK(fabs(plastic.specular[i] - 0.04) < 1e-15 && plastic.albedo[i] == base[i]);
    }
    TL_CHECK(fabs(tl_ref_ggx_alpha(metal.gloss) - 0.25) < 1e-15);
    TL_CHECK(tl_ref_ggx_alpha(1.0 - 0.05) == TL_REF_GGX_MIN_ALPHA);
    /* a light at the mirror position of the eye: the metal's highlight is tinted by its base colour */
    tl_ref_light l = {.type = TL_REF_LIGHT_POINT, .position = {0.0, 0.0, 0.0}, .color = {1.0, 1.0, 1.0}, .range = 20.0};
    double cm[3], cp[3];
    tl_ref_shade(TL_REF_MODEL_GGX, &metal, p, n, &l, 1, ambient, cm);
    tl_ref_shade(TL_REF_MODEL_GGX, &plastic, p, n, &l, 1, ambient, cp);
    printf("  head-on, roughness 0.5: metal (%.4f %.4f %.4f), dielectric (%.4f %.4f %.4f)\n", cm[0], cm[1], cm[2], cp[0],
           cp[1], cp[2]);
    TL_CHECK(fabs(cm[1] / cm[0] - base[1] / base[0]) < 1e-12 && fabs(cm[2] / cm[0] - base[2] / base[0]) < 1e-12);
    TL_CHECK(cp[0] > cp[1] && cp[1] > cp[2]); /* diffuse base colour plus a white highlight */
}

static int finite_nonneg(const double *t, int count)
{
    for (int i = 0; i < count; i++)
        if (!isfinite(t[i]) || t[i] < 0.0) return 0;
    return 1;
}

/* docs/stability.md for both models: gloss 0 and 1 (roughness 1 and the alpha floor), n.v and
 * n.l -> 0, a light behind the surface, at the shaded point and a hair from it, source radius 0
 * and far larger than the distance, huge and tiny ranges: every weight finite and >= 0, and no
 * more than the per-light clamp. */
TL_TEST(ggx_extreme_cases_finite)
{
    const double p[3] = {0.0, 0.0, -2.0}, n[3] = {0.0, 0.0, 1.0};
    const double views[][3] = {{0, 0, 1}, {1, 0, 0}, {0.99999999, 0, 1e-8}, {0, -1, 0}, {0.6, 0, -0.8}};
    const double offsets[][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {1, 0, 1e-9}, {0, 0, 0}, {0, 0, 1e-12},
                                 {-1, 0, 1}, {0.3, 0.4, 1e-3}, {100, 0, 1}};
    const double radii[] = {0.0, 1e-6, 0.5, 1.0, 3.0, 1e3}, ranges[] = {1e-3, 2.0, 1e6}, glosses[] = {0.0, 1.0, 0.5};
    size_t total = 0, bad = 0;
    for (size_t vi = 0; vi < sizeof views / sizeof views[0]; vi++)
        for (size_t oi = 0; oi < sizeof offsets / sizeof offsets[0]; oi++)
            for (size_t ri = 0; ri < sizeof radii / sizeof radii[0]; ri++)
                for (size_t gi = 0; gi < sizeof ranges / sizeof ranges[0] * 3; gi++)
                    for (int type = 1; type <= 3; type++) {
                        tl_ref_light l = {.type = (tl_ref_light_type)type, .direction = {0.0, 0.0, -1.0},
                                          .range = ranges[gi % 3], .source_radius = radii[ri],
                                          .cos_inner = 0.95, .cos_outer = 0.8};
                        for (int k = 0; k < 3; k++) l.position[k] = p[k] + offsets[oi][k];
                        double g = glosses[gi / 3], bp[2], gg[3];
                        tl_ref_blinn_phong_terms(&l, p, n, views[vi], tl_ref_specular_power(g), bp);
                        tl_ref_ggx_terms(&l, p, n, views[vi], tl_ref_ggx_alpha(g), gg);
                        int ok = finite_nonneg(bp, 2) && finite_nonneg(gg, 3) && bp[0] <= TL_REF_LIGHT_CLAMP &&
                                 bp[1] <= TL_REF_LIGHT_CLAMP && gg[0] <= TL_REF_LIGHT_CLAMP &&
                                 gg[1] + gg[2] <= TL_REF_LIGHT_CLAMP * (1.0 + 1e-15);
                        if (!ok && bad < 5)
                            fprintf(stderr, "  view %zu offset %zu radius %g range %g gloss %g type %d: %g %g | %g %g %g\n", vi,
                                    oi, radii[ri], ranges[gi % 3], g, type, bp[0], bp[1], gg[0], gg[1], gg[2]);
                        bad += !ok;
                        total++;
                    }
    printf("  %zu extreme (view, light, radius, range, gloss, type) cases: %zu non-finite, negative or over the clamp\n",
           total, bad);
    TL_CHECK_EQ_U(bad, 0);
    /* the pieces on their own, at their edges */
    TL_CHECK(tl_ref_ggx_alpha(1.0) == TL_REF_GGX_MIN_ALPHA && tl_ref_ggx_alpha(0.0) == 1.0);
    TL_CHECK(isfinite(tl_ref_ggx_d(1.0, TL_REF_GGX_MIN_ALPHA)) && tl_ref_ggx_d(0.0, 0.5) == 0.0);
    TL_CHECK(isfinite(tl_ref_ggx_vis(0.0, 0.0, TL_REF_GGX_MIN_ALPHA)));
    TL_CHECK(tl_ref_fresnel_weight(0.0) == 1.0 && tl_ref_fresnel_weight(1.0) == 0.0 && tl_ref_fresnel_weight(-1.0) == 1.0);
}
