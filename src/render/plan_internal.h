/* Private planner helpers shared by plan.c and the renderer. */
#ifndef TL_RENDER_PLAN_INTERNAL_H
#define TL_RENDER_PLAN_INTERNAL_H

#include "thinlight/renderer.h"

#define TL__MAX_SIZE 16384u

/* Resolves zeroed fields to their defaults; TL_ERROR_INVALID_ARGUMENT for an enum out of range,
 * TL_ERROR_LIMIT for a size over TL__MAX_SIZE. */
tl_result tl__renderer_desc_resolve(const tl_renderer_desc *in, tl_renderer_desc *out);
/* The GL internal format of a target in a (resolved) configuration. */
unsigned tl__target_format(const tl_renderer_desc *d, tl_target_id id);

#endif
