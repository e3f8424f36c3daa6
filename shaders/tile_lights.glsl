// A pixel's light sums from the tile lists, as the tiled light pass (lights_tiled.glsl), the
// re-lighting (light_relight.glsl) and the light scale's re-lit pixels in light-upsample
// (light_upsample.comp.glsl) call them: thin wrappers of the one light loop (light_loop.glsl),
// which walks the lists and sums.
#ifndef TL_TILE_LIGHTS_GLSL
#define TL_TILE_LIGHTS_GLSL

#include "light_loop.glsl"

// One light's terms (zero when it cannot reach p, as the volumes discard).
vec3 tl_tiled_terms(tl_light_data l, vec3 p, vec3 n, vec3 v, float shape)
{
    return tl_light_reached_weights(l, int(l.color_type.w), p, n, v, shape);
}

// One light that may cast (its slot in cos_inner.z), added to the FP16-clamped sums.
void tl_tiled_add_shadowed(tl_light_data l, vec3 p, vec3 n, vec3 v, float shape, inout vec3 diffuse,
                           inout vec3 specular, inout vec3 fresnel)
{
    tl_light_sums s = tl_light_sums(diffuse, specular, fresnel);
    tl_light_visit(TL_LIGHTS_SUMS, l, true, tl_light_point_at(p, n, v, shape), s);
    diffuse = s.diffuse;
    specular = s.specular;
    fresnel = s.fresnel;
}

// The directional lights, then every light of frame pixel px's tile lists (tl_tile_lights_walk),
// added to the FP16-clamped sums.
void tl_tile_lights_add(ivec2 px, vec3 p, vec3 n, vec3 v, float shape, inout vec3 diffuse, inout vec3 specular,
                        inout vec3 fresnel)
{
    tl_light_sums s = tl_light_sums(diffuse, specular, fresnel);
    tl_tile_lights_walk(TL_LIGHTS_SUMS, px, tl_light_point_at(p, n, v, shape), s);
    diffuse = s.diffuse;
    specular = s.specular;
    fresnel = s.fresnel;
}

#endif
