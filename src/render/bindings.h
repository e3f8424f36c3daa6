/* Fixed binding points of every program (GLSL `layout(binding = N)`), and the constants C and GLSL
 * share (TL_CULL_CHUNK): set once in the shaders, so
 * no frame looks up or sets a uniform location or a sampler unit. The same list becomes #defines
 * in front of every shader (programs.c), so C and GLSL cannot disagree. A target sampled by a
 * pass is bound to texture unit TL_UNIT_<TARGET> = its tl_target_id (targets.c). */
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
    X(SSBO_FIXUP, 5)             /* the light scale's fix-up: counters, list of pixels (fixup.c) */ \
    X(IMAGE_LIGHT_DIFFUSE, 0)    /* image units of the compute shading pass's writes */           \
    X(IMAGE_LIGHT_SPECULAR, 1)                                                                    \
    X(IMAGE_HDR, 2)                                                                               \
    X(IMAGE_LIGHT_FRESNEL, 3)                                                                     \
    X(IMAGE_LIGHT_COAT, 4)       /* the coat's sum (TL_CLEARCOAT_SUMS) */                           \
    X(UNIT_ALBEDO_TEXTURE, 32)   /* material textures (units below 32 are the targets') */        \
    X(UNIT_NORMAL_TEXTURE, 33)                                                                    \
    X(UNIT_MR_TEXTURE, 34)                                                                        \
    X(UNIT_EMISSIVE_TEXTURE, 35)                                                                  \
    X(UNIT_OCCLUSION_TEXTURE, 36)                                                                 \
    X(UNIT_SHADOW_ATLAS, 37)     /* the shadow atlas, a depth-compare sampler (shadows.c) */       \
    X(UNIT_ENV_SKY, 38)          /* the environment image (the sky pass) */                        \
    X(UNIT_ENV_SPECULAR, 39)     /* its GGX-prefiltered mip chain (image-based light) */           \
    X(UNIT_ENV_BRDF, 40)         /* the split-sum BRDF table */                                    \
    X(SHADOW_LIGHTS, 64)         /* light records of the shadow lookup block (shadow.glsl) */      \
    X(SHADOW_VIEWS, 384)         /* its views: 6 per light (a point light's faces) */            \
    X(CULL_CHUNK, 16384)         /* local lights one light-cull invocation tests (tiles.glsl) */

enum {
#define TL__BINDING_ENUM(name, value) TL__##name = value,
    TL__BINDING_LIST(TL__BINDING_ENUM)
#undef TL__BINDING_ENUM
    TL__MATERIAL_TEXTURES = 5,
    TL__TEXTURE_UNITS_USED = 41, /* units the renderer may bind: 0 .. 40 */
    TL__BUFFER_BINDINGS_USED = 6, /* uniform and storage binding points it may bind: 0 .. 5 */
    TL__IMAGE_UNITS_USED = 5     /* image units it may bind: 0 .. 4 */
};

#endif
