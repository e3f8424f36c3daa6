/* The sphere light's representative-point error table and the GGX albedo table of
 * docs/lighting.md: computed by the lighting tests (which assert on them) and written into the
 * doc by lighting_doc (tests/lighting_doc.c). */
#ifndef TL_LIGHTING_TABLES_H
#define TL_LIGHTING_TABLES_H

#include <stdint.h>
#include <stdio.h>

#include "lighting_integrals.h"

/* One configuration: a sphere light of radius ratio * d at distance d = 1 on the mirror
 * direction of a view at view_deg from the normal, GGX alpha = roughness^2. */
typedef struct tl_rp_cell {
    double roughness, ratio, view_deg;
    tl_ref_estimate peak_true; /* the sphere's specular weight, Monte Carlo */
    double peak_rp;            /* tl_ref_ggx_terms' weight (representative point) */
    tl_ref_estimate energy_rp; /* highlight energy of the representative point */
    tl_ref_estimate energy_true; /* the sphere's: solid angle / radius^2 times the albedo */
} tl_rp_cell;

/* Resolutions: Monte Carlo side^2 (x2 strategies), energy quadrature steps x 4 steps, albedo
 * quadrature side^2. */
typedef struct tl_rp_resolution {
    uint32_t mc_side, energy_steps, albedo_side;
} tl_rp_resolution;

void tl_rp_cell_compute(tl_rp_cell *c, const tl_rp_resolution *res);

/* The grids of the doc. */
#define TL_RP_ROUGHNESS_COUNT 4
#define TL_RP_RATIO_COUNT 6
#define TL_RP_VIEW_COUNT 3
extern const double tl_rp_roughness[TL_RP_ROUGHNESS_COUNT]; /* 0.1, 0.3, 0.6, 1.0 */
extern const double tl_rp_ratio[TL_RP_RATIO_COUNT];         /* 0.05 ... 0.9 */
extern const double tl_rp_view_deg[TL_RP_VIEW_COUNT];       /* 0, 45, 75 */

/* Writes the representative-point table (markdown) for the cells of the doc's grids, in
 * roughness-major, ratio, view order. */
void tl_rp_table_markdown(FILE *f, const tl_rp_cell *cells, const tl_rp_resolution *res);

/* Writes the directional-albedo table (markdown): the model's k = alpha / 2 beside UE4's k and the
 * exact Smith G1, over roughness and n.v; returns the largest albedo of the model plus its error. */
double tl_albedo_table_markdown(FILE *f, uint32_t side);

#endif
