// Material models' per-light terms shared by forward (material_models.glsl) and fat's light pass
// (fat_models.glsl): the sheen's lobe, the wrapped diffuse weight and the light's falloff with its
// direction.
#ifndef TL_MODEL_LIGHT_GLSL
#define TL_MODEL_LIGHT_GLSL

#include "light_eval.glsl"

// Charlie sheen distribution (Estevez and Kulla, "Production Friendly Microfacet Sheen BRDF", 2017),
// r: sheen roughness (floored at 0.07 on the CPU).
float tl_charlie_d(float nh, float r)
{
    float inv = 1.0 / r;
    float sin2 = max(1.0 - nh * nh, 0.0);
    return (2.0 + inv) * pow(sin2, 0.5 * inv) / (2.0 * TL_PI);
}

// Neubelt and Pettineo's cloth visibility 1 / (4 (n.l + n.v - n.l n.v)), finite at n.l = n.v = 0.
float tl_sheen_vis(float nl, float nv)
{
    return 1.0 / max(4.0 * (nl + nv - nl * nv), 1e-4);
}

// Energy-conserving wrapped Lambert: max(n.l + w, 0) / (1 + w)^2 (integrates to Lambert's pi).
float tl_wrap_weight(float nl, float w)
{
    return max(nl + w, 0.0) / ((1.0 + w) * (1.0 + w));
}

// The light's windowed falloff (and spot cone) with the direction to it, as the standard model's
// punctual diffuse weight has them (a sphere light's centre stands for the sphere).
float tl_model_falloff(int type, vec3 p, vec3 n, vec4 position_radius, vec3 direction, float cos_inner,
                       float cos_outer, out vec3 l)
{
    if (type == 3) {
        l = -direction;
        return 1.0;
    }
    vec3 to = position_radius.xyz - p;
    float dist = length(to);
    l = dist > 1e-6 ? to / dist : n;
    float att = tl_attenuation(dist, position_radius.w);
    if (type == 2) att *= tl_spot(l, direction, cos_inner, cos_outer);
    return att;
}

// One light's sheen weight (forward's, per light): pi D_c V n.l times the falloff; r: the sheen
// roughness; att and l from tl_model_falloff.
float tl_sheen_weight(vec3 n, vec3 v, vec3 l, float att, float r)
{
    float nl = dot(n, l);
    vec3 h = l + v;
    float hl2 = dot(h, h);
    if (!(nl > 0.0) || hl2 < 1e-12) return 0.0;
    float nh = dot(n, h * inversesqrt(hl2));
    float nv = clamp(dot(n, v), 0.0, 1.0);
    return min(TL_PI * tl_charlie_d(nh, r) * tl_sheen_vis(nl, nv) * nl * att, TL_LIGHT_CLAMP);
}

#endif
