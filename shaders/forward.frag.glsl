// Forward shading (forward mode, and alpha-blended materials in every mode): each fragment
// evaluates the lights in its object's list (built on the CPU per frame, lights whose range
// reaches the object's bounds), or with TL_FORWARD_TILED (Forward+) the directional lights and
// its tile's list. TL_DEPTH_ONLY: the depth pre-pass. TL_TRANSPARENT: alpha out.
#include "codec.glsl"
#include "frame.glsl"
#include "light_eval.glsl"
#include "material.glsl"
#include "object.glsl"
#ifdef TL_IBL
#include "ibl.glsl" // image-based light from the environment
#endif
#ifdef TL_STIPPLE
#include "stipple_gather.glsl" // the layer's light from its own pixels of the G-buffer
#endif

#ifndef TL_DEPTH_ONLY
#include "tiles.glsl" // the lights block (and, for Forward+, the tile lists)
#ifdef TL_SHADOWS
#include "shadow.glsl"
#endif
layout(std430, binding = TL_SSBO_FORWARD_INDICES) readonly buffer tl_light_index_buffer { uint tl_light_indices[]; };
#if defined(TL_MATERIAL_MODELS) && defined(TL_FORWARD)
#include "material_models.glsl" // per-material models: each light's exact terms
#endif

layout(location = TL_OUT_HDR) out vec4 o_color;
#ifdef TL_SSAO_AMBIENT
layout(binding = TL_UNIT_AO) uniform sampler2D u_ao;
#endif

void tl_forward_add(tl_light_data l, vec3 p, vec3 n, vec3 v, float shape, inout vec3 diffuse, inout vec3 specular,
                    inout vec3 fresnel)
{
    vec3 t = tl_light_data_weights(l, int(l.color_type.w), p, n, v, shape);
    float vis = 1.0;
#ifdef TL_SHADOWS
#if defined(TL_MATERIAL_MODELS) && defined(TL_FORWARD)
    bool lit = true; // a model's own terms (wrap, sheen) may reach past the standard ones
#else
    bool lit = t != vec3(0.0);
#endif
    if (l.cos_inner.z > 0.0 && lit)
        vis = tl_light_shadow(l.cos_inner.z, int(l.color_type.w), p, n, l.position_radius.xyz, l.direction_cos_outer.xyz);
    t *= vis;
#endif
    diffuse += l.color_type.rgb * t.x;
    specular += l.color_type.rgb * t.y;
    fresnel += l.color_type.rgb * t.z;
#if defined(TL_MATERIAL_MODELS) && defined(TL_FORWARD)
    tl_model_light_add(l, p, n, v, vis);
#endif
}
#endif

void main()
{
#ifdef TL_STIPPLE
    float z_s = tl_stipple_linear_depth(gl_FragCoord.z);
    vec2 dz_s = vec2(dFdx(z_s), dFdy(z_s));
#endif
    tl_surface s = tl_material_surface();
    if (tl_material_masked(s)) discard;
#ifndef TL_DEPTH_ONLY
    vec3 n = tl_material_normal();
    vec3 p = v_view_position;
    vec3 v = normalize(-p);
    float shape = tl_lobe_shape(s.gloss);
    vec3 diffuse = vec3(0.0), specular = vec3(0.0), fresnel = vec3(0.0);
#ifdef TL_FORWARD_TILED
    // Forward+: the directional lights, then the pixel's tile lists (every local light of a chunk
    // whose list overflowed)
    for (uint i = 0u; i < u_light_counts.x; i++) tl_forward_add(tl_lights[i], p, n, v, shape, diffuse, specular, fresnel);
    ivec2 px = ivec2(gl_FragCoord.xy);
    uint tile = tl_tile_index(px), bit = tl_tile_block_bit(px), chunks = tl_tile_chunks();
    for (uint c = 0u; c < chunks; c++) {
        uvec2 h = tl_tile_headers[tl_tile_header_index(tile, c)];
        uint count = tl_tile_list_size(h, c);
        for (uint k = 0u; k < count; k++) {
            uint e = tl_tile_list_entry(h, k);
            if ((e & bit) != 0u) tl_forward_add(tl_lights[tl_tile_entry_light(e, c)], p, n, v, shape, diffuse, specular, fresnel);
        }
    }
#else
#ifdef TL_STIPPLE
    // the stipple's resolve: the light of the layer's own pixels, or (none credible) forward
    vec4 ld;
    vec3 ls, lf;
    float total = tl_stipple_layer_light(tl_stipple_layer(), z_s, dz_s, n,
                                         tl_stipple_power(any(greaterThan(s.specular, vec3(0.0))), s.gloss), ld, ls, lf);
    if (total >= TL_STIPPLE_CREDIBLE) {
        tl_stipple_finish(total, ld, ls, lf, diffuse, specular, fresnel);
#ifdef TL_FRESNEL_NV
        fresnel = tl_fresnel_schlick(s.specular, clamp(dot(n, v), 0.0, 1.0)) * specular; // as the material pass
        specular = vec3(0.0);
#endif
    } else
#endif
    {
        uint first = tl_objects[v_object].lights.x, count = tl_objects[v_object].lights.y;
        for (uint k = 0u; k < count; k++)
            tl_forward_add(tl_lights[tl_light_indices[first + k]], p, n, v, shape, diffuse, specular, fresnel);
    }
#endif
#ifdef TL_SPECULAR_NONE
    specular = fresnel = vec3(0.0);
#endif
#ifdef TL_SSAO_AMBIENT
    // SSAO (docs/effects.md): the ambient term, and with TL_SSAO_DIFFUSE the diffuse light
    float ao = texelFetch(u_ao, ivec2(gl_FragCoord.xy), 0).r;
#ifdef TL_SSAO_DIFFUSE
    diffuse *= ao;
#endif
    vec3 ambient = u_ambient * (s.occlusion * ao);
#else
    vec3 ambient = u_ambient * s.occlusion;
#endif
    vec3 c = s.albedo * (diffuse + ambient) + s.specular * specular + fresnel + s.emissive;
#if defined(TL_MATERIAL_MODELS) && defined(TL_FORWARD) && !defined(TL_STIPPLE)
    c = tl_model_shade(u_material_model, s, clamp(dot(n, v), 0.0, 1.0), diffuse, ambient, s.specular * specular + fresnel,
                       tl_model_acc);
#endif
#ifdef TL_IBL
#if defined(TL_MATERIAL_MODELS) && defined(TL_FORWARD) && !defined(TL_STIPPLE)
    if (u_material_model != TL_MODEL_UNLIT) // an unlit material takes no light, the environment's neither
#endif
        c += tl_ibl(s.albedo, s.specular, s.gloss, s.occlusion, n, v);
#endif
#ifdef TL_TRANSPARENT
    o_color = vec4(min(c, vec3(65504.0)), clamp(s.alpha, 0.0, 1.0));
#else
    o_color = vec4(min(c, vec3(65504.0)), 1.0);
#endif
#endif
}
