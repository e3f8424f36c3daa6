// Visibility's vis-resolve (pass_visibility.c): dispatched once per material drawn, over the tiles
// of its bucket (vis_tiles.glsl), four 8 x 8 workgroups per 16 x 16 tile. A pixel whose id names a
// triangle of this material rebuilds its attributes (vis_rebuild.glsl), evaluates the material as
// every geometry pass does (material.glsl, its textures with the analytic derivatives), sums its
// tile's lights with forward's light loop and colour (Forward+), and stores the colour into HDR.
#define TL_VIS_RESOLVE
#include "codec.glsl"
#include "frame.glsl"
#include "light_eval.glsl"
#include "material.glsl"
#include "object.glsl"
#ifdef TL_IBL
#include "ibl.glsl"
#endif
#ifdef TL_MATERIAL_MODELS
#include "material_models.glsl" // per-material models: each light's exact terms (before the loop: its visitor)
#endif
#include "light_loop.glsl"
#include "forward_color.glsl"
#include "vis_tiles.glsl"
#include "vis_rebuild.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = TL_UNIT_VIS_ID) uniform TL_VIS_ID_SAMPLER u_vis_id;
layout(rgba16f, binding = TL_IMAGE_HDR) uniform writeonly TL_VIS_HDR_IMAGE u_hdr_image;

// The colour of the pixel's surface on triangle `id` seen through window point q.
vec3 tl_vis_shade(uint id, ivec2 px, vec2 q)
{
    tl_vis_rebuild(tl_vis_object(id), tl_vis_triangle(id), q);
    tl_surface s = tl_material_surface();
    vec3 n = tl_material_normal();
    vec3 p = v_view_position;
    vec3 v = normalize(-p);
    tl_light_sums sums = tl_light_sums_zero();
#ifdef TL_FORWARD_TILED
    tl_tile_lights_walk(TL_LIGHTS_FORWARD, px, tl_light_point_at(p, n, v, tl_lobe_shape(s.gloss)), sums);
#endif
    return min(tl_forward_color(s, n, v, sums, px), vec3(65504.0));
}

#ifdef TL_GBUFFER_SAMPLES
// sample s's position in its pixel (frame.glsl: u_sample_positions)
vec2 tl_vis_sample_position(int s)
{
    vec4 two = u_sample_positions[s >> 1];
    return (s & 1) == 0 ? two.xy : two.zw;
}
#endif

void main()
{
    ivec2 size = tl_vis_id_size(u_vis_id);
    uint tiles_x = uint(size.x + 15) / 16u, tiles = tiles_x * (uint(size.y + 15) / 16u);
    uint bucket = u_material_index % uint(TL_VIS_BUCKETS);
    uint tile = tl_vis_tiles[bucket * tiles + gl_WorkGroupID.x];
    // four consecutive invocations are a 2 x 2 quad of pixels, as a rasteriser's are: where a
    // texture unit takes one level of detail per quad, it is the quad's (llvmpipe)
    uint lane = gl_LocalInvocationIndex, quad = lane >> 2;
    ivec2 in_block = ivec2(int(quad & 3u) * 2 + int(lane & 1u), int(quad >> 2) * 2 + int((lane >> 1) & 1u));
    ivec2 px = ivec2(tile % tiles_x, tile / tiles_x) * 16 + ivec2(gl_WorkGroupID.y & 1u, gl_WorkGroupID.y >> 1) * 8 + in_block;
    if (any(greaterThanEqual(px, size))) return;
#ifdef TL_GBUFFER_SAMPLES
    // MSAA: each distinct triangle of this material among the pixel's samples is shaded once, at
    // the pixel's centre where it covers them all (as without MSAA), else at its first sample's
    // position (an edge), and stored to every sample it covers
    int n = tl_vis_id_samples(u_vis_id);
    for (int k = 0; k < n; k++) {
        uint id = tl_vis_id_fetch(u_vis_id, px, k);
        if (id == 0u || tl_object_material(tl_vis_object(id)) != u_material_index) continue;
        bool seen = false;
        for (int j = 0; j < k; j++) seen = seen || tl_vis_id_fetch(u_vis_id, px, j) == id;
        if (seen) continue;
        int covered = 0;
        for (int j = k; j < n; j++) covered += tl_vis_id_fetch(u_vis_id, px, j) == id ? 1 : 0;
        vec2 q = vec2(px) + (covered == n ? vec2(0.5) : tl_vis_sample_position(k));
        vec4 c = vec4(tl_vis_shade(id, px, q), 1.0);
        for (int j = k; j < n; j++)
            if (tl_vis_id_fetch(u_vis_id, px, j) == id) tl_vis_hdr_store(u_hdr_image, px, j, c);
    }
#else
    uint id = tl_vis_id_fetch(u_vis_id, px, 0);
    if (id == 0u || tl_object_material(tl_vis_object(id)) != u_material_index) return; // none, or another material
    tl_vis_hdr_store(u_hdr_image, px, 0, vec4(tl_vis_shade(id, px, vec2(px) + 0.5), 1.0));
#endif
}
