// Visibility's vis-classify (pass_visibility.c): one workgroup per 16 x 16 tile. Its pixels mark
// the material buckets (material index mod TL_VIS_BUCKETS) they show in shared memory; then each
// marked bucket gets the tile appended to its list, its indirect dispatch counting the tiles.
// Pixels where nothing was drawn get HDR's clear value (vis-resolve writes only drawn ones).
#include "frame.glsl"
#include "object.glsl"
#include "vis_tiles.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = TL_UNIT_VIS_ID) uniform TL_VIS_ID_SAMPLER u_vis_id;
layout(rgba16f, binding = TL_IMAGE_HDR) uniform writeonly TL_VIS_HDR_IMAGE u_hdr_image;

shared uint s_buckets[TL_VIS_BUCKETS / 32];

void main()
{
    uint lane = gl_LocalInvocationIndex;
    if (lane < uint(TL_VIS_BUCKETS / 32)) s_buckets[lane] = 0u;
    barrier();
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (all(lessThan(px, tl_vis_id_size(u_vis_id)))) {
        for (int s = 0; s < tl_vis_id_samples(u_vis_id); s++) {
            uint id = tl_vis_id_fetch(u_vis_id, px, s);
            if (id == 0u) {
                tl_vis_hdr_store(u_hdr_image, px, s, vec4(0.0));
            } else {
                uint b = tl_object_material(tl_vis_object(id)) % uint(TL_VIS_BUCKETS);
                atomicOr(s_buckets[b / 32u], 1u << (b % 32u));
            }
        }
    }
    barrier();
    // the dispatches' other sizes (the buffer was cleared to zeros): four 8 x 8 workgroups a tile
    if (gl_WorkGroupID.xy == uvec2(0u) && lane < uint(TL_VIS_BUCKETS)) tl_vis_dispatch[lane].yz = uvec2(4u, 1u);
    if (lane < uint(TL_VIS_BUCKETS) && (s_buckets[lane / 32u] & (1u << (lane % 32u))) != 0u) {
        uint tiles = gl_NumWorkGroups.x * gl_NumWorkGroups.y;
        uint n = atomicAdd(tl_vis_dispatch[lane].x, 1u);
        tl_vis_tiles[lane * tiles + n] = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    }
}
