// A pixel's light sums from the tile lists (tiles.glsl): one light's clamped terms, and the
// directional lights plus the lists of its tile. The tiled light pass (lights_tiled.glsl) and the
// light scale's fix-up in the material pass (light_upsample.glsl) sum with these.
#ifndef TL_TILE_LIGHTS_GLSL
#define TL_TILE_LIGHTS_GLSL

#include "light_eval.glsl"
#include "tiles.glsl"
#ifdef TL_SHADOWS
#include "shadow.glsl"
#endif

// One light's clamped terms added to the sums; nothing when it cannot reach p (as the volumes discard).
void tl_tiled_add(tl_light_data l, vec3 p, vec3 n, vec3 v, float shape, inout vec3 diffuse, inout vec3 specular,
                  inout vec3 fresnel)
{
    int type = int(l.color_type.w);
    if (type != 3) {
        vec3 to_light = l.position_radius.xyz - p;
        float d2 = dot(to_light, to_light);
        if (d2 >= l.position_radius.w * l.position_radius.w) return;
        if (type == 2 && d2 > 0.0 && dot(-to_light, l.direction_cos_outer.xyz) <= l.direction_cos_outer.w * sqrt(d2)) return;
    }
    vec3 t = tl_light_weights(type, p, n, v, shape, l.position_radius, l.direction_cos_outer.xyz, l.cos_inner.x,
                              l.direction_cos_outer.w, l.cos_inner.y);
    const vec3 fp16_max = vec3(65504.0);
#ifdef TL_SHADOWS
    if (l.cos_inner.z > 0.0 && t != vec3(0.0))
        t *= tl_shadow(l.cos_inner.z, p, n, tl_shadow_to_light(type, p, l.position_radius.xyz, l.direction_cos_outer.xyz), l.position_radius.xyz);
#endif
    diffuse += min(l.color_type.rgb * t.x, fp16_max);
    specular += min(l.color_type.rgb * t.y, fp16_max);
    fresnel += min(l.color_type.rgb * t.z, fp16_max);
}

// The directional lights, then every light of `tile`'s lists (chunk by chunk, in their order).
void tl_tile_lights_add(uint tile, vec3 p, vec3 n, vec3 v, float shape, inout vec3 diffuse, inout vec3 specular,
                        inout vec3 fresnel)
{
    for (uint i = 0u; i < u_light_counts.x; i++) tl_tiled_add(tl_lights[i], p, n, v, shape, diffuse, specular, fresnel);
    uint chunks = tl_tile_chunks();
    for (uint c = 0u; c < chunks; c++) {
        uvec2 h = tl_tile_headers[tl_tile_header_index(tile, c)];
        uint count = tl_tile_list_size(h, c);
        for (uint k = 0u; k < count; k++)
            tl_tiled_add(tl_lights[tl_tile_list_light(h, c, k)], p, n, v, shape, diffuse, specular, fresnel);
    }
}

#endif
