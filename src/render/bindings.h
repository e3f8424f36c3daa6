/* Fixed binding points of every program (GLSL `layout(binding = N)`), and the constants C and GLSL
 * share (TL_CULL_CHUNK): set once in the shaders, so
 * no frame looks up or sets a uniform location or a sampler unit. The same list becomes #defines
 * in front of every shader (programs.c), so C and GLSL cannot disagree. The targets a pass samples
 * take texture units 0, 1, ... in tl_target_id order and the ones it writes as images image units
 * 0, 1, ...: each of its programs gets TL_UNIT_<TARGET> and TL_IMAGE_<TARGET> for them, and
 * TL_UNIT_NONE / TL_IMAGE_NONE for every other target (graph.c, programs.c), so a target id is no
 * texture unit and the ids are not bounded by the units a context has. */
#ifndef TL_RENDER_BINDINGS_H
#define TL_RENDER_BINDINGS_H

#define TL__BINDING_LIST(X)                                                                       \
    X(UBO_FRAME, 0)              /* per frame and view: matrices, depth, sizes, post parameters */ \
    X(UBO_MATERIAL, 1)           /* per material: one std140 record, bound as a range */          \
    X(UBO_PASS, 2)               /* the running pass's parameter block (tl__pass_def.params) */     \
    X(UBO_SHADOWS, 3)            /* shadow atlas views and casting lights (shadows.c, std140) */  \
    X(UBO_ENVIRONMENT, 4)        /* the environment's SH and intensity (environment.c) */          \
    X(SSBO_OBJECTS, 0)           /* per object: model and normal matrices, forward light range */ \
    X(SSBO_LIGHTS, 1)            /* the visible lights, view space, directional ones first */     \
    X(SSBO_FORWARD_INDICES, 2)   /* forward: per-object light index lists */                      \
    X(SSBO_TILE_HEADERS, 3)      /* tiled: counters and per-tile (offset, count) */               \
    X(SSBO_TILE_ENTRIES, 4)      /* tiled: the lists' light indices */                            \
    X(SSBO_FIXUP, 5)             /* the light scale's and MSAA's re-lit count (fixup.c) */         \
    X(SSBO_VIS_VERTICES, 6)      /* visibility: the scene's vertex buffer (tl_vertex, 12 floats) */ \
    X(SSBO_VIS_INDICES, 7)       /* visibility: the scene's index buffer */                         \
    X(SSBO_VIS_TILES, 8)         /* visibility: per material bucket, an indirect dispatch and its tiles */ \
    X(SSBO_VIS_COLORS, 9)        /* visibility: tl_scene.colors (vec4 per vertex) */                \
    X(SSBO_VIS_UV1, 10)          /* visibility: tl_scene.uv1 (vec2 per vertex) */                   \
    X(VIS_TRIANGLE_BITS, 20)     /* visibility: the id's low bits, the triangle within its object */ \
    X(VIS_BUCKETS, 64)           /* visibility: material buckets (material index mod 64) */         \
    X(UNIT_ALBEDO_TEXTURE, 16)   /* material textures (units 0 .. 15 are the pass's targets') */   \
    X(UNIT_NORMAL_TEXTURE, 17)                                                                    \
    X(UNIT_MR_TEXTURE, 18)                                                                        \
    X(UNIT_EMISSIVE_TEXTURE, 19)                                                                  \
    X(UNIT_OCCLUSION_TEXTURE, 20)                                                                 \
    X(UNIT_SHADOW_ATLAS, 21)     /* the shadow atlas, a depth-compare sampler (shadows.c) */       \
    X(UNIT_ENV_SKY, 22)          /* the environment image (the sky pass) */                        \
    X(UNIT_ENV_SPECULAR, 23)     /* its GGX-prefiltered mip chain (image-based light) */           \
    X(UNIT_ENV_BRDF, 24)         /* the split-sum BRDF table */                                    \
    X(UNIT_NONE, 25)             /* a target the pass does not sample: a unit nothing is bound to */ \
    X(IMAGE_NONE, 7)             /* a target the pass does not write as an image */                 \
    X(SHADOW_LIGHTS, 64)         /* light records of the shadow lookup block (shadow.glsl) */      \
    X(SHADOW_VIEWS, 384)         /* its views: 6 per light (a point light's faces) */            \
    X(CULL_CHUNK, 16384)         /* local lights one light-cull invocation tests (tiles.glsl) */

enum {
#define TL__BINDING_ENUM(name, value) TL__##name = value,
    TL__BINDING_LIST(TL__BINDING_ENUM)
#undef TL__BINDING_ENUM
    TL__MATERIAL_TEXTURES = 5,
    TL__TARGET_UNITS = 16,       /* targets one pass may sample: units 0 .. 15 */
    TL__TEXTURE_UNITS_USED = 26, /* units the renderer may bind: 0 .. 24, and 25 left empty */
    TL__BUFFER_BINDINGS_USED = 11, /* uniform and storage binding points it may bind: 0 .. 10 */
    TL__IMAGE_UNITS_USED = 7     /* image units a pass may bind: 0 .. 6 (7: TL_IMAGE_NONE) */
};

#endif
