// Visibility's id and material buckets (pass_visibility.c): the id's split, and the storage
// vis-classify fills and vis-resolve dispatches from: per bucket an indirect dispatch (x: its tiles,
// y: 4 workgroups of 8 x 8 per 16 x 16 tile, z: 1), then per bucket its list of tiles (y * tiles
// across + x), room for every tile.
#ifndef TL_VIS_TILES_GLSL
#define TL_VIS_TILES_GLSL

layout(std430, binding = TL_SSBO_VIS_TILES) buffer tl_vis_tile_block {
    uvec4 tl_vis_dispatch[TL_VIS_BUCKETS];
    uint tl_vis_tiles[];
};

// MSAA (TL_GBUFFER_SAMPLES): the id, and HDR, have samples; "all" is what the targets really
// have (textureSamples: llvmpipe makes 4 of 2).
#ifdef TL_GBUFFER_SAMPLES
#define TL_VIS_ID_SAMPLER usampler2DMS
#define TL_VIS_HDR_IMAGE image2DMS
#define tl_vis_id_samples(t) textureSamples(t)
#define tl_vis_id_size(t) textureSize(t)
#define tl_vis_id_fetch(t, px, s) texelFetch(t, px, s).r
#define tl_vis_hdr_store(img, px, s, v) imageStore(img, px, s, v)
#else
#define TL_VIS_ID_SAMPLER usampler2D
#define TL_VIS_HDR_IMAGE image2D
#define tl_vis_id_samples(t) 1
#define tl_vis_id_size(t) textureSize(t, 0)
#define tl_vis_id_fetch(t, px, s) texelFetch(t, px, 0).r
#define tl_vis_hdr_store(img, px, s, v) imageStore(img, px, v)
#endif

// The id's object slot (its high bits, minus 1) and triangle within the object's draw (its low bits).
uint tl_vis_object(uint id) { return (id >> TL_VIS_TRIANGLE_BITS) - 1u; }
uint tl_vis_triangle(uint id) { return id & ((1u << TL_VIS_TRIANGLE_BITS) - 1u); }

#endif
