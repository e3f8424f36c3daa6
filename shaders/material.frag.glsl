// Pass 3 (thin-lpp): the second geometry pass applies materials to the accumulated light
// (depth EQUAL). TL_NO_LIGHTS: no light buffer, ambient and emissive only.
#include "frame.glsl"
#include "lighting.glsl"
#include "material.glsl"

layout(binding = TL_UNIT_LIGHT_DIFFUSE) uniform sampler2D u_light_diffuse;
layout(binding = TL_UNIT_LIGHT_SPECULAR) uniform sampler2D u_light_specular;

layout(location = TL_OUT_HDR) out vec4 o_color;
#ifdef TL_SSAO_AMBIENT
layout(binding = TL_UNIT_AO) uniform sampler2D u_ao;
#endif

vec3 tl_finite(vec3 c) // FP16 sums of many bright lights can reach Inf: keep targets finite
{
    return vec3(isinf(c.r) || isnan(c.r) ? 65504.0 : c.r, isinf(c.g) || isnan(c.g) ? 65504.0 : c.g,
                isinf(c.b) || isnan(c.b) ? 65504.0 : c.b);
}

void main()
{
    tl_surface s = tl_material_surface();
    if (tl_material_masked(s)) discard;
    vec3 diffuse = vec3(0.0), specular = vec3(0.0);
#ifndef TL_NO_LIGHTS
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec4 ld = texelFetch(u_light_diffuse, px, 0);
    diffuse = tl_finite(ld.rgb);
#if defined(TL_SPECULAR_EXACT)
    specular = tl_finite(texelFetch(u_light_specular, px, 0).rgb);
#elif defined(TL_SPECULAR_COMPACT)
    // Compact layout: specular colour follows the diffuse light's chromaticity.
    float lum = tl_luminance(diffuse);
    specular = lum > 1e-8 ? diffuse * (min(ld.a, 65504.0) / lum) : vec3(0.0);
#endif
#endif
#ifdef TL_SSAO_AMBIENT
    // SSAO (docs/effects.md): the ambient term, and with TL_SSAO_DIFFUSE the diffuse light
    float ao = texelFetch(u_ao, ivec2(gl_FragCoord.xy), 0).r;
#ifdef TL_SSAO_DIFFUSE
    diffuse *= ao;
#endif
    vec3 c = s.albedo * (diffuse + u_ambient * (s.occlusion * ao)) + s.specular * specular + s.emissive;
#else
    vec3 c = s.albedo * (diffuse + u_ambient * s.occlusion) + s.specular * specular + s.emissive;
#endif
    o_color = vec4(min(c, vec3(65504.0)), 1.0);
}
