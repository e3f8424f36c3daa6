// Per-frame and per-view data of every pass: one std140 uniform block at a fixed binding, written
// once per frame (tl__frame_ubo in src/render/renderer_internal.h mirrors it member for member).

#ifndef TL_FRAME_GLSL
#define TL_FRAME_GLSL

layout(std140, binding = TL_UBO_FRAME) uniform tl_frame_block {
    mat4 u_view;
    mat4 u_proj;
    mat4 u_view_proj;
    vec4 u_depth_params;  // a = m[10], b = m[14], c = m[11], reversed (0/1)
    vec4 u_ray_params;    // m[0], m[5], m[8], m[9]
    vec3 u_ambient;       // linear ambient radiance
    float u_clear_depth;  // the depth of background pixels
    vec2 u_inv_size;      // 1 / target size
    float u_exposure;
    float u_fxaa_subpix;
    float u_fxaa_edge_threshold;
    float u_fxaa_edge_threshold_min;
    uvec4 u_tiles;        // tiled: tile side in pixels, tiles across, tiles down, list entries the buffer holds
    uvec4 u_light_counts; // visible lights: directional (first in the lights block), local after them
    vec4 u_ssao;          // effects: radius, k_b, k_d, exponent
    vec4 u_fog_color;     // rgb, density
    vec4 u_fog;           // height, height falloff, noise, noise scale
    vec4 u_effects;       // noise speed, camera time, focus distance, aperture
    vec4 u_dof_params;    // largest CoC (fraction of the height), 0, 0, 0
    vec4 u_bloom;         // threshold, knee (absolute), intensity, scatter
    vec4 u_ssr_march;           // max distance, thickness, min gloss, edge fade
    vec4 u_ssr_weight;         // intensity, near plane distance, 0, 0
};

#endif
