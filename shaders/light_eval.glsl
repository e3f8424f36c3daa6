// One light under the frame's lighting model, for every pass that evaluates lights (light volumes,
// tiled, forward): TL_GGX selects GGX (tl_ggx_light_terms), otherwise normalised Blinn-Phong
// (tl_light_terms). Both give three weights to multiply the light's colour with:
//   x: diffuse (times albedo),  y: specular times F0,  z: specular added as it is,
// so a light's radiance is albedo c x + F0 c y + c z whatever the model: Blinn-Phong has z = 0,
// GGX splits its specular w into w (1 - s) and w s with Schlick's s = (1 - v.h)^5 (docs/lighting.md).

#ifndef TL_LIGHT_EVAL_GLSL
#define TL_LIGHT_EVAL_GLSL

#include "codec.glsl"
#include "lighting.glsl"

// One light as every pass reads it (the lights storage block's record, tiles.glsl; the light
// volumes' instance, light.vert.glsl): view space; C packs it once (tl__light_record_fill).
struct tl_light_data {
    vec4 position_radius;     // view space
    vec4 color_type;          // linear colour, type (1 point, 2 spot, 3 directional)
    vec4 direction_cos_outer; // view space
    vec4 cos_inner;           // spot cos_inner, sphere light radius, shadow slot (0: none), specular scale
};

// The lobe's shape from the stored gloss, once per pixel: the GGX alpha or the Blinn-Phong power.
float tl_lobe_shape(float gloss)
{
#ifdef TL_GGX
    return tl_gloss_to_ggx_alpha(gloss);
#else
    return tl_gloss_to_specular_power(gloss);
#endif
}

// type: 1 point, 2 spot, 3 directional; position_radius.w is the light's range; source_radius the
// emitting sphere's (GGX only: Blinn-Phong lights are punctual).
vec3 tl_light_weights(int type, vec3 p, vec3 n, vec3 v, float shape, vec4 position_radius, vec3 direction,
                      float cos_inner, float cos_outer, float source_radius)
{
#ifdef TL_GGX
    return tl_ggx_light_terms(type, p, n, v, shape, position_radius.xyz, position_radius.w, source_radius, direction,
                              cos_inner, cos_outer);
#else
    return vec3(tl_light_terms(type, p, n, v, shape, position_radius.xyz, position_radius.w, direction, cos_inner,
                               cos_outer), 0.0);
#endif
}

// One light's weights at p (tl_light_weights of its record) with its specular scale on the
// specular terms: the one place a light's own factors apply, for every pass.
vec3 tl_light_data_weights(tl_light_data l, int type, vec3 p, vec3 n, vec3 v, float shape)
{
    vec3 t = tl_light_weights(type, p, n, v, shape, l.position_radius, l.direction_cos_outer.xyz, l.cos_inner.x,
                              l.direction_cos_outer.w, l.cos_inner.y);
    return vec3(t.x, t.yz * l.cos_inner.w);
}

#endif
