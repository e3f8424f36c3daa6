// The light scale's edge fix-up (docs/frame.md, "Light at reduced resolution"): one invocation per
// pixel the material pass listed (no credible reduced texel near it), lit at full resolution from
// DEPTH, RT0 and its tile's lists exactly as the tiled light pass lights a pixel at scale 1, times
// the albedo and specular colour the material pass listed with it, plus the colour it had without
// light (ambient, emissive), written to HDR with alpha 0.5 (the re-lit mark). Written, not added:
// a pixel two coplanar surfaces both drew at its depth is listed twice, and each entry writes a
// whole colour of its own surface (which one stays is unordered, as z-fighting is).
#include "lights_tiled.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = TL_SSBO_FIXUP) readonly buffer tl_fixup_buffer { uvec4 tl_fixup_counters; uvec4 tl_fixup_entries[]; };
layout(rgba16f, binding = TL_IMAGE_HDR) uniform writeonly image2D u_hdr_image;

void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i >= min(tl_fixup_counters.w, uint(tl_fixup_entries.length()) / 2u)) return;
    uvec4 e = tl_fixup_entries[2u * i], e2 = tl_fixup_entries[2u * i + 1u];
    ivec2 px = ivec2(e.x & 0xFFFFu, e.x >> 16);
    vec2 a = unpackHalf2x16(e.y), b = unpackHalf2x16(e.z), c = unpackHalf2x16(e.w);
    vec3 albedo = vec3(a, b.x), f0 = vec3(b.y, c), base = vec3(unpackHalf2x16(e2.x), unpackHalf2x16(e2.y).x);
    tl_tiled_result r = tl_tiled_shade(px);
    vec3 lit = r.surface ? albedo * r.diffuse + f0 * r.specular + r.fresnel : vec3(0.0);
    imageStore(u_hdr_image, px, vec4(min(base + lit, vec3(65504.0)), 0.5));
}
