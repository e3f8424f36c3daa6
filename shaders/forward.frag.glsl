// Forward shading (forward mode, and alpha-blended materials in every mode): each fragment
// evaluates the lights in its object's list (built on the CPU per frame, lights whose range
// reaches the object's bounds), or with TL_FORWARD_TILED (Forward+) the directional lights and
// its tile's list. TL_DEPTH_ONLY: the depth pre-pass. TL_TRANSPARENT: alpha out.
#include "codec.glsl"
#include "frame.glsl"
#include "lighting.glsl"
#include "material.glsl"
#include "object.glsl"

#ifndef TL_DEPTH_ONLY
#include "tiles.glsl" // the lights block (and, for Forward+, the tile lists)
layout(std430, binding = TL_SSBO_FORWARD_INDICES) readonly buffer tl_light_index_buffer { uint tl_light_indices[]; };

layout(location = TL_OUT_HDR) out vec4 o_color;
#ifdef TL_SSAO_AMBIENT
layout(binding = TL_UNIT_AO) uniform sampler2D u_ao;
#endif

void tl_forward_add(tl_light_data l, vec3 p, vec3 n, vec3 v, float power, inout vec3 diffuse, inout vec3 specular)
{
    vec2 t = tl_light_terms(int(l.color_type.w), p, n, v, power, l.position_radius.xyz, l.position_radius.w,
                            l.direction_cos_outer.xyz, l.cos_inner.x, l.direction_cos_outer.w);
    diffuse += l.color_type.rgb * t.x;
    specular += l.color_type.rgb * t.y;
}
#endif

void main()
{
    tl_surface s = tl_material_surface();
    if (tl_material_masked(s)) discard;
#ifndef TL_DEPTH_ONLY
    vec3 n = tl_material_normal();
    vec3 p = v_view_position;
    vec3 v = normalize(-p);
    float power = tl_gloss_to_specular_power(s.gloss);
    vec3 diffuse = vec3(0.0), specular = vec3(0.0);
#ifdef TL_FORWARD_TILED
    // Forward+: the directional lights, then the pixel's tile lists (every local light of a chunk
    // whose list overflowed)
    for (uint i = 0u; i < u_light_counts.x; i++) tl_forward_add(tl_lights[i], p, n, v, power, diffuse, specular);
    uint tile = tl_tile_index(ivec2(gl_FragCoord.xy)), chunks = tl_tile_chunks();
    for (uint c = 0u; c < chunks; c++) {
        uvec2 h = tl_tile_headers[tl_tile_header_index(tile, c)];
        uint count = tl_tile_list_size(h, c);
        for (uint k = 0u; k < count; k++)
            tl_forward_add(tl_lights[tl_tile_list_light(h, c, k)], p, n, v, power, diffuse, specular);
    }
#else
    uint first = tl_objects[v_object].lights.x, count = tl_objects[v_object].lights.y;
    for (uint k = 0u; k < count; k++)
        tl_forward_add(tl_lights[tl_light_indices[first + k]], p, n, v, power, diffuse, specular);
#endif
#ifdef TL_SPECULAR_NONE
    specular = vec3(0.0);
#endif
#ifdef TL_SSAO_AMBIENT
    // SSAO (docs/effects.md): the ambient term, and with TL_SSAO_DIFFUSE the diffuse light
    float ao = texelFetch(u_ao, ivec2(gl_FragCoord.xy), 0).r;
#ifdef TL_SSAO_DIFFUSE
    diffuse *= ao;
#endif
    vec3 c = s.albedo * (diffuse + u_ambient * (s.occlusion * ao)) + s.specular * specular + s.emissive;
#else
    vec3 c = s.albedo * (diffuse + u_ambient * s.occlusion) + s.specular * specular + s.emissive;
#endif
#ifdef TL_TRANSPARENT
    o_color = vec4(min(c, vec3(65504.0)), clamp(s.alpha, 0.0, 1.0));
#else
    o_color = vec4(min(c, vec3(65504.0)), 1.0);
#endif
#endif
}
