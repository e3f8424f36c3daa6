// Material models (scene.h tl_material.model; docs/lighting.md, "Material models"): the pixel's
// colour from the light sums under its material's model. forward adds each light's exact terms
// (tl_model_light_add); the light pre-pass's material pass has only the light buffer's sums and
// approximates the terms the sums do not hold (tl_model_sums_from_buffer). Needs material.glsl
// (the parameters) and lighting.glsl / light_eval.glsl.

#ifndef TL_MATERIAL_MODELS_GLSL
#define TL_MATERIAL_MODELS_GLSL

#include "model_light.glsl" // tl_wrap_weight, tl_model_falloff

const int TL_MODEL_STANDARD = 0;
const int TL_MODEL_UNLIT = 1;
const int TL_MODEL_CLEARCOAT = 2;
const int TL_MODEL_SHEEN = 3;
const int TL_MODEL_WRAP = 4;
const int TL_MODEL_TOON = 5;

// The sums a model needs besides the standard ones (light colour times weight, summed):
// coat: the coat's GGX lobe with F = 1; sheen: the Charlie lobe; wrap: the wrapped diffuse.
struct tl_model_sums {
    vec3 coat;
    vec3 sheen;
    vec3 wrap;
};

// Coat Fresnel with n.v (glTF's fresnel_coat), times the coat's weight.
float tl_coat_fresnel(float nv)
{
    return u_clearcoat * (0.04 + 0.96 * tl_fresnel_weight(nv));
}

// Toon: the diffuse light's luminance rounded to 1 / steps bands (its chromaticity kept), the
// highlight a flat one of luminance 1 where the specular radiance's luminance passes 1/2.
vec3 tl_toon_ramp(vec3 d, float steps)
{
    float l = tl_luminance(d);
    if (!(l > 0.0)) return vec3(0.0);
    return d * (floor(l * steps + 0.5) / (steps * l));
}

vec3 tl_toon_highlight(vec3 sp)
{
    float l = tl_luminance(sp);
    return l > 0.5 ? sp / l : vec3(0.0);
}

// The pixel's colour under `model`. d: the diffuse light sum; a: the ambient term (ambient times
// occlusion); sp: the standard specular radiance (F0 S1 + S2, or the frame's equivalent).
vec3 tl_model_shade(int model, tl_surface s, float nv, vec3 d, vec3 a, vec3 sp, tl_model_sums m)
{
    if (model == TL_MODEL_UNLIT) return s.albedo + s.emissive;
    if (model == TL_MODEL_WRAP) d = m.wrap;
    if (model == TL_MODEL_TOON) {
        d = tl_toon_ramp(d, u_toon_steps);
        sp = tl_toon_highlight(sp);
    }
    vec3 c = s.albedo * (d + a) + sp + s.emissive;
    if (model == TL_MODEL_SHEEN) c += u_sheen_color * m.sheen;
    if (model == TL_MODEL_CLEARCOAT) {
        float fc = tl_coat_fresnel(nv);
        c = c * (1.0 - fc) + fc * m.coat;
    }
    return c;
}

// The sheen lobe's mean over light directions weighted as the diffuse sum weighs them (n.l):
// pi D V averaged over 4 x 4 stratified cosine-weighted directions, v in the x-z plane of the
// normal's frame. The sheen sum is the diffuse sum times this: exact for light arriving evenly
// from the hemisphere, approximate for a few lights.
float tl_sheen_mean(float nv, float r)
{
    vec3 v = vec3(sqrt(max(1.0 - nv * nv, 0.0)), 0.0, nv);
    float sum = 0.0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            float u1 = (float(i) + 0.5) / 4.0, phi = 2.0 * TL_PI * (float(j) + 0.5) / 4.0;
            float st = sqrt(u1), nl = sqrt(1.0 - u1);
            vec3 h = normalize(vec3(st * cos(phi), st * sin(phi), nl) + v);
            sum += TL_PI * tl_charlie_d(h.z, r) * tl_sheen_vis(nl, nv);
        }
    return sum / 16.0;
}

// The light pre-pass: the models' sums from the light buffer's. d: the diffuse sum; spec: the
// specular sum with F = 1 (S1 + S2). A clearcoat's G-buffer holds the coat's roughness
// (gbuffer.frag.glsl), so spec is the coat's own sum (and the base's specular is approximated with
// the coat's lobe); the sheen sum is the diffuse sum times the lobe's mean (tl_sheen_mean); the
// wrap scales the diffuse sum to the wrapped weight at n.l = 1/2.
tl_model_sums tl_model_sums_from_buffer(vec3 d, vec3 spec, float nv)
{
    tl_model_sums m;
    m.coat = spec;
    m.sheen = d * tl_sheen_mean(nv, u_sheen_roughness);
    m.wrap = d * (tl_wrap_weight(0.5, u_wrap) / 0.5);
    return m;
}

#ifdef TL_FORWARD
// forward: each light's exact model terms, summed over the pixel's lights (tl_model_light_add).
tl_model_sums tl_model_acc = tl_model_sums(vec3(0.0), vec3(0.0), vec3(0.0));

// `vis`: the light's visibility at p (its shadow; 1 without one).
void tl_model_light_add(tl_light_data ld, vec3 p, vec3 n, vec3 v, float vis)
{
    int model = u_material_model, type = int(ld.color_type.w);
    vec3 c = ld.color_type.rgb * vis;
    if (model == TL_MODEL_CLEARCOAT) {
        float shape = tl_lobe_shape(1.0 - u_clearcoat_roughness);
        vec3 t = tl_light_data_weights(ld, type, p, n, v, shape);
        tl_model_acc.coat += c * min(t.y + t.z, TL_LIGHT_CLAMP);
        return;
    }
    if (model != TL_MODEL_SHEEN && model != TL_MODEL_WRAP) return;
    vec3 l;
    float att = tl_model_falloff(type, p, n, ld.position_radius, ld.direction_cos_outer.xyz, ld.cos_inner.x,
                                 ld.direction_cos_outer.w, l);
    float nl = dot(n, l);
    if (model == TL_MODEL_WRAP) {
        tl_model_acc.wrap += c * min(att * tl_wrap_weight(nl, u_wrap), TL_LIGHT_CLAMP);
        return;
    }
    tl_model_acc.sheen += c * tl_sheen_weight(n, v, l, att, u_sheen_roughness);
}
#endif

#endif
