// Per-frame and per-view data of every pass: one std140 uniform block at a fixed binding, written
// once per frame (tl__frame_ubo in src/render/scene/view.h mirrors it member for member). A pass's own
// parameters are its block at TL_UBO_PASS, declared in its shader (tl__pass_def.params).

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
    uvec4 u_tiles;        // tiled: tile side in pixels, tiles across, tiles down, list entries the buffer holds
    uvec4 u_light_counts; // visible lights: directional (first in the lights block), local after them; z: end of the casting local lights (first)
    vec4 u_sample_positions[4]; // MSAA: sample s at (x, y) in its pixel = [s / 2].xy (even s) or .zw (odd), GL window space
};

#endif
