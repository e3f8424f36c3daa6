// Tiled light lists: the frame's visible lights (view space, directional ones first) and, per
// screen tile, the local lights that may reach a surface in it (light_cull.comp.glsl writes them;
// the tiled light pass and Forward+ read them). docs/frame.md, "Tiled light accumulation".

#ifndef TL_TILES_GLSL
#define TL_TILES_GLSL

#include "frame.glsl"

struct tl_light_data {
    vec4 position_radius;     // view space
    vec4 color_type;          // linear colour, type (1 point, 2 spot, 3 directional)
    vec4 direction_cos_outer; // view space
    vec4 cos_inner;
};
layout(std430, binding = TL_SSBO_LIGHTS) readonly buffer tl_light_buffer { tl_light_data tl_lights[]; };

// A tile whose list did not fit in the entries buffer: its pixels loop over every visible light.
const uint TL_TILE_OVERFLOW = 0xFFFFFFFFu;

#ifdef TL_TILES_WRITE
#define TL_TILES_ACCESS
#else
#define TL_TILES_ACCESS readonly
#endif
// tl_counters: entries used, tiles that overflowed, pixel-light pairs (low and high 32 bits)
layout(std430, binding = TL_SSBO_TILE_HEADERS) TL_TILES_ACCESS buffer tl_tile_header_buffer {
    uvec4 tl_counters;
    uvec2 tl_tile_headers[]; // (first entry, count) per tile, row by row
};
layout(std430, binding = TL_SSBO_TILE_ENTRIES) TL_TILES_ACCESS buffer tl_tile_entry_buffer { uint tl_tile_entries[]; };

uint tl_tile_index(ivec2 px)
{
    uvec2 t = uvec2(px) / u_tiles.x;
    return t.y * u_tiles.y + t.x;
}

#endif
