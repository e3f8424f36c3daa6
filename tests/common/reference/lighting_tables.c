/* Tables of docs/lighting.md; see lighting_tables.h. */
#include "lighting_tables.h"

#include <math.h>

#include "lighting_ref.h"

const double tl_rp_roughness[TL_RP_ROUGHNESS_COUNT] = {0.1, 0.3, 0.6, 1.0};
const double tl_rp_ratio[TL_RP_RATIO_COUNT] = {0.05, 0.1, 0.2, 0.4, 0.6, 0.9};
const double tl_rp_view_deg[TL_RP_VIEW_COUNT] = {0.0, 45.0, 75.0};

void tl_rp_cell_compute(tl_rp_cell *c, const tl_rp_resolution *res)
{
    const double n[3] = {0.0, 0.0, 1.0}, p[3] = {0.0, 0.0, 0.0}, d = 1.0;
    double t = c->view_deg * TL_REF_PI / 180.0, alpha = c->roughness * c->roughness, radius = c->ratio * d;
    double v[3] = {sin(t), 0.0, cos(t)}, centre[3] = {-sin(t) * d, 0.0, cos(t) * d};
    uint64_t seed = 0x5EED0000u + (uint64_t)(c->roughness * 1000.0) * 7919u + (uint64_t)(c->ratio * 1000.0) * 31u +
                    (uint64_t)c->view_deg;
    c->peak_true = tl_ref_sphere_specular_mc(n, v, centre, radius, alpha, res->mc_side, seed);
    /* range 50 d: the window is 1 - 3e-7 here, and its distance floor 0.01 range < d */
    tl_ref_light light = {.type = TL_REF_LIGHT_POINT, .position = {centre[0], centre[1], centre[2]},
                          .range = 50.0 * d, .source_radius = radius};
    double out[3];
    tl_ref_ggx_terms(&light, p, n, v, alpha, out);
    c->peak_rp = out[1] + out[2];
    c->energy_rp = tl_ref_sphere_rp_energy(n, v, d, radius, alpha, res->energy_steps);
    tl_ref_estimate a = tl_ref_ggx_albedo(alpha, v[2], TL_REF_G1_SCHLICK, res->albedo_side);
    double s2 = radius * radius / (d * d), omega = 2.0 * TL_REF_PI * s2 / (1.0 + sqrt(1.0 - s2));
    c->energy_true = (tl_ref_estimate){omega * a.value / (radius * radius), omega * a.error / (radius * radius)};
}

void tl_rp_table_markdown(FILE *f, const tl_rp_cell *cells, const tl_rp_resolution *res)
{
    fprintf(f, "| roughness (alpha) | radius / distance |");
    for (int k = 0; k < TL_RP_VIEW_COUNT; k++) fprintf(f, " peak, view %g° |", tl_rp_view_deg[k]);
    for (int k = 0; k < TL_RP_VIEW_COUNT; k++) fprintf(f, " energy, view %g° |", tl_rp_view_deg[k]);
    fprintf(f, "\n|---|---:|");
    for (int k = 0; k < 2 * TL_RP_VIEW_COUNT; k++) fprintf(f, "---:|");
    fprintf(f, "\n");
    double worst_mc = 0.0, worst_q = 0.0;
    for (int a = 0; a < TL_RP_ROUGHNESS_COUNT; a++)
        for (int q = 0; q < TL_RP_RATIO_COUNT; q++) {
            const tl_rp_cell *row = cells + (a * TL_RP_RATIO_COUNT + q) * TL_RP_VIEW_COUNT;
            fprintf(f, "| %.1f (%.2g) | %.2f |", row[0].roughness, row[0].roughness * row[0].roughness, row[0].ratio);
            for (int k = 0; k < TL_RP_VIEW_COUNT; k++) {
                fprintf(f, " %+.1f %% |", 100.0 * (row[k].peak_rp / row[k].peak_true.value - 1.0));
                worst_mc = fmax(worst_mc, row[k].peak_true.error / row[k].peak_true.value);
            }
            for (int k = 0; k < TL_RP_VIEW_COUNT; k++) {
                fprintf(f, " %+.1f %% |", 100.0 * (row[k].energy_rp.value / row[k].energy_true.value - 1.0));
                worst_q = fmax(worst_q, (row[k].energy_rp.error + row[k].energy_true.error) / row[k].energy_true.value);
            }
            fprintf(f, "\n");
        }
    fprintf(f,
            "\nPeak: the representative point's specular weight against the sphere's (Monte Carlo, %u x %u "
            "stratified samples of each strategy, relative standard error at most %.2f %%) with the light's "
            "centre on the mirror direction. Energy: the highlight's weight integrated over every direction of "
            "the light's centre, against the sphere's (its solid angle / radius^2 times the GGX albedo); "
            "quadrature uncertainty at most %.2f %%.\n",
            (unsigned)res->mc_side, (unsigned)res->mc_side, 100.0 * worst_mc, 100.0 * worst_q);
}

double tl_albedo_table_markdown(FILE *f, uint32_t side)
{
    static const double rough[] = {0.088388, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0};
    static const double nvs[] = {0.01, 0.1, 0.25, 0.5, 0.75, 1.0};
    static const char *const names[] = {"k = alpha / 2 (the model)", "UE4 k = (r + 1)^2 / 8", "exact Smith G1"};
    const size_t nr = sizeof rough / sizeof rough[0], nn = sizeof nvs / sizeof nvs[0];
    fprintf(f, "| G1 | roughness r (alpha) |");
    for (size_t i = 0; i < nn; i++) fprintf(f, " n.v = %g |", nvs[i]);
    fprintf(f, "\n|---|---|");
    for (size_t i = 0; i < nn; i++) fprintf(f, "---:|");
    fprintf(f, "\n");
    double worst = 0.0;
    for (int g = 0; g < 3; g++)
        for (size_t a = 0; a < nr; a++) {
            double alpha = fmax(rough[a] * rough[a], TL_REF_GGX_MIN_ALPHA);
            fprintf(f, "| %s | %.3g (%.3g) |", names[g], rough[a], alpha);
            for (size_t i = 0; i < nn; i++) {
                tl_ref_estimate e = tl_ref_ggx_albedo(alpha, nvs[i], (tl_ref_g1)g, side);
                if (g == TL_REF_G1_SCHLICK) worst = fmax(worst, e.value + e.error);
                fprintf(f, " %.4f |", e.value);
            }
            fprintf(f, "\n");
        }
    return worst;
}
