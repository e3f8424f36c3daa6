// The light scale's edge fix-up (docs/frame.md, "Light at reduced resolution"): one invocation per
// pixel the material pass listed (no credible reduced texel near it), lit at full resolution from
// DEPTH, RT0 and its tile's lists exactly as the tiled light pass lights a pixel at scale 1, times
// the albedo and specular colour the material pass listed with it, added to HDR. The material pass
// wrote that pixel's ambient, emissive and HDR alpha 0.5 (the re-lit mark) already.
#include "lights_tiled.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = TL_SSBO_FIXUP) readonly buffer tl_fixup_buffer { uvec4 tl_fixup_counters; uvec4 tl_fixup_entries[]; };
layout(rgba16f, binding = TL_IMAGE_HDR) uniform image2D u_hdr_image;

void main()
{
    uint i = gl_GlobalInvocationID.x;
    if (i >= min(tl_fixup_counters.w, uint(tl_fixup_entries.length()))) return;
    uvec4 e = tl_fixup_entries[i];
    ivec2 px = ivec2(e.x & 0xFFFFu, e.x >> 16);
    vec2 a = unpackHalf2x16(e.y), b = unpackHalf2x16(e.z), c = unpackHalf2x16(e.w);
    vec3 albedo = vec3(a, b.x), f0 = vec3(b.y, c);
    tl_tiled_result r = tl_tiled_shade(px);
    if (!r.surface) return;
    vec4 h = imageLoad(u_hdr_image, px);
    vec3 lit = albedo * r.diffuse + f0 * r.specular + r.fresnel;
    imageStore(u_hdr_image, px, vec4(min(h.rgb + lit, vec3(65504.0)), h.a));
}
