/* Private planner entry points shared by plan.c and the renderer. */
#ifndef TL_RENDER_PLAN_INTERNAL_H
#define TL_RENDER_PLAN_INTERNAL_H

#include "pass.h"

#define TL__MAX_SIZE 16384u
/* Tiled strategy defaults (docs/frame.md gives the measurements behind them): the tile side, and
 * the number of local lights from which the planner prefers tiles to volumes. */
#define TL__TILE_SIZE_DEFAULT 16u
/* tiled_shading auto: the fragment pass, the faster on the one device measured (llvmpipe: docs/frame.md,
 * "Fragment or compute", the two passes as configurations of the same bench runs) */
#define TL__TILED_SHADING_AUTO TL_TILED_SHADING_FRAGMENT
#define TL__TILED_CROSSOVER 32u

/* Resolves zeroed options to their defaults (desc.c; each pass resolves its own slice):
 * TL_ERROR_INVALID_ARGUMENT for a value out of range, naming the field, its value and its range in
 * `why` (may be NULL). */
tl_result tl__options_resolve(const tl_renderer_options *in, tl_renderer_options *out, tl__why *why);
/* The same for a descriptor, with its size: TL_ERROR_LIMIT over TL__MAX_SIZE. */
tl_result tl__renderer_desc_resolve(const tl_renderer_desc *in, tl_renderer_desc *out, tl__why *why);

/* The whole plan, with the application passes (plan.c). Pure: no GL, no allocation. */
tl_result tl__plan_build(const tl_renderer_desc *desc, const tl_scene_feature_set *features,
                         const tl__app_pass *apps, size_t app_count, tl__plan *plan);

/* The options the plan does not honour as asked, into plan->downgrades (plan_downgrades.c). */
void tl__plan_downgrades(const tl__plan_input *in, tl_frame_plan *plan);

#endif
