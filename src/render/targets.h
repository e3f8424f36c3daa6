/* The render targets as one table: name, the macro shaders know it by (TL_UNIT_<M>, TL_OUT_<M>),
 * what it counts as, and its format in a configuration. */
#ifndef TL_RENDER_TARGETS_H
#define TL_RENDER_TARGETS_H

#include <stdint.h>

#include "thinlight/renderer.h"

/* The part of what a technique stores that a target is (tl_frame_plan.gbuffer_bytes_per_pixel
 * counts all three; tl_frame_stats counts G-buffer and light buffer apart). */
typedef enum tl__store {
    TL__STORE_NONE = 0,  /* images of the frame and effect targets: HDR, LDR, output, AO, DOF, ... */
    TL__STORE_GBUFFER,   /* depth and the G-buffer */
    TL__STORE_LIGHT,     /* the light buffer */
    TL__STORE_LISTS      /* the tiled light lists */
} tl__store;

typedef struct tl__target_def {
    const char *name;   /* tl_target_name */
    const char *macro;  /* "RT0": TL_UNIT_RT0 (texture unit = id), TL_OUT_RT0 (colour location) */
    uint32_t format;    /* GL internal format; 0: depends on the options (tl__target_format) */
    uint8_t store;      /* tl__store: what the technique stores, and as which part */
    uint8_t buffer;     /* a storage buffer, not a texture: no attachment, unit or memory sharing */
    uint8_t shift;      /* its first level is the frame's size divided by 2^shift, rounded up */
    uint8_t linear;     /* sampled with bilinear filtering (of its first level) */
} tl__target_def;

/* Most mip levels a target may have. */
#define TL__MAX_LEVELS 8u

extern const tl__target_def tl__targets[TL_TARGET_COUNT];

/* The GL internal format of a target in a resolved configuration (0 for buffers). */
uint32_t tl__target_format(const tl_renderer_desc *d, tl_target_id id);

/* The size of a target's first level and its mip levels in a resolved configuration: a reduced
 * target rounds up and is never 0 wide; levels stop before a level would be smaller than 1x1. */
void tl__target_size(const tl_renderer_desc *d, tl_target_id id, uint32_t *width, uint32_t *height, uint32_t *levels);

/* Tiled light lists: entries each tile starts with (the buffer grows when a frame needs more). */
#define TL__TILE_START_ENTRIES 32u
/* Bytes of the light lists for a number of tiles: 4 counters, (offset, count) per tile, entries. */
size_t tl__light_lists_bytes(size_t tiles);

#endif
