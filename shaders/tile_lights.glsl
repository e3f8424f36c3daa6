// A pixel's light sums from the tile lists in separate vectors, as light-upsample's re-lit pixels
// (light_upsample.comp.glsl) take them: a thin wrapper of the one light loop (light_loop.glsl),
// which walks the lists and sums.
#ifndef TL_TILE_LIGHTS_GLSL
#define TL_TILE_LIGHTS_GLSL

#include "light_loop.glsl"

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
