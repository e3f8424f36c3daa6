/* The shadow module (docs/shadows.md): which casting lights get a map this frame, where their views
 * lie in the one depth atlas and with which matrices (shadow_views.c, CPU only), and the atlas, its
 * rendering and the lookup data the lighting shaders read (shadows.c). The frame calls prepare
 * before the lights module fills its light data (the lights' slots) and render before its passes. */
#ifndef TL_RENDER_SHADOWS_H
#define TL_RENDER_SHADOWS_H

#include "lights.h"
#include "option_check.h"
#include "scene_gpu.h"

enum {
    TL__SHADOW_MAX_LIGHTS = TL__SHADOW_LIGHTS, /* light records of the lookup block (shadow.glsl) */
    TL__SHADOW_CASCADES = 4,
    TL__SHADOW_MAX_VIEWS = TL__SHADOW_VIEWS,
    TL__SHADOW_FADE_FRAMES = 8, /* frames a light takes to gain or lose its shadow */
    TL__SHADOW_PCSS_RADIUS = 16 /* PCSS: the largest blocker search and kernel radius, texels */
};

/* std140 records of shadow.glsl's uniform block (every member a multiple of 16 bytes). */
typedef struct tl__shadow_view_gpu {
    float m[16];    /* view space to the view's clip space */
    float rect[4];  /* atlas uv offset, scale */
    float texel[4]; /* texel world size per clip w; atlas depth quantum c0 + c1 w; e_arith's constant part */
    float depth[4]; /* PCSS: stored depth d to light distance z (1/z or z = x d + y), light size in texels, perspective */
} tl__shadow_view_gpu;
typedef struct tl__shadow_light_gpu {
    uint32_t info[4]; /* first view, view count, kind, 0 */
    float fade[4];    /* strength, tile side in texels, 0, 0 */
    float splits[4];  /* cascades: the view depth where each ends */
} tl__shadow_light_gpu;
typedef struct tl__shadow_block {
    float params[4];   /* 1 / atlas side, PCF radius, G-buffer position error a z + b z^2 */
    uint32_t flags[4]; /* 0, PCSS's largest radius (0: PCF), 0, 0 */
    float bias[4];     /* the lighting normal's angular error bound (radians), 0, 0, 0 */
    tl__shadow_light_gpu lights[TL__SHADOW_MAX_LIGHTS];
} tl__shadow_block;

/* One view of the atlas for this frame. */
typedef struct tl__shadow_view {
    tl__mat4 world_clip;       /* world to the view's clip space (rendering, culling) */
    uint32_t x, y, size;       /* its tile in texels */
    uint64_t signature;        /* matrix, tile and the casters in it: equal to the kept one, not rendered */
    int render;                /* rendered this frame */
    /* what tl_renderer_get_shadow_views reports */
    uint32_t light, index;     /* scene light; cascade, cube face or 0 */
    float near_z, far_z;       /* depth range along the light */
    float split;               /* cascades: the view depth where it ends */
    int perspective;
} tl__shadow_view;

typedef struct tl__shadows {
    /* CPU, per scene light (grown with the lights) */
    float *slots;              /* slot of each scene light (lights.shadow_slots), 0: none */
    float *fade;               /* shadow strength 0..1 */
    float *score;              /* this frame's priority (screen coverage times intensity) */
    uint32_t *order;           /* casting lights by score */
    size_t light_capacity;
    /* this frame */
    tl__shadow_block block;
    tl__shadow_view_gpu views_gpu[TL__SHADOW_MAX_VIEWS];
    tl__shadow_view views[TL__SHADOW_MAX_VIEWS];
    size_t view_count, light_count;
    uint64_t kept[TL__SHADOW_MAX_VIEWS]; /* the signature each tile holds (0: nothing) */
    size_t kept_count;
    uint32_t unmapped_logged;  /* the most casting lights in view without a map a warning named */
    /* GL */
    GLuint atlas, fbo, lookup, ubo;
    GLuint depth_sampler;      /* PCSS: the atlas read as depth values (no compare) */
    GLuint program;            /* the shadow pass's (the device's program cache owns it) */
    uint32_t atlas_size;
    size_t ubo_stride;
} tl__shadows;

/* shadow_views.c: selects the casting lights (budget, fading), places their views in the atlas and
 * computes every matrix; decides which views must be rendered again (signatures); fills the slots,
 * the lookup block and the frame's statistics. */
tl_result tl__shadows_prepare(tl__device *dev, tl__shadows *s, const tl__lights *l, const tl__scene_gpu *g,
                              const tl__view *v, const tl_renderer_options *o, tl_frame_stats *st);
/* The casters of a view: calls `draw` for each opaque triangle object inside its frustum. */
uint64_t tl__shadow_casters(const tl__scene_gpu *g, const tl__mat4 *world_clip,
                            void (*draw)(void *user, uint32_t object), void *user);

/* shadows.c: the atlas (made again when its size or depth convention changes), the changed views
 * rendered into it, the lookup block uploaded and bound with the atlas for the lighting passes
 * (the shadows pass, pass_shadows.c); returns its draw calls. */
uint32_t tl__shadows_render(tl__device *dev, tl__shadows *s, const tl__scene_gpu *g, tl_frame_stats *st);
void tl__shadows_release(tl__device *dev, tl__shadows *s);
/* The debug reads (tl_renderer_get_shadow_views, tl_renderer_read_shadow_atlas): the last frame's
 * views, and the atlas's depth as floats (rows bottom to top). */
tl_result tl__shadows_views(const tl__shadows *s, const tl_light *lights, size_t light_count, tl_shadow_view_info *out,
                            size_t *count);
tl_result tl__shadows_read_atlas(tl__device *dev, const tl__shadows *s, float *depth, size_t *size);

#endif
