// Tiled light lists: the frame's visible lights (view space, directional ones first) and, per
// screen tile, the local lights that may reach a surface in it (light_cull.comp.glsl writes them;
// the tiled light pass and Forward+ read them). docs/frame.md, "Tiled light accumulation".

#ifndef TL_TILES_GLSL
#define TL_TILES_GLSL

#include "frame.glsl"
#include "light_eval.glsl" // tl_light_data

layout(std430, binding = TL_SSBO_LIGHTS) readonly buffer tl_light_buffer { tl_light_data tl_lights[]; };

// A tile whose list did not fit in the entries buffer: its pixels loop over every visible light.
const uint TL_TILE_OVERFLOW = 0xFFFFFFFFu;

#ifdef TL_TILES_WRITE
#define TL_TILES_ACCESS
#else
#define TL_TILES_ACCESS readonly
#endif
// tl_counters: entries used, lists that overflowed, pixel-light pairs (low and high 32 bits).
// The local lights are culled in chunks of TL_CULL_CHUNK (llvmpipe ends any shader invocation's
// loops after 65535 iterations in total, Mesa's LP_MAX_TGSI_LOOP_ITERATIONS: one invocation per
// tile testing every light twice would lose lights beyond about 32,000); each chunk has its own
// list per tile, and a pixel reads its tile's lists in chunk order, so lights keep their order.
layout(std430, binding = TL_SSBO_TILE_HEADERS) TL_TILES_ACCESS buffer tl_tile_header_buffer {
    uvec4 tl_counters;
    uvec2 tl_tile_headers[]; // (first entry, count) per chunk and tile: chunk by chunk, row by row
};
layout(std430, binding = TL_SSBO_TILE_ENTRIES) TL_TILES_ACCESS buffer tl_tile_entry_buffer { uint tl_tile_entries[]; };

uint tl_tile_index(ivec2 px)
{
    uvec2 t = uvec2(px) / u_tiles.x;
    return t.y * u_tiles.y + t.x;
}

uint tl_tile_chunks() { return max((u_light_counts.y + uint(TL_CULL_CHUNK) - 1u) / uint(TL_CULL_CHUNK), 1u); }

uint tl_tile_header_index(uint tile, uint chunk) { return chunk * u_tiles.y * u_tiles.z + tile; }

// The lights a list holds: its count, or on overflow every local light of its chunk.
uint tl_tile_list_size(uvec2 h, uint chunk)
{
    return h.x != TL_TILE_OVERFLOW ? h.y : min(uint(TL_CULL_CHUNK), u_light_counts.y - chunk * uint(TL_CULL_CHUNK));
}

// A list entry: the light's index within its chunk (low 16 bits) and the mask of the tile's 4 x 4
// blocks it may reach (high 16 bits; light_cull.comp.glsl). On overflow, the chunk's k-th light
// and every block.
uint tl_tile_list_entry(uvec2 h, uint k) { return h.x != TL_TILE_OVERFLOW ? tl_tile_entries[h.x + k] : k | 0xFFFF0000u; }

// An entry's light (an index into tl_lights).
uint tl_tile_entry_light(uint e, uint chunk) { return u_light_counts.x + chunk * uint(TL_CULL_CHUNK) + (e & 0xFFFFu); }

// The bit of frame pixel px's block in an entry's high half.
uint tl_tile_block_bit(ivec2 px)
{
    uvec2 q = (uvec2(px) % u_tiles.x) / (u_tiles.x / 4u);
    return 0x10000u << (q.y * 4u + q.x);
}

// Whether local light i's range reaches p, reading its position and range alone (the rest of its
// record is read only for the lights that reach p).
bool tl_light_range_reaches(uint i, vec3 p)
{
    vec4 pr = tl_lights[i].position_radius;
    vec3 to_light = pr.xyz - p;
    return dot(to_light, to_light) < pr.w * pr.w;
}

#endif
