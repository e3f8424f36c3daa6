/* The renderer's shadow term of one light on the shadow scenes (shadow_scenes.h), on the tests'
 * context (shadow_term.c). */
#ifndef TL_SHADOW_TERM_H
#define TL_SHADOW_TERM_H

#include "shadow_scenes.h"

/* The shadow term of `light` (the only light) as the renderer draws it with `o`: the HDR image
 * with the light casting over the image without, per pixel (-1 where the light adds nothing);
 * malloc'd, rows bottom-up, or NULL after a line on stderr. */
float *tl_shadow_term(const tl_shadow_case *c, const tl_light *light, tl_renderer_options o, uint32_t w, uint32_t h,
                      tl_frame_stats *stats);
/* The same ratio not clamped to 1 (a filter whose weights sum past 1 shows as a term above 1);
 * with `views`, the frame's shadow views (tl_renderer_get_shadow_views: *view_count their capacity,
 * then their count, 0 when they could not be read). */
float *tl_shadow_ratio(const tl_shadow_case *c, const tl_light *light, tl_renderer_options o, uint32_t w, uint32_t h,
                       tl_frame_stats *stats, tl_shadow_view_info *views, size_t *view_count);

#endif
