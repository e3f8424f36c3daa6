// The deferred modes' material models (docs/lighting.md, "Material models", "The other modes"): the
// light pass shades each light under the pixel's model as forward does (tl_model_light_add): unlit
// adds nothing, wrap's diffuse weight is the wrapped one, clearcoat blends the base with the coat's
// lobe by the coat's Fresnel, fat's sheen adds its colour times the Charlie lobe. Toon is shaded as
// standard (not a sum of per-light terms), so is thin-deferred's sheen (no room for its colour).
// Where the model is stored:
//   fat: fat.position.w = 1 + model + frac / 2, frac the wrap, a clearcoat's 8-bit factor and
//        roughness as (q_c 256 + q_r) / 2^16, or a sheen's 4-bit colour (clamped to 1) and 8-bit
//        roughness as (r 2^16 + g 2^12 + b 2^8 + q_r) / 2^20 (RGBA32F holds it exactly);
//   thin-deferred: RT1.a's byte = model | q5 << 3, q5 the wrap or the coat's roughness in 5 bits
//        (the coat's factor is taken as 1; the byte is free unless SSAO stores occlusion there).
// Needs gbuffer_decode.glsl.
#ifndef TL_FAT_MODELS_GLSL
#define TL_FAT_MODELS_GLSL

#include "light_eval.glsl"
#include "model_light.glsl"

struct tl_fat_model {
    int model;
    float wrap;       // wrap: the wrap parameter
    float coat_shape; // clearcoat: the coat's lobe shape
    float fc;         // clearcoat: the coat's Fresnel times its factor, with n.v
    vec3 sheen_color; // fat's sheen
    float sheen_r;
};

tl_fat_model tl_fat_model_read(ivec2 px, vec3 n, vec3 v)
{
    tl_fat_model fm;
    float nv = clamp(dot(n, v), 0.0, 1.0);
#ifdef TL_LIGHT_SHADE_FAT
    float w = max(tl_gfetch(u_fat_position, px).w - 1.0, 0.0);
    fm.model = int(w);
    float frac = (w - float(fm.model)) * 2.0;
    uint q = uint(frac * 65536.0 + 0.5);
    fm.wrap = frac;
    fm.coat_shape = tl_lobe_shape(1.0 - float(q & 255u) / 255.0);
    fm.fc = float(q >> 8) / 255.0 * (0.04 + 0.96 * tl_fresnel_weight(nv));
    uint qs = uint(frac * 1048576.0 + 0.5);
    fm.sheen_color = vec3(uvec3(qs >> 16, qs >> 12, qs >> 8) & 15u) / 15.0;
    fm.sheen_r = max(float(qs & 255u) / 255.0, 0.07);
#else
    uint b = tl_unorm8_bytes(tl_gfetch(u_rt1, px)).a;
    fm.model = int(b & 7u);
    fm.wrap = float(b >> 3) / 31.0;
    fm.coat_shape = tl_lobe_shape(1.0 - fm.wrap);
    fm.fc = 0.04 + 0.96 * tl_fresnel_weight(nv);
    fm.sheen_color = vec3(0.0);
    fm.sheen_r = 1.0;
#endif
    return fm;
}

// One light's radiance on the pixel under its model (the light's record and type, and the pixel's
// albedo and specular colour).
vec3 tl_fat_model_radiance(tl_fat_model fm, tl_light_data ld, int type, vec3 p, vec3 n, vec3 v, float shape,
                           vec3 albedo, vec3 spec_color)
{
    if (fm.model == 1) return vec3(0.0); // unlit
    vec3 t = tl_light_data_weights(ld, type, p, n, v, shape), color = ld.color_type.rgb;
    vec4 position_radius = ld.position_radius;
    vec3 direction = ld.direction_cos_outer.xyz;
    float cos_inner = ld.cos_inner.x, cos_outer = ld.direction_cos_outer.w;
    const vec3 fp16_max = vec3(65504.0);
    vec3 d = min(color * t.x, fp16_max);
    vec3 l, sheen = vec3(0.0);
    if (fm.model == 3 || fm.model == 4) {
        float att = tl_model_falloff(type, p, n, position_radius, direction, cos_inner, cos_outer, l);
        if (fm.model == 4) d = color * min(att * tl_wrap_weight(dot(n, l), fm.wrap), TL_LIGHT_CLAMP);
        else sheen = fm.sheen_color * color * tl_sheen_weight(n, v, l, att, fm.sheen_r);
    }
#ifdef TL_SPECULAR_NONE
    t.yz = vec2(0.0);
#endif
    vec3 c = albedo * d + spec_color * min(color * t.y, fp16_max) + min(color * t.z, fp16_max);
    if (fm.model == 2) {
        vec3 tc = tl_light_data_weights(ld, type, p, n, v, fm.coat_shape);
        c = c * (1.0 - fm.fc) + fm.fc * color * min(tc.y + tc.z, TL_LIGHT_CLAMP);
    }
    return c + sheen;
}

#endif
