/* Render targets: each is declared by the pass that owns it, in that pass's file (tl__pass_def.targets):
 * its name, the macro shaders know it by (TL_UNIT_<M>, TL_OUT_<M>), what it counts as, and its
 * format and size in a configuration. Its id is its public tl_target_id, a stable index. */
#ifndef TL_RENDER_TARGETS_H
#define TL_RENDER_TARGETS_H

#include <stddef.h>
#include <stdint.h>

#include "thinlight/renderer.h"

/* The part of what a technique stores that a target is (tl_frame_plan.gbuffer_bytes_per_pixel
 * counts all three; tl_frame_stats counts G-buffer and light buffer apart). */
typedef enum tl__store {
    TL__STORE_NONE = 0,  /* images of the frame and effect targets: HDR, LDR, output, AO, DOF, ... */
    TL__STORE_GBUFFER,   /* depth and the G-buffer */
    TL__STORE_LIGHT,     /* the light buffer */
    TL__STORE_LISTS      /* the tiled light lists, the light scale's fix-up list */
} tl__store;

typedef struct tl__target_def {
    tl_target_id id;
    const char *name;   /* tl_target_name */
    const char *macro;  /* "RT0": TL_UNIT_RT0 (texture unit = id), TL_OUT_RT0 (colour location) */
    uint32_t format;    /* GL internal format, unless format_of decides */
    uint32_t (*format_of)(const tl_renderer_options *o); /* the format in a configuration (NULL: format) */
    uint32_t (*levels_of)(const tl_renderer_options *o); /* mip levels wanted (NULL: 1) */
    /* storage its module owns (a buffer, the shadow atlas), not a texture of the graph's: its bytes
     * in a plan */
    size_t (*buffer_bytes)(const tl_frame_plan *p, const tl_renderer_options *o);
    uint8_t store;      /* tl__store: what the technique stores, and as which part */
    uint8_t shift;      /* its first level is the frame's size divided by 2^shift, rounded up */
    uint32_t (*shift_of)(const tl_renderer_options *o); /* the shift in a configuration (NULL: shift) */
    uint32_t (*samples_of)(const tl_renderer_options *o); /* samples per pixel (NULL: 1): MSAA's targets */
    uint8_t linear;     /* sampled with bilinear filtering (of its first level) */
    uint8_t depth;      /* a depth target: a pass's depth attachment (depth_target), never a colour write */
    uint8_t frame_output; /* the frame's final image: what read_output reads, where render_to draws */
    uint8_t read_rt0;   /* read_target decodes it as RT0 (octahedral normal, gloss), not as floats */
    uint8_t read_vis_id; /* read_target splits it as visibility's id: object slot, triangle, drawn */
} tl__target_def;

/* The first fields of a definition: `{TL__TARGET(HDR, "hdr"), .format = GL_RGBA16F}`. */
#define TL__TARGET(id_, name_) .id = TL_TARGET_##id_, .name = name_, .macro = #id_

/* Most mip levels a target may have. */
#define TL__MAX_LEVELS 8u

/* Every target's definition, found in the pass table by id (NULL for an id no pass declares). */
void tl__target_defs(const tl__target_def *out[TL_TARGET_COUNT]);

/* Every tl_target_id, as a set. */
#define TL__TARGETS_EVERY ((tl_target_set)-1 >> (64 - TL_TARGET_COUNT))

/* The target that is the frame's final image (tl__target_def.frame_output). */
tl_target_id tl__target_frame_output(void);

/* The GL internal format of a target in a resolved configuration (0 for buffers). */
uint32_t tl__target_format(const tl__target_def *def, const tl_renderer_options *o);

/* A target's shift in a resolved configuration: its first level is the frame's size over 2^shift. */
uint32_t tl__target_shift(const tl__target_def *def, const tl_renderer_options *o);

/* A target's samples per pixel in a resolved configuration (1, or the MSAA count). */
uint32_t tl__target_samples(const tl__target_def *def, const tl_renderer_options *o);

/* MSAA in a resolved configuration: why the options' samples are not planned (NULL: they are, or
 * none were asked for), and the samples of the multisampled targets (1: no MSAA). */
const char *tl__msaa_refusal(const tl_renderer_options *o);
uint32_t tl__msaa_samples(const tl_renderer_options *o);
/* How planned MSAA lights the frame (tl_frame_plan.msaa_reason); 1 when it is per-sample lighting
 * on edges (a multisampled G-buffer: tl__gbuffer_samples its samples, else 1). */
const char *tl__msaa_how(const tl_renderer_options *o);
int tl__msaa_sample_edges(const tl_renderer_options *o);
uint32_t tl__gbuffer_samples(const tl_renderer_options *o);

/* The light buffer's shift (light_scale 2^-k: k): thin-lpp only, every other mode 0. */
uint32_t tl__light_shift(const tl_renderer_options *o);

/* The size of a target's first level and its mip levels for a frame of width x height: a reduced
 * target rounds up and is never 0 wide; levels stop before a level would be smaller than 1x1. */
void tl__target_size(const tl__target_def *def, const tl_renderer_options *o, uint32_t width, uint32_t height,
                     uint32_t *out_width, uint32_t *out_height, uint32_t *levels);

/* Tiled light lists: entries each tile starts with (the buffer grows when a frame needs more). */
#define TL__TILE_START_ENTRIES 32u

#endif
