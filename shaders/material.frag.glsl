// Pass 3 (thin-lpp): the second geometry pass applies materials to the accumulated light
// (depth EQUAL). TL_NO_LIGHTS: no light buffer, ambient and emissive only.
#include "frame.glsl"
#include "light_eval.glsl"
#include "material.glsl"
#ifdef TL_IBL
#include "ibl.glsl" // image-based light: the environment's, with this pass's F0, gloss and normal
#endif
#ifdef TL_MODEL
#include "material_models.glsl" // this program's material model (TL_MODEL: its tl_material_model)
#endif

layout(binding = TL_UNIT_LIGHT_DIFFUSE) uniform sampler2D u_light_diffuse;
layout(binding = TL_UNIT_LIGHT_SPECULAR) uniform sampler2D u_light_specular;
layout(binding = TL_UNIT_LIGHT_FRESNEL) uniform sampler2D u_light_fresnel;
#if defined(TL_COAT_SUMS) && defined(TL_MODEL) && TL_MODEL == 2
layout(binding = TL_UNIT_LIGHT_COAT) uniform sampler2D u_light_coat; // the coat's own sum (coat_sums.glsl)
#ifdef TL_STIPPLE
#define TL_STIPPLE_COAT // gathered as the other sums are where layers took pixels (stipple_gather.glsl)
#endif
#endif

layout(location = TL_OUT_HDR) out vec4 o_color;
#include "ambient.glsl" // the ambient term, with SSAO's AO

vec3 tl_finite(vec3 c) // FP16 sums of many bright lights can reach Inf: keep targets finite
{
    return vec3(isinf(c.r) || isnan(c.r) ? 65504.0 : c.r, isinf(c.g) || isnan(c.g) ? 65504.0 : c.g,
                isinf(c.b) || isnan(c.b) ? 65504.0 : c.b);
}

// files are included once, at their first #include: the ones both blocks below use come first
#include "object.glsl"
#include "tiles.glsl"
#if (defined(TL_MSAA_LIGHT) || defined(TL_STIPPLE)) && !defined(TL_NO_LIGHTS)
#include "light_loop.glsl" // the one light loop: the re-lighting's and the stipple's
#endif
#if defined(TL_MSAA_LIGHT) && !defined(TL_NO_LIGHTS)
#include "light_relight.glsl" // re-lighting from lists: MSAA's edges
#endif
#if defined(TL_STIPPLE) && !defined(TL_NO_LIGHTS)
#include "stipple_opaque.glsl" // transparent layers took some of the G-buffer's pixels
#endif
#if defined(TL_MSAA_LIGHT) && !defined(TL_NO_LIGHTS)
#include "light_msaa.glsl" // multisampled over the one-sample light buffer
#endif

void main()
{
#if defined(TL_MSAA_LIGHT) && !defined(TL_NO_LIGHTS)
    vec2 dzw = vec2(dFdx(gl_FragCoord.z), dFdy(gl_FragCoord.z)); // MSAA: the fragment's depth slope
#endif
#if defined(TL_STIPPLE) && !defined(TL_NO_LIGHTS)
    float z_s = tl_stipple_linear_depth(gl_FragCoord.z);
    vec2 dz_s = vec2(dFdx(z_s), dFdy(z_s));
#endif
    tl_surface s = tl_material_surface();
    if (tl_material_masked(s)) discard;
    vec3 diffuse = vec3(0.0), specular = vec3(0.0), fresnel = vec3(0.0);
    float alpha = 1.0;
#if defined(TL_MODEL) && TL_MODEL == 2 && !defined(TL_COAT_SUMS)
    float relight_gloss = 1.0 - u_clearcoat_roughness; // a clearcoat's sums are its coat's (gbuffer.frag.glsl)
#else
    float relight_gloss = s.gloss;
#endif
#if defined(TL_MSAA_LIGHT) && !defined(TL_NO_LIGHTS)
    // HDR's alpha (read by no pass) marks the samples re-lit here: 0.5 (tests)
    if (tl_msaa_light(dzw, tl_material_normal(), relight_gloss, diffuse, specular, fresnel))
        alpha = 0.5;
#elif defined(TL_STIPPLE) && !defined(TL_NO_LIGHTS)
    if (tl_stipple_opaque_light(z_s, dz_s, tl_material_normal(), relight_gloss, any(greaterThan(s.specular, vec3(0.0))),
                                diffuse, specular, fresnel))
        alpha = 0.5; // lit here, as MSAA's re-lit samples are marked
#elif !defined(TL_NO_LIGHTS)
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 ld = texelFetch(u_light_diffuse, px, 0);
    diffuse = tl_finite(ld.rgb);
#if defined(TL_SPECULAR_EXACT)
    specular = tl_finite(texelFetch(u_light_specular, px, 0).rgb);
#ifdef TL_FRESNEL_SUMS
    fresnel = tl_finite(texelFetch(u_light_fresnel, px, 0).rgb);
#endif
#elif defined(TL_SPECULAR_COMPACT)
    // Compact layout: specular colour follows the diffuse light's chromaticity.
    float lum = tl_luminance(diffuse);
    specular = lum > 1e-8 ? diffuse * (min(ld.a, 65504.0) / lum) : vec3(0.0);
#endif
#endif
    // GGX: F0 S1 + S2 with the two sums (exact), or one sum times Schlick with n.v; Blinn-Phong: F0 S
#if defined(TL_GGX) && defined(TL_FRESNEL_NV) && !defined(TL_NO_LIGHTS)
    vec3 f0 = tl_fresnel_schlick(s.specular, clamp(dot(tl_material_normal(), normalize(-v_view_position)), 0.0, 1.0));
#else
    vec3 f0 = s.specular;
#endif
    vec3 ambient = tl_ambient(s.occlusion, ivec2(gl_FragCoord.xy), diffuse);
    vec3 c = s.albedo * (diffuse + ambient) + f0 * specular + fresnel + s.emissive;
#ifdef TL_MODEL
    float nv_m = clamp(dot(tl_material_normal(), normalize(-v_view_position)), 0.0, 1.0);
    tl_model_sums ms = tl_model_sums_from_buffer(diffuse, specular + fresnel, nv_m);
#if defined(TL_COAT_SUMS) && TL_MODEL == 2 && !defined(TL_NO_LIGHTS)
#ifdef TL_STIPPLE_COAT
    ms.coat = tl_stipple_coat;
#else
    ms.coat = tl_finite(texelFetch(u_light_coat, ivec2(gl_FragCoord.xy), 0).rgb); // RT0 kept the base's gloss
#endif
#endif
    c = tl_model_shade(TL_MODEL, s, nv_m, diffuse, ambient, f0 * specular + fresnel, ms);
#endif
#if defined(TL_IBL) && (!defined(TL_MODEL) || TL_MODEL != 1) // an unlit material takes no light, the environment's neither
    c += tl_ibl(s.albedo, s.specular, s.gloss, s.occlusion, tl_material_normal(), normalize(-v_view_position));
#endif
    o_color = vec4(min(c, vec3(65504.0)), alpha);
}
