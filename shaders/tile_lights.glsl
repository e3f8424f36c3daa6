// A pixel's light sums from the tile lists (tiles.glsl): one light's clamped terms, and the
// directional lights plus the lists of its tile. The tiled light pass (lights_tiled.glsl) and the
// light scale's re-lit pixels in light-upsample (light_upsample.comp.glsl) sum with these.
#ifndef TL_TILE_LIGHTS_GLSL
#define TL_TILE_LIGHTS_GLSL

#include "light_eval.glsl"
#include "tiles.glsl"
#ifdef TL_SHADOWS
#include "shadow.glsl"
#endif

// One light's terms (zero when it cannot reach p, as the volumes discard).
vec3 tl_tiled_terms(tl_light_data l, vec3 p, vec3 n, vec3 v, float shape)
{
    int type = int(l.color_type.w);
    if (type != 3) {
        vec3 to_light = l.position_radius.xyz - p;
        float d2 = dot(to_light, to_light);
        if (d2 >= l.position_radius.w * l.position_radius.w) return vec3(0.0);
        if (type == 2 && d2 > 0.0 && dot(-to_light, l.direction_cos_outer.xyz) <= l.direction_cos_outer.w * sqrt(d2)) return vec3(0.0);
    }
    return tl_light_data_weights(l, type, p, n, v, shape);
}

// The clamped terms t of light l added to the sums.
void tl_tiled_sum(tl_light_data l, vec3 t, inout vec3 diffuse, inout vec3 specular, inout vec3 fresnel)
{
    const vec3 fp16_max = vec3(65504.0);
    diffuse += min(l.color_type.rgb * t.x, fp16_max);
    specular += min(l.color_type.rgb * t.y, fp16_max);
    fresnel += min(l.color_type.rgb * t.z, fp16_max);
}

// One light without a shadow, added to the sums.
void tl_tiled_add(tl_light_data l, vec3 p, vec3 n, vec3 v, float shape, inout vec3 diffuse, inout vec3 specular,
                  inout vec3 fresnel)
{
    tl_tiled_sum(l, tl_tiled_terms(l, p, n, v, shape), diffuse, specular, fresnel);
}

// One light that may cast (its slot in cos_inner.z), added to the sums.
void tl_tiled_add_shadowed(tl_light_data l, vec3 p, vec3 n, vec3 v, float shape, inout vec3 diffuse,
                           inout vec3 specular, inout vec3 fresnel)
{
    vec3 t = tl_tiled_terms(l, p, n, v, shape);
#ifdef TL_SHADOWS
    if (l.cos_inner.z > 0.0 && t != vec3(0.0))
        t *= tl_light_shadow(l.cos_inner.z, int(l.color_type.w), p, n, l.position_radius.xyz, l.direction_cos_outer.xyz);
#endif
    tl_tiled_sum(l, t, diffuse, specular, fresnel);
}

// The directional lights, then every light of `tile`'s lists (chunk by chunk, in their order). The
// casting local lights come first in the lights block (u_light_counts.z ends them), so a list
// starts with them: only that first run of a list carries the shadow lookup's code, which llvmpipe
// would otherwise run (masked) for every light of the list.
void tl_tile_lights_add(uint tile, vec3 p, vec3 n, vec3 v, float shape, inout vec3 diffuse, inout vec3 specular,
                        inout vec3 fresnel)
{
    for (uint i = 0u; i < u_light_counts.x; i++) tl_tiled_add_shadowed(tl_lights[i], p, n, v, shape, diffuse, specular, fresnel);
    uint chunks = tl_tile_chunks();
    for (uint c = 0u; c < chunks; c++) {
        uvec2 h = tl_tile_headers[tl_tile_header_index(tile, c)];
        uint count = tl_tile_list_size(h, c), k = 0u;
#ifdef TL_SHADOWS
        for (; k < count; k++) {
            uint i = tl_tile_list_light(h, c, k);
            if (i >= u_light_counts.z) break;
            tl_tiled_add_shadowed(tl_lights[i], p, n, v, shape, diffuse, specular, fresnel);
        }
#endif
        for (; k < count; k++)
            tl_tiled_add(tl_lights[tl_tile_list_light(h, c, k)], p, n, v, shape, diffuse, specular, fresnel);
    }
}

#endif
