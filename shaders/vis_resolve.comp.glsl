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
layout(binding = TL_UNIT_VIS_ID) uniform usampler2D u_vis_id;
layout(rgba16f, binding = TL_IMAGE_HDR) uniform writeonly image2D u_hdr_image;

void main()
{
    ivec2 size = textureSize(u_vis_id, 0);
    uint tiles_x = uint(size.x + 15) / 16u, tiles = tiles_x * (uint(size.y + 15) / 16u);
    uint bucket = u_material_index % uint(TL_VIS_BUCKETS);
    uint tile = tl_vis_tiles[bucket * tiles + gl_WorkGroupID.x];
    // four consecutive invocations are a 2 x 2 quad of pixels, as a rasteriser's are: where a
    // texture unit takes one level of detail per quad, it is the quad's (llvmpipe)
    uint lane = gl_LocalInvocationIndex, quad = lane >> 2;
    ivec2 in_block = ivec2(int(quad & 3u) * 2 + int(lane & 1u), int(quad >> 2) * 2 + int((lane >> 1) & 1u));
    ivec2 px = ivec2(tile % tiles_x, tile / tiles_x) * 16 + ivec2(gl_WorkGroupID.y & 1u, gl_WorkGroupID.y >> 1) * 8 + in_block;
    if (any(greaterThanEqual(px, size))) return;
    uint id = texelFetch(u_vis_id, px, 0).r;
    if (id == 0u) return;
    uint object = tl_vis_object(id);
    if (tl_object_material(object) != u_material_index) return; // another material of the bucket
    tl_vis_rebuild(object, tl_vis_triangle(id), vec2(px) + 0.5);

    tl_surface s = tl_material_surface();
    vec3 n = tl_material_normal();
    vec3 p = v_view_position;
    vec3 v = normalize(-p);
    tl_light_sums sums = tl_light_sums_zero();
#ifdef TL_FORWARD_TILED
    tl_tile_lights_walk(TL_LIGHTS_FORWARD, px, tl_light_point_at(p, n, v, tl_lobe_shape(s.gloss)), sums);
#endif
    vec3 c = tl_forward_color(s, n, v, sums, px);
    imageStore(u_hdr_image, px, vec4(min(c, vec3(65504.0)), 1.0));
}
