// Pass 2: one light volume's fragments (additive blending). TL_LIGHT_ACCUM (thin-lpp) sums light
// into the FP16 light buffer; TL_LIGHT_SHADE_THIN / TL_LIGHT_SHADE_FAT (deferred modes) read the
// material from the G-buffer and add shaded radiance to HDR.
#include "gbuffer_decode.glsl"
#include "light_eval.glsl"
#ifdef TL_SHADOWS
#include "shadow.glsl"
#endif
#if defined(TL_MATERIAL_MODELS) && !defined(TL_LIGHT_ACCUM)
#include "fat_models.glsl" // each light under the pixel's material model
#endif

// the light's record, view space (light.vert.glsl)
flat in vec4 f_position_radius;
flat in vec4 f_color_type;
flat in vec4 f_direction_cos_outer;
flat in vec4 f_cos_inner;

tl_light_data tl_volume_light() { return tl_light_data(f_position_radius, f_color_type, f_direction_cos_outer, f_cos_inner); }

#ifdef TL_LIGHT_ACCUM
layout(location = TL_OUT_LIGHT_DIFFUSE) out vec4 o_diffuse;
#ifdef TL_SPECULAR_EXACT
layout(location = TL_OUT_LIGHT_SPECULAR) out vec4 o_specular;
#endif
#ifdef TL_FRESNEL_SUMS
layout(location = TL_OUT_LIGHT_FRESNEL) out vec4 o_fresnel;
#endif
#ifdef TL_COAT_SUMS
#include "coat_sums.glsl"
layout(location = TL_OUT_LIGHT_COAT) out vec4 o_coat;

// The light's coat weight S1 + S2 at the coat's gloss where a coat is (zero elsewhere).
vec3 tl_light_coat(ivec2 px, vec3 p, vec3 n, vec3 v)
{
    float g;
    if (!tl_coat_gloss(px, g)) return vec3(0.0);
    vec3 t = tl_light_data_weights(tl_volume_light(), TL_LIGHT_TYPE, p, n, v, tl_lobe_shape(g));
#ifdef TL_SHADOWS
    if (f_cos_inner.z > 0.0 && t != vec3(0.0)) t *= tl_light_shadow(f_cos_inner.z, TL_LIGHT_TYPE, p, n, f_position_radius.xyz, f_direction_cos_outer.xyz);
#endif
    return min(f_color_type.rgb * (t.y + t.z), vec3(65504.0));
}
#endif
#else
layout(location = TL_OUT_HDR) out vec4 o_color;
#endif

void main()
{
    ivec2 px = ivec2(gl_FragCoord.xy);
    vec3 p, n;
    float gloss;
#ifdef TL_LIGHT_SHADE_FAT
    vec3 albedo, spec_color;
    if (!tl_fat_position(px, p)) discard;
#else
    if (!tl_gbuffer_position(px, p)) discard;
#endif
#if TL_LIGHT_TYPE != 3
    // Out of the light's range (the volume is only a bound): skip the surface fetch and decode,
    // and the blend, where the light adds exactly zero.
    vec3 to_light = f_position_radius.xyz - p;
    float d2 = dot(to_light, to_light);
    if (d2 >= f_position_radius.w * f_position_radius.w) discard;
#if TL_LIGHT_TYPE == 2
    if (d2 > 0.0 && dot(-to_light, f_direction_cos_outer.xyz) <= f_direction_cos_outer.w * sqrt(d2)) discard;
#endif
#endif
#ifdef TL_LIGHT_SHADE_FAT
    tl_fat_surface(px, n, gloss, albedo, spec_color);
#else
    tl_gbuffer_normal_gloss(px, n, gloss);
#endif
    vec3 v = normalize(-p);
#if defined(TL_MATERIAL_MODELS) && !defined(TL_LIGHT_ACCUM)
    tl_fat_model fm = tl_fat_model_read(px, n, v);
    if (fm.model != 0) {
#ifdef TL_LIGHT_SHADE_THIN
        vec3 albedo, spec_color;
        tl_rt1_read(px, albedo, spec_color);
#endif
        vec3 radiance = tl_fat_model_radiance(fm, tl_volume_light(), TL_LIGHT_TYPE, p, n, v, tl_lobe_shape(gloss),
                                              albedo, spec_color);
#ifdef TL_SHADOWS
        // one light's radiance is linear in its visibility, whatever the model
        if (f_cos_inner.z > 0.0 && radiance != vec3(0.0))
            radiance *= tl_light_shadow(f_cos_inner.z, TL_LIGHT_TYPE, p, n, f_position_radius.xyz, f_direction_cos_outer.xyz);
#endif
        o_color = vec4(min(radiance, vec3(65504.0)), 0.0);
        return;
    }
#endif
    vec3 t = tl_light_data_weights(tl_volume_light(), TL_LIGHT_TYPE, p, n, v, tl_lobe_shape(gloss));
#ifdef TL_SHADOWS
    if (f_cos_inner.z > 0.0 && t != vec3(0.0)) t *= tl_light_shadow(f_cos_inner.z, TL_LIGHT_TYPE, p, n, f_position_radius.xyz, f_direction_cos_outer.xyz);
#endif
    // One light's output never exceeds the FP16 maximum, whatever its colour (an Inf would poison
    // every later sum); sums past it are the readers' job (material.frag, tonemap.frag).
    const vec3 fp16_max = vec3(65504.0);
    vec3 diffuse = min(f_color_type.rgb * t.x, fp16_max);
    vec3 specular = min(f_color_type.rgb * t.y, fp16_max); // times F0
    vec3 fresnel = min(f_color_type.rgb * t.z, fp16_max);  // added as it is (GGX's Schlick part)
#ifdef TL_LIGHT_ACCUM
#ifndef TL_FRESNEL_SUMS
    specular = min(specular + fresnel, fp16_max); // one sum: Fresnel is applied per pixel
#endif
#if defined(TL_SPECULAR_EXACT)
    o_diffuse = vec4(diffuse, 0.0);
    o_specular = vec4(specular, 0.0);
#ifdef TL_FRESNEL_SUMS
    o_fresnel = vec4(fresnel, 0.0);
#endif
#elif defined(TL_SPECULAR_COMPACT)
    o_diffuse = vec4(diffuse, min(tl_luminance(specular), 65504.0));
#else
    o_diffuse = vec4(diffuse, 0.0);
#endif
#ifdef TL_COAT_SUMS
    o_coat = vec4(tl_light_coat(px, p, n, v), 0.0);
#endif
#else
#ifdef TL_LIGHT_SHADE_THIN
    vec3 albedo, spec_color;
    tl_rt1_read(px, albedo, spec_color);
#endif
#ifdef TL_SPECULAR_NONE
    spec_color = vec3(0.0);
    fresnel = vec3(0.0);
#endif
    o_color = vec4(min(albedo * diffuse + spec_color * specular + fresnel, fp16_max), 0.0);
#endif
}
