// Pass 2: one light volume's fragments (additive blending). TL_LIGHT_ACCUM (thin-lpp) sums light
// into the FP16 light buffer; TL_LIGHT_SHADE_THIN / TL_LIGHT_SHADE_FAT (deferred modes) read the
// material from the G-buffer and add shaded radiance to HDR.
#include "gbuffer_decode.glsl"
#include "light_eval.glsl" // first here: files are included once, at their first #include
#if defined(TL_MATERIAL_MODELS) && !defined(TL_LIGHT_ACCUM)
#include "fat_models.glsl" // each light under the pixel's material model
#endif
#include "light_loop.glsl" // one light's reach test, shadow gate and clamped terms

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
    t *= tl_light_visibility(tl_volume_light(), TL_LIGHT_TYPE, p, n, t != vec3(0.0));
    return tl_light_coat(f_color_type.rgb, t);
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
    // Out of the light's range (the volume is only a bound): skip the surface fetch and decode,
    // and the blend, where the light adds exactly zero.
    if (!tl_light_reaches(tl_volume_light(), TL_LIGHT_TYPE, p)) discard;
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
        radiance *= tl_light_visibility(tl_volume_light(), TL_LIGHT_TYPE, p, n, radiance != vec3(0.0));
        o_color = vec4(min(radiance, TL_FP16_MAX), 0.0);
        return;
    }
#endif
    vec3 t = tl_light_data_weights(tl_volume_light(), TL_LIGHT_TYPE, p, n, v, tl_lobe_shape(gloss));
    t *= tl_light_visibility(tl_volume_light(), TL_LIGHT_TYPE, p, n, t != vec3(0.0));
    // One light's output never exceeds the FP16 maximum, whatever its colour (an Inf would poison
    // every later sum); sums past it are the readers' job (material.frag, tonemap.frag).
    tl_light_sums one = tl_light_sums_of(f_color_type.rgb, t, true);
#ifdef TL_LIGHT_ACCUM
#ifndef TL_FRESNEL_SUMS
    tl_light_sums_fold(one);
    one.specular = min(one.specular, TL_FP16_MAX); // the one specular sum of two clamped terms
#endif
#if defined(TL_SPECULAR_EXACT)
    o_diffuse = vec4(one.diffuse, 0.0);
    o_specular = vec4(one.specular, 0.0);
#ifdef TL_FRESNEL_SUMS
    o_fresnel = vec4(one.fresnel, 0.0);
#endif
#elif defined(TL_SPECULAR_COMPACT)
    o_diffuse = vec4(one.diffuse, min(tl_luminance(one.specular), 65504.0));
#else
    o_diffuse = vec4(one.diffuse, 0.0);
#endif
#ifdef TL_COAT_SUMS
    o_coat = vec4(tl_light_coat(px, p, n, v), 0.0);
#endif
#else
#ifdef TL_LIGHT_SHADE_THIN
    vec3 albedo, spec_color;
    tl_rt1_read(px, albedo, spec_color);
#endif
    o_color = vec4(tl_light_sums_radiance(one, albedo, spec_color), 0.0);
#endif
}
