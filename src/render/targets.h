/* The render targets as one table: name, the macro shaders know it by (TL_UNIT_<M>, TL_OUT_<M>),
 * what it counts as, and its format in a configuration. */
#ifndef TL_RENDER_TARGETS_H
#define TL_RENDER_TARGETS_H

#include <stdint.h>

#include "thinlight/renderer.h"

typedef struct tl__target_def {
    const char *name;   /* tl_target_name */
    const char *macro;  /* "RT0": TL_UNIT_RT0 (texture unit = id), TL_OUT_RT0 (colour location) */
    uint32_t format;    /* GL internal format; 0: depends on the options (tl__target_format) */
    uint8_t gbuffer;    /* counts as what the technique stores (G-buffer or light buffer) */
} tl__target_def;

extern const tl__target_def tl__targets[TL_TARGET_COUNT];

/* The GL internal format of a target in a resolved configuration. */
uint32_t tl__target_format(const tl_renderer_desc *d, tl_target_id id);

#endif
